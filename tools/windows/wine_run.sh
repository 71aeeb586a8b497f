#!/usr/bin/env bash
# Runs a Windows program of the cross-build under Wine: CMake's CROSSCOMPILING_EMULATOR for every test
# of the Windows build (tools/windows/build.sh sets it). The Wine prefix lives in the build tree
# (build-windows/wine, made on first use) and never in the user's ~/.wine; one persistent wineserver
# (`wineserver -p`, started by the windows label's setup test and ended by its PID by the cleanup test)
# keeps each start at a few hundredths of a second instead of half a second.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${FXLAB_WINDOWS_BUILD_DIR:-$(cd "$here/../.." && pwd)/build-windows}"
export WINEPREFIX="${WINEPREFIX:-$build/wine}"
export WINEDEBUG="${WINEDEBUG:--all}"
export WINEDLLOVERRIDES="${WINEDLLOVERRIDES:-mscoree,mshtml=}"  # no Mono or Gecko installer prompts
# Mesa's llvmpipe, as the Linux tests use, through Wine's WGL.
export LIBGL_ALWAYS_SOFTWARE=1
exec wine "$@"
