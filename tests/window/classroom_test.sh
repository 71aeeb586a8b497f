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
#   measure      F7 in lesson 05 step 4 with the inspector open: the cost panel's sweep runs a slice a
#                frame to its end without a GL error; a second run cancels it with Esc and goes on
#   focus        lesson 05 step 2: ctrl+click a parameter's slider, type a value, Enter, the right arrow,
#                Esc (xdotool): the value is the parameter's in step 2 (step 3 opens with its own), the
#                step moved, "." never paused the clock
#   lesson-clock lesson 07 step 2 at a forced 150 ms a frame: the hitch and its burst on the third frame
#                only, and the window's picture byte for byte the headless capture of the same frames
#   compare-moment lesson 08 step 6 to 7 with 0.5 s clock steps, then F3 twice: the difference of the two
#                steps at one moment (only the object shadows differ), not of the clouds' drift
#   reference-over-frames lesson 09 step 7: the reference's samples summed a budget's worth a frame, one
#                the first frame, and the finished picture byte for byte the headless one
#   picture-scale lesson 10 step 4 with --picture-scale 40%: the picture rendered at 40% of its place and
#                scaled into it; from the automatic scale, F6 pins it at 100%
#   compare-scale compare-moment's steps, F3 twice, then F6 halves the picture while comparing: both
#                pictures at the new scale (the step before drawn again), so only the shadows differ
#   slow-input   lesson 04 step 2 at a forced 1.2 s a frame (xdotool): F6 three times within one frame is
#                three presses in order, and a click made at the same moment, while the picture-scale
#                notice changes from one frame to the next, lands on split_view's checkbox
# Each run gets its own settings folder (FXLAB_CONFIG_DIR), so no teacher's ui.json is read or written.
# The picture scale is pinned at 100% (unless the case is about it): the checks compare the window's
# pixels with the lesson's own picture, and a loaded machine would otherwise shrink it.
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
lesson() { ls "$lessons"/fxlab-"$1"-* 2>/dev/null | sed -n 1p; }
# run <folder> <exe> [flags]: the run's captures and report in <folder>, its log beside it.
run() {
  local out="$1" exe="$2"; shift 2
  if ! "$exe" --frames "${frames:-6}" --picture-scale "${scale:-1}" "$@" --capture "$work/$out" --report "$work/$out/report.json" >"$work/$out.log" 2>&1; then
    echo "FAIL: $(basename "$exe") $* exited with an error:"; cat "$work/$out.log"; exit 1
  fi
}
checked() { "$check" "$@" || { echo "FAIL: $case_ (logs in $work)"; exit 1; }; }

case "$case_" in
  layout-*)
    size="${case_#layout-}"
    run shot "$(lesson 02)" --size "$size" --step 2
    # A 4:3 window keeps the 16:9 picture: bars above and below it, so a smaller share of the window.
    share=0.45
    [ "$size" = 1024x768 ] && share=0.35
    checked "$work/shot" --window "$size" --picture-share "$share" ;;
  text-scale)
    run first "$(lesson 02)" --size 1024x768 --press plus@1 --press plus@2
    checked "$work/first" --text-scale 1.5 --window 1024x768 --picture-share 0.2
    grep -q '"textScale": 1.5' "$FXLAB_CONFIG_DIR/ui.json" || { echo "FAIL: ui.json does not keep the text scale:"; cat "$FXLAB_CONFIG_DIR/ui.json"; exit 1; }
    # A new start, no --size: the window and the text come back as they were left.
    run again "$(lesson 02)"
    checked "$work/again" --text-scale 1.5 --window 1024x768 --picture-share 0.2 ;;
  reset)
    mkdir -p "$FXLAB_CONFIG_DIR"
    printf '{"textScale": 2.0, "columnShare": 0.6, "lessonShare": 0.2, "pictureShare": 0.8}\n' >"$FXLAB_CONFIG_DIR/ui.json"
    run jammed "$(lesson 02)" --size 1280x720 --resize 400x300@1 --resize 1280x720@3
    checked "$work/jammed" --window 1280x720 --text-scale 2 --picture-share 0.15
    frames=7 run reset "$(lesson 02)" --size 1280x720 --resize 400x300@1 --resize 1280x720@3 --press F2@4
    checked "$work/reset" --window 1280x720 --text-scale 2 --picture-share 0.25
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
    checked "$work/nan" --picture-share 0.17 --nan-log "$work/nan.log" ;;
  next-lesson)
    run next "$(lesson 01)" --size 1024x768 --press pagedown@2
    grep -q "starting fxlab-02-" "$work/next.log" || { echo "FAIL: Page Down did not start lesson 02"; cat "$work/next.log"; exit 1; }
    checked "$work/next" --lesson "$(basename "$(lesson 02)")" --window 1024x768 --picture-share 0.35 ;;
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
  measure)
    # Lesson 05's samples knob: 7 settings of 7 frames each, one frame a slice, the inspector open on
    # the blur's input all the while (the old sweep ran inside the overlay's frame and released
    # textures the inspector was still drawing: glBindTexture of a deleted name).
    # The window is resized half-way: the sweep keeps measuring at the size it started with, so its
    # frames and the lesson's are of different sizes (a sweep run while the frame's textures are held
    # would then release them under the inspector).
    frames=90 run measure "$(lesson 05)" --size 1280x720 --step 4 --inspect blur.offset --press F7@2 --resize 1100x700@20
    checked "$work/measure" --picture-share 0.17
    grep -q "measured the cost of quality" "$work/measure.log" || { echo "FAIL: the sweep did not finish:"; cat "$work/measure.log"; exit 1; }
    # Esc during the sweep cancels it and the lesson goes on to its last frame.
    frames=20 run cancel "$(lesson 05)" --size 1280x720 --step 4 --press F7@2 --press Esc@8
    grep -q "measure cancelled" "$work/cancel.log" || { echo "FAIL: Esc did not cancel the sweep:"; cat "$work/cancel.log"; exit 1; }
    count="$(grep -c '"cpuMs"' "$work/cancel/report.json")"
    [ "$count" -eq 20 ] || { echo "FAIL: Esc during the sweep ended the run after $count of 20 frames"; exit 1; }
    checked "$work/cancel" ;;
  focus)
    command -v xdotool >/dev/null || { echo "FAIL: xdotool is missing (Debian package xdotool)"; exit 1; }
    exe="$(lesson 05)"
    mkdir -p "$work/focus"
    "$exe" --size 1280x720 --step 2 --picture-scale 1 --capture "$work/focus" --report "$work/focus/report.json" \
      >"$work/focus.log" 2>&1 &
    app=$!
    wid="$(timeout 30 xdotool search --sync --onlyvisible --name "fxlab 5:" | sed -n 1p)"
    [ -n "$wid" ] || { kill "$app"; echo "FAIL: no lesson window"; exit 1; }
    xdotool windowfocus --sync "$wid"
    # The overlay has drawn (its font is made at its first frame), so clicks land on its widgets.
    for _ in $(seq 1 120); do grep -q "overlay font" "$work/focus.log" && break; sleep 0.5; done
    sleep 1
    # The first parameter's slider (centre_x) at 1280x720: ctrl+click opens its text field.
    xdotool mousemove --window "$wid" "${FOCUS_X:-130}" "${FOCUS_Y:-362}"
    # At a person's pace (each key a quick tap, shorter than a frame: Dear ImGui 1.86 alone misses those).
    xdotool keydown ctrl click 1 keyup ctrl
    sleep 1
    xdotool type --delay 60 "0.3"
    sleep 1
    xdotool key Return
    sleep 1
    xdotool key Right
    sleep 1.5
    xdotool key Escape
    if ! timeout 30 tail --pid="$app" -f /dev/null; then
      kill "$app"
      echo "FAIL: Esc did not quit the lesson: a text field still had the keyboard (log: $work/focus.log)"; exit 1
    fi
    wait "$app" || { echo "FAIL: the lesson exited with an error:"; cat "$work/focus.log"; exit 1; }
    python3 - "$work/focus/report.json" <<'PY' || { echo "FAIL: focus (log: $work/focus.log)"; exit 1; }
import json, sys
r = json.load(open(sys.argv[1]))
params = {p["name"]: p for p in r["params"]}
ok = True
def check(cond, what):
    global ok
    print(("ok:   " if cond else "FAIL: ") + what)
    ok = ok and cond
# The value typed belongs to step 2, where it was typed; step 3 opens with its own.
typed = params["centre_x"].get("changedInSteps", {}).get("2")
check(typed == "0.3", f"the typed value is the parameter's in step 2 (centre_x there = {typed})")
check(params["centre_x"]["source"] != "overlay", f"and step 3 opened with its own (centre_x = {params['centre_x']['value']}, {params['centre_x']['source']})")
check(r["step"] == 3, f"Enter let go of the keyboard: the right arrow moved to step 3 (step {r['step']})")
check(not r["clock"]["paused"], "the '.' typed into the field did not pause the clock")
sys.exit(0 if ok else 1)
PY
    ;;
  lesson-clock)
    # At 150 ms a frame every frame would be a long frame by the chapter's rules; on the lesson clock it
    # is one 1/60 s step, and the hitch (the third step) is the only long one.
    frames=3 run hitch "$(lesson 07)" --size 1280x720 --step 2 --min-frame-time 150
    frames=8 run after "$(lesson 07)" --size 1280x720 --step 2 --min-frame-time 150
    "$(lesson 07)" --headless --size 896x504 --step 2 --frames 8 --capture "$work/headless" >"$work/headless.log" 2>&1 ||
      { echo "FAIL: the headless run failed"; cat "$work/headless.log"; exit 1; }
    python3 - "$work" <<'PY' || { echo "FAIL: lesson-clock (logs in $work)"; exit 1; }
import json, sys
work = sys.argv[1]
ok = True
def check(cond, what):
    global ok
    print(("ok:   " if cond else "FAIL: ") + what)
    ok = ok and cond
hitch = json.load(open(f"{work}/hitch/report.json"))
after = json.load(open(f"{work}/after/report.json"))
check(hitch["facts"]["hitch"] is True, "the third frame is the hitch")
check(int(hitch["facts"]["negativeAlpha"]) > 0, f"the chapter's fire draws alpha below 0 at the hitch ({hitch['facts']['negativeAlpha']})")
check(after["facts"]["hitch"] is False, "the eighth frame is no hitch")
check(int(after["facts"]["negativeAlpha"]) == 0, f"and draws no alpha below 0, however slow the frame ({after['facts']['negativeAlpha']})")
slow = sorted(f["cpuMs"] for f in after["frames"])[len(after["frames"]) // 2]
check(abs(after["clock"]["seconds"] - 8 / 60) < 1e-9, f"8 frames of {slow:.0f} ms are 8 steps of the lesson clock ({after['clock']['seconds']:.4f} s)")
sys.exit(0 if ok else 1)
PY
    cmp -s "$work/after/picture.png" "$work/headless/final.png" ||
      { echo "FAIL: the window's picture after 8 frames is not the headless capture of 8 frames"; exit 1; }
    echo "the window's picture is byte for byte the headless one" ;;
  compare-moment)
    # Each frame moves the clouds by half a second: between leaving step 6 and pressing F3 they drift.
    frames=8 run moment "$(lesson 08)" --size 1280x720 --step 6 --time-step 0.5 --press right@2 --press F3@5 --press F3@6
    checked "$work/moment" --difference --lit-below 0.08 ;;
  reference-over-frames)
    # Lesson 09's reference in a window: one aperture sample the first frame, then a frame budget's
    # worth a frame; once all are summed the picture is the headless one, byte for byte.
    frames=1 run first "$(lesson 09)" --size 1280x720 --step 7 --param reference_samples=8
    grep -q '"referenceSamples": "1 of 8"' "$work/first/report.json" || { echo "FAIL: the first frame did not sum one sample:"; grep referenceSamples "$work/first/report.json"; exit 1; }
    frames=40 run done "$(lesson 09)" --size 1280x720 --step 7 --param reference_samples=8
    grep -q '"referenceSamples": "8 of 8"' "$work/done/report.json" || { echo "FAIL: the reference did not finish in 40 frames"; exit 1; }
    # The sum shows the moment it started, the first frame's: the headless run of one frame.
    "$(lesson 09)" --headless --frames 1 --size 896x504 --step 7 --param reference_samples=8 --capture "$work/headless" >"$work/headless.log" 2>&1 ||
      { echo "FAIL: the headless run failed"; cat "$work/headless.log"; exit 1; }
    cmp -s "$work/done/picture.png" "$work/headless/final.png" ||
      { echo "FAIL: the reference summed over frames is not the headless one"; exit 1; }
    checked "$work/done" ;;
  compare-scale)
    # As compare-moment, then F6 (pinned 100% to 50%) while the difference shows: the step before is
    # drawn again at the new scale; compared at two scales every edge of the clouds would light.
    frames=9 run scaled "$(lesson 08)" --size 1280x720 --step 6 --time-step 0.5 --press right@2 --press F3@5 --press F3@6 --press F6@7
    python3 - "$work/scaled/report.json" <<'PY' || { echo "FAIL: F6 did not halve the picture while comparing"; exit 1; }
import json, sys
p = json.load(open(sys.argv[1]))["picture"]
print(p)
sys.exit(0 if p["rendered"] == [448, 252] else 1)
PY
    checked "$work/scaled" --difference --lit-below 0.08 ;;
  slow-input)
    command -v xdotool >/dev/null || { echo "FAIL: xdotool is missing (Debian package xdotool)"; exit 1; }
    exe="$(lesson 04)"
    mkdir -p "$work/slow"
    "$exe" --size 1280x720 --step 2 --picture-scale 50% --min-frame-time 1200 --capture "$work/slow" \
      --report "$work/slow/report.json" >"$work/slow.log" 2>&1 &
    app=$!
    wid="$(timeout 30 xdotool search --sync --onlyvisible --name "fxlab 4:" | sed -n 1p)"
    [ -n "$wid" ] || { kill "$app"; echo "FAIL: no lesson window"; exit 1; }
    xdotool windowfocus --sync "$wid"
    for _ in $(seq 1 120); do grep -q "overlay font" "$work/slow.log" && break; sleep 0.5; done
    sleep 3
    # Within one frame: F6 three times (50% pinned -> 25% -> automatic -> 100%: the notice changes on
    # each of the next three frames, and is gone on the third), then a click on split_view's checkbox.
    xdotool key --delay 30 F6 F6 F6
    xdotool mousemove --window "$wid" "${SLOW_X:-17}" "${SLOW_Y:-368}" click 1
    sleep 8
    xdotool key Escape
    if ! timeout 30 tail --pid="$app" -f /dev/null; then
      kill "$app"; echo "FAIL: Esc did not quit the lesson (log: $work/slow.log)"; exit 1
    fi
    wait "$app" || { echo "FAIL: the lesson exited with an error:"; cat "$work/slow.log"; exit 1; }
    python3 - "$work/slow.log" "$work/slow/report.json" <<'PY' || { echo "FAIL: slow-input (log: $work/slow.log)"; exit 1; }
import json, sys
log = open(sys.argv[1]).read()
r = json.load(open(sys.argv[2]))
ok = True
def check(cond, what):
    global ok
    print(("ok:   " if cond else "FAIL: ") + what)
    ok = ok and cond
said = [line.split("picture scale ", 1)[1].strip() for line in log.splitlines() if "picture scale pinned" in line or "picture scale automatic" in line]
check(len(said) == 3 and said[0].startswith("pinned at 25%") and said[1].startswith("automatic") and said[2].startswith("pinned at 100%"),
      f"three F6 presses in one frame acted three times, in order: {said}")
params = {p["name"]: p for p in r["params"]}
check(params["split_view"]["value"] == "false", f"the click landed on split_view's checkbox (split_view = {params['split_view']['value']})")
others = [n for n, p in params.items() if p["source"] == "overlay" and n != "split_view"]
check(not others, f"and on nothing else: {others}")
sys.exit(0 if ok else 1)
PY
    ;;
  picture-scale)
    frames=4 scale=40% run scaled "$(lesson 10)" --size 1280x720 --step 4
    python3 - "$work/scaled/report.json" <<'PY' || { echo "FAIL: picture-scale"; exit 1; }
import json, sys
p = json.load(open(sys.argv[1]))["picture"]
print(p)
sys.exit(0 if p["place"] == [896, 504] and p["rendered"] == [358, 202] and not p["automatic"] else 1)
PY
    # From the automatic scale, F6 pins 100%.
    frames=4 scale=auto run pinned "$(lesson 10)" --size 1280x720 --step 4 --press F6@1
    grep -q "picture scale pinned at 100%" "$work/pinned.log" || { echo "FAIL: F6 said nothing"; exit 1; }
    python3 - "$work/pinned/report.json" <<'PY' || { echo "FAIL: F6 did not pin the scale at 100%"; exit 1; }
import json, sys
p = json.load(open(sys.argv[1]))["picture"]
print(p)
sys.exit(0 if p["rendered"] == [896, 504] and p["scale"] == 1 and not p["automatic"] else 1)
PY
    checked "$work/pinned" ;;
  *) echo "FAIL: unknown case $case_"; exit 2 ;;
esac
echo "$case_: as expected (screenshots in $work)"
