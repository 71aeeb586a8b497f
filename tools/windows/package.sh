#!/usr/bin/env bash
# ./fxlab package windows: the Windows release, made here. Cross-builds fxlab (build.sh), then puts in
# out/fxlab-windows/ what a student unpacks and runs: every lesson's .exe, the exercise and handout
# tools (stripped: the debug symbols stay in build-windows/), shaders/, res/, each lesson's texts,
# exercises/, IPA Gothic for a Windows without Japanese fonts (fonts/, with its licence), fxlab.cmd and
# the README (English and Japanese); and zips that folder into out/fxlab-windows.zip. The .exe's find
# shaders/ and res/ beside themselves (base/paths_win.cpp).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${FXLAB_WINDOWS_BUILD_DIR:-$root/build-windows}"
out="${FXLAB_PACKAGE_DIR:-$root/out}"
here="$root/tools/windows"
started=$(date +%s)

"$here/build.sh" >/dev/null
stage="$out/fxlab-windows"
rm -rf "$stage" "$stage.zip" "$stage.partial"
mkdir -p "$stage.partial"
for exe in "$build"/lessons/fxlab-[0-9][0-9]-*.exe "$build/tools/exercise/fxlab-exercise.exe" \
           "$build/tools/handout/fxlab-handout.exe"; do
  [ -f "$exe" ] || { echo "package: $exe was not built" >&2; exit 1; }
  x86_64-w64-mingw32-strip -o "$stage.partial/$(basename "$exe")" "$exe"
done
cp -R "$root/shaders" "$root/res" "$root/exercises" "$stage.partial/"
# The lessons' texts (lesson.md, lesson.ja.md and whatever else is not code), in the same folders.
for dir in "$root"/lessons/[0-9][0-9]_*/; do
  name="$(basename "$dir")"
  mkdir -p "$stage.partial/lessons/$name"
  find "$dir" -maxdepth 1 -type f ! -name '*.cpp' ! -name '*.hpp' ! -name 'CMakeLists.txt' \
    -exec cp {} "$stage.partial/lessons/$name/" \;
done
ipa=/usr/share/fonts/opentype/ipafont-gothic/ipag.ttf
if [ -f "$ipa" ]; then
  mkdir -p "$stage.partial/fonts"
  cp "$ipa" "$stage.partial/fonts/ipag.ttf"
  cp /usr/share/doc/fonts-ipafont-gothic/copyright "$stage.partial/fonts/ipag-copyright.txt"
fi
# Text files a Windows user opens with Notepad: CRLF line ends.
sed 's/$/\r/' "$here/README.txt" >"$stage.partial/README.txt"
sed 's/$/\r/' "$here/fxlab.cmd" >"$stage.partial/fxlab.cmd"
mv "$stage.partial" "$stage"
(cd "$out" && zip -qrX fxlab-windows.zip fxlab-windows)
size=$(stat -c %s "$out/fxlab-windows.zip")
echo "fxlab: $out/fxlab-windows.zip ($((size / 1024 / 1024)) MiB, $(( $(date +%s) - started )) s): unpack it on Windows and open README.txt" >&2
