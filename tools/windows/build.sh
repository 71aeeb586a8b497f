#!/usr/bin/env bash
# Cross-builds fxlab for 64-bit Windows with Debian's mingw-w64 into build-windows/ (or
# $FXLAB_WINDOWS_BUILD_DIR): GLFW and Dear ImGui from Debian's source packages (fetch_sources.sh),
# everything else as cmake/windows/ and cmake/FxWindowsDependencies.cmake say. Extra arguments go to
# `cmake --build` (--target X). The tests of this build run the .exe's under Wine (wine_run.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${FXLAB_WINDOWS_BUILD_DIR:-$root/build-windows}"
jobs="${FXLAB_JOBS:-$(nproc 2>/dev/null || echo 2)}"
command -v x86_64-w64-mingw32-g++-posix >/dev/null || {
  echo "tools/windows/build.sh: x86_64-w64-mingw32-g++-posix is missing (apt-get install g++-mingw-w64-x86-64-posix)" >&2
  exit 1
}
"$root/tools/windows/fetch_sources.sh" "$build/sources"
if [ ! -f "$build/build.ninja" ]; then
  extra=()
  command -v ccache >/dev/null && extra+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  # Release at -O2: the code the Linux build's RelWithDebInfo makes, without the debug information
  # (which the zip strips anyway, and which costs a third of the compile time).
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${FXLAB_BUILD_TYPE:-Release}" \
    -DCMAKE_C_FLAGS_RELEASE="-O2 -DNDEBUG" -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" \
    -DCMAKE_TOOLCHAIN_FILE="$root/cmake/windows/mingw-w64-x86_64.cmake" \
    -DCMAKE_CROSSCOMPILING_EMULATOR="$root/tools/windows/wine_run.sh" \
    -DFXLAB_WINDOWS_SOURCES="$build/sources" "${extra[@]}" >/dev/null
fi
cmake --build "$build" -j "$jobs" "$@"
