#!/usr/bin/env bash
# window.exercise: lesson 05 in a real window at its exercise (--exercise 1); while it runs the
# student's file is saved with the solution, and the lesson must say FAIL and then PASS, and keep
# running without a GL error. START says what the student's file holds when the lesson opens:
# - starter: the starter, which compiles; the FAIL names the NaN at the centre pixel.
# - broken: the solution with a typo, which does not compile; the lesson opens anyway, drawing with
#   its own file, the FAIL names the student's file and line, and the save that compiles takes over.
# Without a display it restarts itself under xvfb-run.
# usage: exercise_test.sh LESSON_05_EXE SOLUTION_FILE OUT_DIR [starter|broken]
set -euo pipefail
exe="$1" solution="$2" out="$3" start="${4:-starter}"
if [ -z "${DISPLAY:-}" ]; then exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"; fi
rm -rf "$out"; mkdir -p "$out/work"
export FXLAB_EXERCISES="$out/work" FXLAB_CONFIG_DIR="$out/config"
student="$out/work/05-1/radial_blur_offset.glsl"
case "$start" in
  starter) expected_fail="exercise 05-1: FAIL: .*NaN or Inf" ;;
  broken)
    # `start` never overwrites the student's file, so this is what the lesson opens with.
    mkdir -p "$out/work/05-1"
    sed 's/= length(d);/= lenght(d);/' "$solution" >"$student"
    line=$(grep -n "lenght(d)" "$student" | cut -d: -f1)
    [ -n "$line" ] || { echo "the typo was not made in $solution"; exit 1; }
    expected_fail="exercise 05-1: FAIL: .*$student:$line:" ;;
  *) echo "usage: $0 LESSON_05_EXE SOLUTION_FILE OUT_DIR [starter|broken]"; exit 2 ;;
esac
log="$out/run.log"
"$exe" --exercise 1 --size 640x360 --frames 100000 --report "$out/report.json" >"$log" 2>&1 &
pid=$!
wait_for() {  # a line in the log, for up to 60 s while the lesson runs
  for _ in $(seq 600); do
    grep -q "$1" "$log" && return 0
    kill -0 "$pid" 2>/dev/null || { echo "the lesson ended early:"; cat "$log"; return 1; }
    sleep 0.1
  done
  echo "no \"$1\" in 60 s:"; cat "$log"; return 1
}
stop() { kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; }
trap stop EXIT
wait_for "$expected_fail"
if [ "$start" = broken ]; then
  grep -q "drawing with the lesson's own file until yours compiles" "$log" ||
    { echo "the lesson did not say it draws with its own file:"; cat "$log"; exit 1; }
  sleep 1  # a few frames drawn with the lesson's own program
fi
# Saved as an editor saves it: a new file renamed over the old one.
cp "$solution" "$out/work/05-1/.saving" && mv "$out/work/05-1/.saving" "$student"
wait_for "exercise 05-1: PASS"
# The student's program replaced the lesson's own: every program rebuilt from the save, none failed.
[ "$start" = starter ] || wait_for "a shader was saved: [0-9]* program(s) rebuilt"
grep -q '"05-1"' "$out/work/progress.json"
if grep -qi "GL error" "$log"; then echo "GL errors in the run:"; cat "$log"; exit 1; fi
if [ "$start" = starter ] && grep -qi "did not build" "$log"; then echo "errors in the run:"; cat "$log"; exit 1; fi
echo "the verdict changed from FAIL to PASS while the lesson ran (started with the $start)"
