#!/usr/bin/env bash
# Smoke test of one lesson: every step headless at 320x180, checked by fx_smoke_check against
# tests/smoke/golden/<lesson>/step-<k>.png; every step again, which must give the same bytes; and
# every step at 1x1 and 0x0 (a minimised window), which must run without a GL error; and every step
# resized while it runs.
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
# Fixed time step and seeds: a second run of every step gives byte-identical captures.
for step in $(seq 1 "$steps"); do
  again="$work/again-$step"
  "$exe" --headless --size 320x180 --frames 3 --step "$step" --capture "$again" >/dev/null 2>&1
  if ! cmp -s "$work/step-$step/final.png" "$again/final.png"; then
    echo "FAIL: $name step $step differs between two runs"; status=1
  fi
done
# Tiny and minimised framebuffers: every step renders at 1x1 and skips 0x0, with no GL error.
for size in 1x1 0x0; do
  for step in $(seq 1 "$steps"); do
    dir="$work/size-$size-step-$step"
    if ! "$exe" --headless --size "$size" --frames 2 --step "$step" --report "$dir/report.json" --capture "$dir" \
         >"$dir.log" 2>&1; then
      echo "FAIL: $name step $step at $size exited with an error:"; cat "$dir.log"; status=1; continue
    fi
    if ! grep -q '"glErrors": 0,' "$dir/report.json"; then
      echo "FAIL: $name step $step at $size reported GL errors:"; grep '"lastGlError"' "$dir/report.json"; status=1
    fi
  done
done
# Resized while it runs, as a window dragged through every size: minimised, 1x1, odd, and back. Every
# texture follows the size, so the last frame is 320x180 again, with no GL error and no NaN or Inf in
# any texture the report lists (but those the step shows them in on purpose).
for step in $(seq 1 "$steps"); do
  dir="$work/resized-step-$step"
  mkdir -p "$dir"
  if ! "$exe" --headless --size 320x180 --frames 6 --step "$step" --resize 0x0@1 --resize 1x1@2 --resize 97x31@3 \
       --resize 320x180@4 --report "$dir/report.json" >"$dir.log" 2>&1; then
    echo "FAIL: $name step $step, resized while running, exited with an error:"; cat "$dir.log"; status=1; continue
  fi
  if ! "$checker" --report-only "$dir/report.json" 320x180; then
    echo "FAIL: $name step $step, resized while running (report: $dir/report.json)"; status=1
  fi
done
[ "$status" -eq 0 ] && echo "$name: $steps steps passed"
exit "$status"
