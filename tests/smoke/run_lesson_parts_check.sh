#!/usr/bin/env bash
# Checks of single teaching points in lessons 03 and 04, end to end:
#  - lesson 03, viewport_bug: the scene pass drawn with the shadow map's viewport changes the picture
#    and the panel says which viewport the scene got; without it the graph gives the target's.
#  - lesson 04: the split view puts the matrix's side where the objects the text talks about stand
#    (the red box and the green sphere come out grey in step 2), and a step lists only its own
#    parameters (step 4's preset is not a parameter of the grayscale step).
#   run_lesson_parts_check.sh <fxlab-03 exe> <fxlab-04 exe> <work dir>
set -uo pipefail
exe03="$1" exe04="$2" work="$3"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work"
run() {  # run <exe> <name> <args...>
  local exe="$1" name="$2"; shift 2
  "$exe" --headless --size 320x180 --frames 2 --capture "$work/$name" --report "$work/$name.json" "$@" \
    >"$work/$name.log" 2>&1 || { echo "FAIL: $name exited with an error:"; cat "$work/$name.log"; exit 1; }
}
run "$exe03" l03-step4 --step 4
run "$exe03" l03-step4-bug --step 4 --param viewport_bug=true
run "$exe04" l04-step2 --step 2
"$exe04" --list-params >"$work/l04-params.txt" 2>&1 || { echo "FAIL: --list-params"; exit 1; }
PYTHONPATH="$here" python3 - "$work" <<'PY'
import sys
from png_pixels import read_png
from report import load
work = sys.argv[1]
failures = []
def report(name):
    return load(f"{work}/{name}.json")
for name in ("l03-step4", "l03-step4-bug", "l04-step2"):
    if report(name)["glErrors"] != 0:
        failures.append(f"{name}: GL errors")
fine, bug = report("l03-step4")["facts"], report("l03-step4-bug")["facts"]
if "the target's" not in fine.get("sceneViewport", ""):
    failures.append(f"lesson 03: the graph should give the scene its target's viewport: {fine.get('sceneViewport')}")
if not bug.get("sceneViewport", "").startswith("2048x2048 on a 320x180"):
    failures.append(f"lesson 03: viewport_bug should leave the shadow map's viewport: {bug.get('sceneViewport')}")
with open(f"{work}/l03-step4/final.png", "rb") as a, open(f"{work}/l03-step4-bug/final.png", "rb") as b:
    if a.read() == b.read():
        failures.append("lesson 03: viewport_bug changes nothing in the picture")
# Lesson 04 step 2 (grayscale): the red box (about 20 % across, 55 % down) and the green sphere
# (about 36 %, 48 %) are on the matrix's side; the yellow capsule (about 79 %) shows the original.
rows = read_png(f"{work}/l04-step2/final.png")
h, w = len(rows), len(rows[0])
def pixel(fx, fy):
    return rows[int(fy * h)][int(fx * w)]
def spread(p):
    return max(p) - min(p)
for label, at in (("red box", (0.20, 0.55)), ("green sphere", (0.36, 0.48))):
    if spread(pixel(*at)) > 3:
        failures.append(f"lesson 04 step 2: the {label} at {at} is not grey: {pixel(*at)}")
if spread(pixel(0.79, 0.55)) < 40:
    failures.append(f"lesson 04 step 2: the yellow capsule should keep its colour right of the divider: "
                    f"{pixel(0.79, 0.55)}")
params = open(f"{work}/l04-params.txt").read()
start, end = params.find("preset = "), params.find("amount = ")
if start < 0 or end < start or "acts in step 4" not in params[start:end]:
    failures.append(f"lesson 04: preset should act in step 4 only:\n{params}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY
status=$?
[ "$status" -eq 0 ] && echo "lesson 03 and 04 checks passed"
exit "$status"
