#!/usr/bin/env bash
# Smoke test of one lesson: every step headless at 320x180, checked by fx_smoke_check against
# tests/smoke/golden/<lesson>/step-<k>.png; then step 1 again, which must give the same bytes.
#   run_lesson_smoke.sh <lesson exe> <checker exe> <golden dir> <work dir>
set -uo pipefail
exe="$1" checker="$2" golden="$3" work="$4"
name="$(basename "$exe")"
steps=$("$exe" --list-steps | grep -c '^[0-9][0-9]*\. ')
[ "$steps" -ge 1 ] || { echo "FAIL: $name lists no steps"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
status=0
for step in $(seq 1 "$steps"); do
  dir="$work/step-$step"
  if ! "$exe" --headless --size 320x180 --frames 3 --step "$step" --capture "$dir" --report "$dir/report.json" \
       >"$dir.log" 2>&1; then
    echo "FAIL: $name step $step exited with an error:"; cat "$dir.log"; status=1; continue
  fi
  expect=()
  grep -q '"expectErrorsInStep": true' "$dir/report.json" 2>/dev/null && expect=(--expect-gl-errors)
  if ! "$checker" "$dir" "$dir/report.json" "$golden/step-$step.png" "$work/diff-step-$step" "${expect[@]}"; then
    echo "FAIL: $name step $step (log: $dir.log)"; status=1
  fi
done
# Fixed time step and seeds: a second run gives byte-identical captures.
again="$work/again"
"$exe" --headless --size 320x180 --frames 3 --step 1 --capture "$again" >/dev/null 2>&1
if ! cmp -s "$work/step-1/final.png" "$again/final.png"; then
  echo "FAIL: $name step 1 differs between two runs"; status=1
fi
[ "$status" -eq 0 ] && echo "$name: $steps steps passed"
exit "$status"
