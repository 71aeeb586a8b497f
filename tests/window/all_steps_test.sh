#!/usr/bin/env bash
# --all-steps with --capture: every step of a lesson captured in one command, each into DIR/step-K/
# with its own final.png and report.json naming that step, and nothing beyond the last step.
#   all_steps_test.sh <lesson exe> <work dir>
set -uo pipefail
exe="$1" work="$2"
rm -rf "$work"
steps="$("$exe" --list-steps | grep -c '^[0-9][0-9]*\. ')"
if ! "$exe" --headless --size 96x54 --frames 1 --all-steps --capture "$work" >"$work.log" 2>&1; then
  echo "FAIL: --all-steps exited with an error:"; cat "$work.log"; exit 1
fi
for k in $(seq 1 "$steps"); do
  [ -s "$work/step-$k/final.png" ] || { echo "FAIL: no $work/step-$k/final.png"; cat "$work.log"; exit 1; }
  grep -q "\"step\": $k," "$work/step-$k/report.json" || { echo "FAIL: step-$k/report.json is not step $k's"; exit 1; }
done
[ ! -e "$work/step-$((steps + 1))" ] || { echo "FAIL: a step beyond the lesson's $steps"; exit 1; }
grep -q "$steps of $steps steps captured" "$work.log" || { echo "FAIL: the log does not say all steps were captured"; cat "$work.log"; exit 1; }
echo "$(basename "$exe"): $steps steps captured into $work/step-1 ... step-$steps"
