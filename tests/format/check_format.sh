#!/usr/bin/env bash
# Every C++ source of ours is formatted as .clang-format says: the tree was formatted once, and this
# keeps it so. Fails listing the files that differ; `clang-format -i FILE` fixes one.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
formatter="${CLANG_FORMAT:-clang-format}"
# The project's style by name, so a fixture folder that switches formatting off is still checked.
style="--style=file:$root/.clang-format"
if ! command -v "$formatter" >/dev/null; then
  echo "check_format: $formatter not found (Debian: clang-format)" >&2
  exit 1
fi
# With arguments: only those files (the test of this check uses that).
if [ "$#" -gt 0 ]; then files=("$@"); else
mapfile -t files < <(git ls-files -- 'common/*.cpp' 'common/*.hpp' 'lessons/*.cpp' 'lessons/*.hpp' \
                                     'tests/*.cpp' 'tests/*.hpp' 'tools/*.cpp' 'tools/*.hpp' \
                     | grep -v '^tests/layering/fixture/' | grep -v '^tests/format/fixture/' \
                     | grep -v '^tests/lessons/fixture/' | grep -v '^tests/bindings/fixture/')
fi
[ "${#files[@]}" -gt 0 ] || { echo "check_format: no sources found under $root" >&2; exit 1; }
# One run over every file answers the common case quickly; only a failure looks file by file.
if "$formatter" "$style" --dry-run -Werror "${files[@]}" >/dev/null 2>&1; then
  echo "check_format: ${#files[@]} files formatted"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  if [ ! -f "$f" ]; then [ "$#" -gt 0 ] && bad+=("$f (missing)"); continue; fi  # a tracked file deleted here is skipped
  "$formatter" "$style" --dry-run -Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ "${#bad[@]}" -gt 0 ]; then
  echo "check_format: ${#bad[@]} of ${#files[@]} files are not formatted (clang-format -i fixes them):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files formatted"
