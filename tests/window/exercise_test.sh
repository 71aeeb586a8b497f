#!/usr/bin/env bash
# window.exercise: lesson 05 in a real window at its exercise (--exercise 1) with the starter; while
# it runs the student's file is saved with the solution, and the lesson must say FAIL (with the NaN at
# the centre pixel) and then PASS, and keep running without a GL error. Without a display it
# restarts itself under xvfb-run.
# usage: exercise_test.sh LESSON_05_EXE SOLUTION_FILE OUT_DIR
set -euo pipefail
exe="$1" solution="$2" out="$3"
if [ -z "${DISPLAY:-}" ]; then exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"; fi
rm -rf "$out"; mkdir -p "$out/work"
export FXLAB_EXERCISES="$out/work" FXLAB_CONFIG_DIR="$out/config"
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
wait_for "exercise 05-1: FAIL: .*NaN or Inf"
# Saved as an editor saves it: a new file renamed over the old one.
cp "$solution" "$out/work/05-1/.saving" && mv "$out/work/05-1/.saving" "$out/work/05-1/radial_blur_offset.glsl"
wait_for "exercise 05-1: PASS"
grep -q '"05-1"' "$out/work/progress.json"
if grep -qi "GL error\|did not build" "$log"; then echo "errors in the run:"; cat "$log"; exit 1; fi
echo "the verdict changed from FAIL to PASS while the lesson ran"
