#!/usr/bin/env bash
# The classroom window tests: a lesson in a real GLFW window in the presentation layout, driven by
# --press (the window's own keys at given frames) and --resize, each run a few frames long.
#   classroom_test.sh <case> <build lessons folder> <fx_layout_check> <work dir>
# Cases:
#   layout-WxH   lesson 02 at WxH: the picture uncovered, every panel on the window
#   text-scale   + twice, then a second start without --size: the scale and the window size come back
#   reset        a layout left jammed in ui.json, the window shrunk to 400x300 and back, then F2
#   compare      lesson 04 step 1 (colour) then step 2 (grey), F3: the split view of one against the other,
#                then F3 again: the difference x8
#   find-nan     lesson 05 step 2, inspector on the blur's output, F4: the probe pinned on the centre texel
#   next-lesson  lesson 01, Page Down: lesson 02 starts in the same window size with the same flags
#   hidden       lesson 05 unmapped for 2 s (fx_unmap_window): frames skipped, waiting for events
#   screenshots  F12 in two sessions of lesson 05 step 2: two files, neither replacing the other
# Each run gets its own settings folder (FXLAB_CONFIG_DIR), so no teacher's ui.json is read or written.
# Without a display it runs itself again under xvfb-run -a.
set -uo pipefail
case_="$1" lessons="$2" check="$3" work="$4"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  if [ -n "${FXLAB_WINDOW_TEST_IN_XVFB:-}" ] || ! command -v xvfb-run >/dev/null; then
    echo "FAIL: no display, and xvfb-run is missing (Debian packages xvfb and xauth)"; exit 1
  fi
  FXLAB_WINDOW_TEST_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 2048x1280x24" "$0" "$@"
fi
rm -rf "$work" && mkdir -p "$work"
export FXLAB_CONFIG_DIR="$work/config"
lesson() { ls "$lessons"/fxlab-"$1"-* 2>/dev/null | head -1; }
# run <folder> <exe> [flags]: the run's captures and report in <folder>, its log beside it.
run() {
  local out="$1" exe="$2"; shift 2
  if ! "$exe" --frames "${frames:-6}" "$@" --capture "$work/$out" --report "$work/$out/report.json" >"$work/$out.log" 2>&1; then
    echo "FAIL: $(basename "$exe") $* exited with an error:"; cat "$work/$out.log"; exit 1
  fi
}
checked() { "$check" "$@" || { echo "FAIL: $case_ (logs in $work)"; exit 1; }; }

case "$case_" in
  layout-*)
    size="${case_#layout-}"
    run shot "$(lesson 02)" --size "$size" --step 2
    checked "$work/shot" --window "$size" ;;
  text-scale)
    run first "$(lesson 02)" --size 1024x768 --press plus@1 --press plus@2
    checked "$work/first" --text-scale 1.5 --window 1024x768
    grep -q '"textScale": 1.5' "$FXLAB_CONFIG_DIR/ui.json" || { echo "FAIL: ui.json does not keep the text scale:"; cat "$FXLAB_CONFIG_DIR/ui.json"; exit 1; }
    # A new start, no --size: the window and the text come back as they were left.
    run again "$(lesson 02)"
    checked "$work/again" --text-scale 1.5 --window 1024x768 ;;
  reset)
    mkdir -p "$FXLAB_CONFIG_DIR"
    printf '{"textScale": 2.0, "columnShare": 0.6, "lessonShare": 0.2, "pictureShare": 0.8}\n' >"$FXLAB_CONFIG_DIR/ui.json"
    run jammed "$(lesson 02)" --size 1280x720 --resize 400x300@1 --resize 1280x720@3
    checked "$work/jammed" --window 1280x720 --text-scale 2 --picture-share 0.39
    frames=7 run reset "$(lesson 02)" --size 1280x720 --resize 400x300@1 --resize 1280x720@3 --press F2@4
    checked "$work/reset" --window 1280x720 --text-scale 2
    grep -q '"columnShare": 0.3' "$FXLAB_CONFIG_DIR/ui.json" || { echo "FAIL: F2 did not put the default layout back:"; cat "$FXLAB_CONFIG_DIR/ui.json"; exit 1; } ;;
  compare)
    # Without the lesson's own before|after split, so that the whole picture changes between the steps.
    run split "$(lesson 04)" --size 1280x720 --step 1 --param split_view=false --press right@2 --press F3@3
    checked "$work/split" --split
    grep -q "compare: split" "$work/split.log" || { echo "FAIL: the log does not say the split view is on"; exit 1; }
    # F3 again: the difference x8 (grey steps agree with colour ones on white and grey surfaces).
    run difference "$(lesson 04)" --size 1280x720 --step 1 --param split_view=false --press right@2 --press F3@3 --press F3@4
    checked "$work/difference" --difference ;;
  screenshots)
    # F12 in two sessions: the second never replaces the first, and the names say lesson and step.
    (cd "$work" && run one "$(lesson 05)" --size 640x360 --step 2 --press F12@2) || exit 1
    (cd "$work" && run two "$(lesson 05)" --size 640x360 --step 2 --press F12@2) || exit 1
    for n in 001 002; do
      [ -s "$work/out/fxlab-05-radial-blur-step2-$n.png" ] || { echo "FAIL: no out/fxlab-05-radial-blur-step2-$n.png"; ls -R "$work/out"; exit 1; }
    done ;;
  find-nan)
    run nan "$(lesson 05)" --size 1280x720 --step 2 --inspect blur.offset --press F4@3
    checked "$work/nan" --picture-share 0.25 --nan-log "$work/nan.log" ;;
  next-lesson)
    run next "$(lesson 01)" --size 1024x768 --press pagedown@2
    grep -q "starting fxlab-02-" "$work/next.log" || { echo "FAIL: Page Down did not start lesson 02"; cat "$work/next.log"; exit 1; }
    checked "$work/next" --lesson "$(basename "$(lesson 02)")" --window 1024x768 ;;
  hidden)
    # Unmapped for 2 s (as when minimised): the loop waits for events instead of rendering, so the
    # report has frames of 0 ms (skipped) for that time, and the run still ends with a picture.
    "$FXLAB_UNMAP_WINDOW" "fxlab 5:" 2 >"$work/unmap.log" 2>&1 &
    unmapper=$!
    frames=150 run hidden "$(lesson 05)" --size 320x180 --no-overlay
    wait "$unmapper" || { echo "FAIL: could not unmap the window:"; cat "$work/unmap.log"; exit 1; }
    skipped="$(grep -c '"cpuMs": 0.0' "$work/hidden/report.json" || true)"
    echo "frames skipped while hidden: $skipped"
    [ "$skipped" -ge 3 ] || { echo "FAIL: the hidden window kept rendering (no skipped frames)"; exit 1; }
    [ -s "$work/hidden/final.png" ] || { echo "FAIL: no picture after the window came back"; exit 1; } ;;
  *) echo "FAIL: unknown case $case_"; exit 2 ;;
esac
echo "$case_: as expected (screenshots in $work)"
