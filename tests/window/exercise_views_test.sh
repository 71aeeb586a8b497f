#!/usr/bin/env bash
# window.exercise-views: lesson 05 at its exercise in a 1280x720 window, keys typed with xdotool. F3 on
# the exercise's step cycles the probe's views: yours, the reference's, their difference (each said in
# the log with where it was drawn). In the difference view a screenshot (F12) shows the starter's NaN
# at the centre pixel in magenta; after the solution is saved the verdict turns to PASS and the same
# view is black all over; F3 once more goes back to the lesson's picture. No GL error in the run.
# Without a display it restarts itself under xvfb-run.
# usage: exercise_views_test.sh LESSON_05_EXE VIEW_CHECKER SOLUTION_FILE OUT_DIR
set -euo pipefail
exe="$(realpath "$1")" checker="$(realpath "$2")" solution="$(realpath "$3")" out="$(realpath -m "$4")"
if [ -z "${DISPLAY:-}" ]; then exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"; fi
command -v xdotool >/dev/null || { echo "FAIL: xdotool is missing (Debian package xdotool)"; exit 1; }
rm -rf "$out"; mkdir -p "$out/work"
export FXLAB_EXERCISES="$out/work" FXLAB_CONFIG_DIR="$out/config"
student="$out/work/05-1/radial_blur_offset.glsl"
log="$out/run.log"
# In $out: F12's screenshots go to out/ there.
(cd "$out" && exec "$exe" --exercise 1 --size 1280x720 --frames 100000 >"$log" 2>&1) &
pid=$!
stop() { kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; }
trap stop EXIT
wait_for() {  # a line in the log, for up to 60 s while the lesson runs
  for _ in $(seq 600); do
    grep -q -- "$1" "$log" && return 0
    kill -0 "$pid" 2>/dev/null || { echo "FAIL: the lesson ended early:"; cat "$log"; return 1; }
    sleep 0.1
  done
  echo "FAIL: no \"$1\" in 60 s:"; cat "$log"; return 1
}
wid="$(timeout 30 xdotool search --sync --onlyvisible --name "fxlab 5:" | sed -n 1p || true)"
[ -n "$wid" ] || { echo "FAIL: no lesson window:"; cat "$log"; exit 1; }
# Each key to the lesson's window, focused again first.
press() { xdotool windowfocus --sync "$wid"; xdotool key "$1"; }
wait_for "exercise 05-1: FAIL: .*NaN or Inf"
sleep 1
# One F3 a view, each waited for: yours, the reference's, the difference.
view=0
for name in YOURS REFERENCE DIFFERENCE; do
  view=$((view + 1))
  press F3
  wait_for "F3 view $view of 3: $name"
  wait_for "exercise view $view drawn at"
done
place="$(grep -o "exercise view 3 drawn at [0-9]*,[0-9]* [0-9]*x[0-9]*" "$log" | tail -1 | sed 's/.* at //; s/[,x]/ /g')"
# A screenshot of the view as it is now (F12), by the notice that names its file: $shot.
screenshot() {
  local before
  before=$(grep -c "screenshot saved:" "$log" || true)
  press F12
  for _ in $(seq 300); do
    [ "$(grep -c "screenshot saved:" "$log" || true)" -gt "$before" ] && break
    sleep 0.1
  done
  [ "$(grep -c "screenshot saved:" "$log" || true)" -gt "$before" ] ||
    { echo "FAIL: no screenshot 30 s after F12:"; cat "$log"; exit 1; }
  shot="$out/$(grep -o "screenshot saved: .*" "$log" | tail -1 | sed 's/screenshot saved: //')"
}
screenshot
# shellcheck disable=SC2086  # the place is four numbers
"$checker" "$shot" $place nonfinite ||
  { echo "FAIL: the starter's difference view shows no NaN (log: $log)"; exit 1; }
# Saved as an editor saves it: a new file renamed over the old one.
cp "$solution" "$out/work/05-1/.saving" && mv "$out/work/05-1/.saving" "$student"
wait_for "exercise 05-1: PASS"
sleep 1  # frames drawn with the new pictures
screenshot
# shellcheck disable=SC2086
"$checker" "$shot" $place black ||
  { echo "FAIL: the solution's difference view is not black (log: $log)"; exit 1; }
press F3
wait_for "F3 view off"
press Escape
timeout 30 tail --pid="$pid" -f /dev/null || { echo "FAIL: Esc did not end the lesson"; exit 1; }
if grep -qi "GL error" "$log"; then echo "FAIL: GL errors in the run:"; cat "$log"; exit 1; fi
echo "F3 showed yours, the reference's and the difference: the starter's NaN magenta, the solution's black"
