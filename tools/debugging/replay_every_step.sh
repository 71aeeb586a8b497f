#!/usr/bin/env bash
# Every step of every lesson captured headless with --renderdoc and each capture opened and replayed by
# RenderDoc's Python module (issue 39's acceptance; too long for CI, whose renderdoc label checks
# lessons 06, 07 and 10 in depth). Under xvfb-run -a when there is no display.
#   tools/debugging/replay_every_step.sh <build dir> <work dir>
set -uo pipefail
build="$1" work="$2"
here="$(cd "$(dirname "$0")/../.." && pwd)"
if [ -z "${DISPLAY:-}" ]; then exec xvfb-run -a -s "-screen 0 640x480x24" "$0" "$@"; fi
mkdir -p "$work"
export FXLAB_CONFIG_DIR="$work/config" HOME="$work/home" && mkdir -p "$HOME"
failed=0 count=0
for exe in "$build"/lessons/fxlab-[0-9][0-9]-*; do
  name="$(basename "$exe")"
  steps="$("$exe" --list-steps 2>/dev/null | grep -c '^[0-9][0-9]*\. ')"
  for ((k = 1; k <= steps; k++)); do
    run="$work/$name-step-$k"
    count=$((count + 1))
    if ! "$exe" --headless --size 160x90 --step "$k" --renderdoc "$run.rdc" --capture "$run" >"$run.log" 2>&1 ||
      ! /usr/bin/python3 "$here/tests/renderdoc/check_capture.py" "$run.rdc" --replay-only >>"$run.log" 2>&1; then
      echo "FAIL: $name step $k ($run.log)"; failed=$((failed + 1))
    fi
  done
done
echo "$((count - failed)) of $count steps captured, opened and replayed"
[ "$failed" -eq 0 ]
