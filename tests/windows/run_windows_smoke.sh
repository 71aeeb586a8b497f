#!/usr/bin/env bash
# One lesson of the Windows build under Wine: every step headless at 320x180 (--all-steps, so each step
# is a child process started by the lesson: lesson_switch_win.cpp's runAndWait), each checked by the
# smoke checker built for Windows against the Linux golden with the Linux tolerance (no GL error, no
# NaN or Inf, not flat, within RMSE 1.5 and 64 levels). Prints each step's RMSE against its golden.
#   run_windows_smoke.sh <wine_run.sh> <lesson.exe> <smoke_check.exe> <golden dir> <work dir>
set -uo pipefail
wine="$1" exe="$2" checker="$3" golden="$4" work="$5"
name="$(basename "$exe" .exe)"
steps=$("$wine" "$exe" --list-steps | tr -d '\r' | grep -c '^[0-9][0-9]*\. ')
[ "$steps" -ge 1 ] || { echo "FAIL: $name lists no steps under Wine"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
if ! "$wine" "$exe" --all-steps --headless --size 320x180 --frames 3 --capture "$work" >"$work/all-steps.log" 2>&1; then
  echo "FAIL: $name --all-steps exited with an error:"; tail -20 "$work/all-steps.log"
fi
status=0
for step in $(seq 1 "$steps"); do
  dir="$work/step-$step"
  if [ ! -f "$dir/report.json" ]; then
    echo "FAIL: $name step $step wrote no report"; status=1; continue
  fi
  expect=()
  grep -q '"expectErrorsInStep": true' "$dir/report.json" && expect=(--expect-gl-errors)
  if ! "$wine" "$checker" "$dir" "$dir/report.json" "$golden/step-$step.png" "$work/diff-step-$step" "${expect[@]}" \
       >"$dir.check" 2>&1; then
    echo "FAIL: $name step $step:"; tr -d '\r' <"$dir.check"; status=1
  else
    printf '%s step %s: %s\n' "$name" "$step" "$(tr -d '\r' <"$dir.check" | grep -i -m1 'rmse' || echo 'passed')"
  fi
done
[ "$status" -eq 0 ] && echo "$name: $steps steps passed under Wine"
exit "$status"
