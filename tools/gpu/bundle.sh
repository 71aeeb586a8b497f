#!/usr/bin/env bash
# Packs what tools/gpu/run.sh needs from a build into one folder that can travel to a machine with no
# package registry (the GPU machine of docs/bench-gpu.md): the lesson executables, fx_smoke_check and
# fx_series_plot, without debug information and symbols, and in lib/ every shared library they load that is
# not the C library itself, plus the GL dispatch libraries (libglvnd: libEGL, libOpenGL, libGLdispatch),
# which the glad loader opens at run time and so no `ldd` lists. The GPU's own driver (NVIDIA's EGL
# vendor library) is the machine's, never carried. The shaders and res/ travel with the source tree.
#   tools/gpu/bundle.sh <build dir> <bundle dir>
set -euo pipefail
build="$1" bundle="$2"
[ -d "$build/lessons" ] || { echo "bundle.sh: $build/lessons: not a build folder (build first: ./fxlab setup)" >&2; exit 2; }
rm -rf "$bundle" && mkdir -p "$bundle/lib"
exes=()
for f in "$build"/lessons/fxlab-[0-9][0-9]-*; do [ -x "$f" ] && [ -f "$f" ] && exes+=("$f"); done
[ "${#exes[@]}" -gt 0 ] || { echo "bundle.sh: no lesson executables in $build/lessons" >&2; exit 2; }
exes+=("$build/tests/smoke/fx_smoke_check" "$build/tools/bench/fx_series_plot")
for f in "${exes[@]}"; do
  [ -x "$f" ] || { echo "bundle.sh: missing $f" >&2; exit 2; }
  # Debug information and symbols are most of a RelWithDebInfo executable (64 MB of a lesson's 67):
  # without them ten lessons, their libraries and the source tree fit the 64 MiB a device run carries.
  strip --strip-all -o "$bundle/$(basename "$f")" "$f"
done
# The C library and its loader stay the machine's: a program is linked against them, and the GPU
# driver loaded into the same process must use the same ones.
system='^(libc|libm|libdl|libpthread|librt|libresolv|ld-linux-x86-64)\.so'
for f in "${exes[@]}"; do
  ldd "$f" | awk '/=> \// { print $3 }'
done | sort -u | while read -r lib; do
  name="$(basename "$lib")"
  [[ "$name" =~ $system ]] && continue
  cp -L "$lib" "$bundle/lib/$name"
done
# Opened with dlopen by the glad loader (gladLoaderLoadEGL / gladLoaderLoadGL).
for name in libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0 libGL.so.1 libGLX.so.0; do
  path="$(ldconfig -p | awk -v n="$name" '!found && $1 == n && /x86-64/ { print $NF; found = 1 }')"
  [ -n "$path" ] || { echo "bundle.sh: $name not found (Debian package libegl1 / libopengl0 / libgl1)" >&2; exit 2; }
  cp -L "$path" "$bundle/lib/$name"
done
{
  echo "made: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "from: $(cd "$(dirname "$0")/../.." && git describe --always --dirty 2>/dev/null || echo unknown)"
  echo "on: $(. /etc/os-release && echo "$PRETTY_NAME"), $(ldd --version | sed -n 1p)"
} >"$bundle/BUNDLE"
echo "bundle: $(du -sh "$bundle" | cut -f1) in $bundle ($(ls "$bundle" | grep -c '^fx') programs, $(ls "$bundle/lib" | wc -l) libraries)"
