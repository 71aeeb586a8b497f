#!/usr/bin/env bash
# Every GL object has a label and all GPU work is inside a debug group, so RenderDoc and apitrace show
# names (check_gl_names.py says exactly what is checked). The lesson runs under apitrace, and the
# trace's calls are checked.
#   run_gl_names_check.sh headless <lesson exe> <work dir>
#       every step of the lesson, headless (EGL) at 96x54, two frames each, one trace per step; then
#       the lesson's bench sweep at one frame per setting (every knob's value and the references);
#   run_gl_names_check.sh window <lesson exe> <work dir> [lesson flags]
#       the lesson in a GLFW window with the overlay (and whatever the flags open), four frames,
#       under xvfb-run -a when there is no display. Dear ImGui's loader cannot be traced in headless
#       runs (apitrace's EGL wrapper stops it), so the overlay is checked here.
# Exits 77 (skipped) when apitrace is not installed (Debian package apitrace; ./fxlab setup installs it).
set -uo pipefail
mode="$1" exe="$2" work="$3"
shift 3
here="$(cd "$(dirname "$0")" && pwd)"
name="$(basename "$exe")"
if ! command -v apitrace >/dev/null; then
  echo "SKIP: apitrace is not installed (Debian package apitrace)"; exit 77
fi
if [ "$mode" = window ] && [ -z "${DISPLAY:-}" ]; then
  if [ -n "${FXLAB_TRACE_IN_XVFB:-}" ] || ! command -v xvfb-run >/dev/null; then
    echo "FAIL: no display, and xvfb-run is missing (Debian packages xvfb and xauth)"; exit 1
  fi
  FXLAB_TRACE_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$mode" "$exe" "$work" "$@"
fi
rm -rf "$work" && mkdir -p "$work"
export FXLAB_CONFIG_DIR="$work/config"  # never the teacher's ui.json

# Traces one run of the lesson into $work/<label>.trace and checks it. `expect`: --expect-work when
# the run must do GPU work (a lesson without knobs has no bench sweep to do), else -.
check_run() {
  local label="$1" api="$2" expect="$3"
  shift 3
  if ! apitrace trace --api "$api" --output "$work/$label.trace" "$exe" "$@" >"$work/$label.log" 2>&1; then
    echo "FAIL: $name $label: the traced run failed:"; tail -n 20 "$work/$label.log"; return 1
  fi
  if ! apitrace dump --color=never "$work/$label.trace" >"$work/$label.txt" 2>"$work/$label.dump.log"; then
    echo "FAIL: $name $label: apitrace could not read its trace:"; cat "$work/$label.dump.log"; return 1
  fi
  local flags=()
  [ "$expect" = --expect-work ] && flags=(--expect-work)
  python3 "$here/check_gl_names.py" "$work/$label.txt" "${flags[@]}"
}

status=0
case "$mode" in
  headless)
    steps="$("$exe" --list-steps 2>/dev/null | grep -c '^[0-9][0-9]*\. ')"
    if [ "${steps:-0}" -lt 1 ]; then echo "FAIL: $name --list-steps lists no steps"; exit 1; fi
    for ((k = 1; k <= steps; k++)); do
      check_run "step-$k" egl --expect-work --headless --size 96x54 --frames 2 --step "$k" || status=1
    done
    check_run bench egl - --bench --size 96x54 --bench-frames 1 --bench-out "$work/bench" || status=1
    ;;
  window)
    check_run window gl --expect-work --frames 4 "$@" || status=1
    ;;
  *)
    echo "usage: run_gl_names_check.sh headless|window <lesson exe> <work dir> [lesson flags]"; exit 2
    ;;
esac
[ "$status" -eq 0 ] && echo "$name ($mode): every GL object labelled, all GPU work in debug groups"
exit "$status"
