#!/usr/bin/env bash
# Lesson 09. Scenes decide: on a scene without postEffects.depthOfField (lesson 04's) every step runs
# no depth-of-field pass, and the report gives the scene's reason for each; on its own scene the same
# passes run. Slider extremes the scene loader refuses (focus at the focal length, f-number 0, focal
# length 0) and focus at infinity: no GL error, no NaN or infinity in any texture with statistics.
#   run_dof_scene_checks.sh <lesson 09 exe> <scene without depth of field> <work dir>
set -uo pipefail
exe="$1" scene="$2" work="$3"
rm -rf "$work" && mkdir -p "$work"
status=0
for step in 2 4 5 6 7; do
  report="$work/step-$step.json"
  if ! "$exe" --headless --size 64x36 --frames 2 --step "$step" --scene "$scene" --report "$report" >"$work/log" 2>&1; then
    echo "FAIL: step $step exited with an error:"; cat "$work/log"; status=1; continue
  fi
  PYTHONPATH="$(dirname "$0")" python3 - "$report" "$step" <<'PY' || status=1
import sys
from report import load
report, step = load(sys.argv[1]), sys.argv[2]
passes = []
def walk(o):
    if isinstance(o, dict):
        if isinstance(o.get("name"), str) and o["name"].startswith("dof ") and "executed" in o:
            passes.append(o)
        for v in o.values(): walk(v)
    elif isinstance(o, list):
        for v in o: walk(v)
walk(report)
bad = [p["name"] for p in passes if p["executed"] or "does not ask for depthOfField" not in p.get("reason", "")]
if not passes or bad:
    print(f"FAIL: step {step}: dof passes {[p['name'] for p in passes]}, ran or without the scene's reason: {bad}")
    sys.exit(1)
PY
done
# The control: with its own scene, step 6's gather runs.
"$exe" --headless --size 64x36 --frames 2 --step 6 --report "$work/own.json" >"$work/log" 2>&1 || { echo "FAIL: own scene"; status=1; }
grep -q '"dof gather"' "$work/own.json" || { echo "FAIL: no dof gather in the own scene's report"; status=1; }
# A valid scene focused at a far mountain starts focus_distance where it is: the parameter has the
# setting's range (scene/scene_settings.cpp), up to infinity, written as the word.
shipped="$(dirname "$scene")/09_depth_of_field.json"
source "$(dirname "$0")/scene_copy.sh"  # fail, edit
for far in 100000 '"infinity"'; do
  edit "$work/far.json" "d['camera']['lens']['focusDistance'] = $far; d['objects'] = []"  # no paths to resolve
  "$exe" --scene "$work/far.json" --list-params >"$work/far.txt" 2>&1 || { fail "focus at $far refused:"; cat "$work/far.txt"; }
  grep -q "^focus_distance = ${far//\"/}  \[scene\]" "$work/far.txt" || { fail "focus at $far is not the parameter's start:"; cat "$work/far.txt"; }
done
for run in "4 focus_distance=0.0311769" "6 focus_distance=0.0311769" "6 focus_distance=infinity" "4 f_number=0" \
           "6 f_number=0" "7 focal_length=0"; do
  set -- $run
  report="$work/extreme-$1-$2.json"
  "$exe" --headless --size 63x63 --frames 1 --step "$1" --param "$2" --report "$report" >"$work/log" 2>&1 ||
    { echo "FAIL: step $1 with $2 exited with an error:"; cat "$work/log"; status=1; continue; }
  PYTHONPATH="$(dirname "$0")" python3 - "$report" "$1 $2" <<'PY' || status=1
import sys
from report import load, non_finite, texture_stats
r = load(sys.argv[1])
stats = texture_stats(r)
bad = non_finite(r)
if r["glErrors"] or bad or not stats:
    print(f"FAIL: {sys.argv[2]}: {r['glErrors']} GL errors, {bad} NaN/Inf in {len(stats)} channels")
    sys.exit(1)
PY
done
exit $status
