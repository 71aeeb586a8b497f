#!/usr/bin/env bash
# The soak (docs/reliability.md, "Soak"): every lesson in a window, cycling through every step and the
# odd sizes (97x31, 1x1, minimised, back) for many cycles, with --resource-log sampling the process's
# memory and the context's live GL objects every tenth frame. check_soak.py then compares every cycle
# after the first two with the second, sample by sample at the same point of the cycle: a GL object
# more of any kind, or memory past the tolerance, fails.
#   run_soak.sh <lessons folder (build/lessons)> <work dir> <cycles> [lesson numbers, default all]
# The suite runs three lessons for three cycles (window.soak); the long run (tens of cycles) gives the
# figures in docs/reliability.md. Without a display it runs itself again under xvfb-run -a.
set -uo pipefail
lessons="$1" work="$2" cycles="$3"
shift 3
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  if [ -n "${FXLAB_SOAK_IN_XVFB:-}" ] || ! command -v xvfb-run >/dev/null; then
    echo "FAIL: no display, and xvfb-run is missing (Debian packages xvfb and xauth)"; exit 1
  fi
  FXLAB_SOAK_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$lessons" "$work" "$cycles" "$@"
fi
rm -rf "$work" && mkdir -p "$work"
export FXLAB_CONFIG_DIR="$work/config"  # never the teacher's ui.json
numbers=("$@")
[ "${#numbers[@]}" -eq 0 ] && numbers=(01 02 03 04 05 06 07 08 09 10)
base=160x90
segment=10  # frames per state: one --resource-log sample each
status=0
for number in "${numbers[@]}"; do
  exe="$(ls "$lessons"/fxlab-"$number"-* 2>/dev/null | sed -n 1p)"
  [ -x "$exe" ] || { echo "FAIL: no lesson $number in $lessons"; status=1; continue; }
  name="$(basename "$exe")"
  steps="$("$exe" --list-steps 2>/dev/null | grep -c '^[0-9][0-9]*\. ')"
  # One cycle: forward through every step, the odd sizes, back to step 1. Each change lands on the
  # frame after a sample, so every sample sees a state nine frames old.
  args=()
  frame=1
  for ((c = 0; c < cycles; ++c)); do
    for ((k = 1; k < steps; ++k)); do args+=(--press "right@$frame"); frame=$((frame + segment)); done
    for size in 97x31 1x1 0x0 "$base"; do args+=(--resize "$size@$frame"); frame=$((frame + segment)); done
    for ((k = 1; k < steps; ++k)); do args+=(--press "left@$frame"); frame=$((frame + segment)); done
  done
  frames=$((frame + segment - 1))
  segments=$((2 * (steps - 1) + 4))
  start=$(date +%s)
  # The picture scale pinned: the frame budget's automatic scale follows the machine's load, and
  # targets of another size each cycle would read as memory that comes and goes.
  if ! "$exe" --size "$base" --frames "$frames" --picture-scale 100% "${args[@]}" --resource-log "$work/$name.csv" \
       --report "$work/$name.json" >"$work/$name.log" 2>&1; then
    echo "FAIL: $name exited with an error: $(tail -3 "$work/$name.log")"; status=1; continue
  fi
  seconds=$(($(date +%s) - start))
  python3 "$(dirname "$0")/check_soak.py" "$work/$name.csv" "$work/$name.json" "$segments" "$seconds" ||
    status=1
done
exit $status
