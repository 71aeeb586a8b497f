#!/usr/bin/env bash
# The classroom survey: every step of every lesson in a real window with the overlay, as a teacher
# would show it, and the median frame of each (the report's cpuMs). docs/overlay.md shows its table.
#   tools/survey/frame_survey.sh [--lessons DIR] [--size WxH] [--frames N] [--inspector] [--out DIR]
#                                [--only NN] [-- extra lesson flags]
# Writes DIR/survey.md (one row per step: the median frame and the picture's rendered size) and keeps
# each run's report; survey_table.py puts several surveys side by side (before=DIR after=DIR). Records `uptime` before and after: on a shared machine the load inflates every time.
# Without a display it runs itself under xvfb-run.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
lessons="${FXLAB_BUILD_DIR:-$here/../../build}/lessons" size=1280x720 frames=12 inspector=0 out=out/survey only=""
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --lessons) lessons="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --inspector) inspector=1; shift ;;
    --out) out="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "unknown argument $1" >&2; exit 2 ;;
  esac
done
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 ${size}x24" "$0" --lessons "$lessons" --size "$size" --frames "$frames" \
    $([ "$inspector" = 1 ] && echo --inspector) --out "$out" ${only:+--only "$only"} -- "${extra[@]}"
fi
mkdir -p "$out"
export FXLAB_CONFIG_DIR="$out/config"  # never the teacher's ui.json
echo "load before: $(uptime)" | tee "$out/load.txt"
for exe in "$lessons"/fxlab-[0-9][0-9]-*; do
  name="$(basename "$exe")"; number="${name:6:2}"
  [ -n "$only" ] && [ "$only" != "$number" ] && continue
  steps="$("$exe" --list-steps 2>/dev/null | grep -c '^[0-9][0-9]*\. ')"
  for step in $(seq 1 "$steps"); do
    run="$out/$name/step-$step"
    mkdir -p "$run"
    flags=(--size "$size" --step "$step" --frames "$frames" --report "$run/report.json")
    # The inspector open on the frame's output: its list, thumbnails and large view all draw.
    [ "$inspector" = 1 ] && flags+=(--inspect output)
    "$exe" "${flags[@]}" "${extra[@]}" >"$run/log.txt" 2>&1 || echo "$name step $step: exit $?" >&2
  done
done
echo "load after: $(uptime)" | tee -a "$out/load.txt"
python3 "$here/survey_table.py" "survey=$out" >"$out/survey.md"
cat "$out/survey.md"
