#!/usr/bin/env bash
# The handouts of a few lessons in both languages, checked in chromium (check_handout.py), and made a
# second time to show that the pictures come out the same: every picture and graph byte-identical.
#   run_handout_browser_test.sh <fxlab-handout> <python3> <work dir> <lesson exe>...
set -uo pipefail
tool="$1" python="$2" work="$3"
shift 3
here="$(cd "$(dirname "$0")" && pwd)"
if ! command -v chromium >/dev/null && ! command -v chromium-browser >/dev/null; then
  echo "SKIP: chromium is not installed (Debian: apt-get install chromium poppler-utils; ./fxlab test installs them as root)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
"$tool" --lang en,ja --force --out "$work/handouts" "$@" || { echo "FAIL: fxlab-handout"; exit 1; }
"$python" "$here/check_handout.py" "$work/handouts" "$work/check"
status=$?
[ "$status" -eq 77 ] && exit 77
# Two runs give the same pictures (fixed frame count at the fixed time step, fixed seeds).
first="$(basename "$1")"; first="${first#fxlab-}"
made="$work/handouts"
[ $# -gt 1 ] && made="$work/handouts/$first"  # several lessons: one folder each, beside the contents
"$tool" --force --out "$work/again" "$1" >/dev/null 2>&1 || { echo "FAIL: fxlab-handout, second run"; exit 1; }
compared=0
while IFS= read -r file; do
  rel="${file#"$work/again/"}"
  if ! cmp -s "$file" "$made/$rel"; then echo "FAIL: $first/$rel differs between two runs"; status=1; fi
  compared=$((compared + 1))
done < <(find "$work/again" -type f \( -name '*.png' -o -name '*.svg' \))
[ "$compared" -gt 0 ] || { echo "FAIL: no pictures to compare"; status=1; }
[ "$status" -eq 0 ] && echo "ok: $compared pictures and graphs of $first are byte-identical in a second run"
exit "$status"
