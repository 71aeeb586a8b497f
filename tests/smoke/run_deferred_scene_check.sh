#!/usr/bin/env bash
# Lesson 10: the scene decides. With three point lights and the moon (not "many") the light culling pass is not
# called for, with the scene's reason, and every light is still lit; without a mirror neither
# reflection pass runs. A camera in the mirror's plane (edge-on) and the sizes the smoke test does not
# cover (63x63, 1279x719) run with no GL error and no NaN or infinity in any texture; so do the
# mistakes steps 4 and 7 show on purpose. And the bench's light count reaches the picture.
#   run_deferred_scene_check.sh <fxlab-10-deferred-shading> <shipped scene 10_deferred_shading.json> <work dir>
set -uo pipefail
exe="$1" shipped="$2" work="$3"
rm -rf "$work" && mkdir -p "$work"
status=0
source "$(dirname "$0")/scene_copy.sh"  # fail, edit

edit "$work/four_lights.json" 'd["lightGrids"][0]["count"] = [3, 1]; d["objects"] = [o for o in d["objects"] if "mirror" not in o]'
edit "$work/edge_on.json" 'd["camera"] = {"position": [0, 0.02, 12], "target": [0, 0.02, 0], "fovY": 55, "near": 0.1, "far": 200}'

# check <report> <python expression on the report r, passes, facts, finite>: prints the expression's failure
check() { python3 "$(dirname "$0")/report.py" check "$1" "$2" || fail "$1: $2"; }

run() {  # run <name> <frames> <args...>
  local name="$1" frames="$2"; shift 2
  "$exe" --headless --frames "$frames" --report "$work/$name.json" "$@" >"$work/$name.log" 2>&1 || fail "$name exited with an error: $(tail -5 "$work/$name.log")"
}

run few 2 --step 7 --size 160x90 --scene "$work/four_lights.json"
check "$work/few.json" 'passes["light culling"]["status"] == "not called for" and passes["light culling"]["reason"] == "scene has 4 lights; many lights means more than 4"'
check "$work/few.json" 'passes["deferred lighting"]["status"] == "runs" and r["facts"]["pointLights"] == "3"'
check "$work/few.json" 'passes["planar reflection"]["status"] == "not called for" and "no mirror" in passes["planar reflection"]["reason"] and passes["mirror surface"]["status"] == "not called for"'
check "$work/few.json" 'r["glErrors"] == 0 and finite'

run edge 2 --step 7 --size 160x90 --scene "$work/edge_on.json" --capture "$work/edge"
check "$work/edge.json" 'passes["planar reflection"]["status"] == "runs" and r["glErrors"] == 0 and finite'

for step in 1 2 3 4 5 6 7; do
  run "s63-$step" 2 --step "$step" --size 63x63 --capture "$work/s63-$step"
  check "$work/s63-$step.json" 'r["glErrors"] == 0 and finite'
  # The large odd size with a few lights, so the untiled steps stay quick on a software renderer.
  run "big-$step" 1 --step "$step" --size 1279x719 --param light_count=16 --capture "$work/big-$step"
  check "$work/big-$step.json" 'r["glErrors"] == 0 and finite'
done
# The mistakes shown on purpose (tests/gl/test_planar_reflection.cpp and test_per_vertex_lighting.cpp
# read their pictures back): each runs in the lesson without a GL error and says what it draws.
run per-vertex 2 --step 4 --size 160x90 --param lighting=per-vertex
check "$work/per-vertex.json" 'passes["per-vertex lighting"]["status"] == "runs" and r["glErrors"] == 0 and finite and r["facts"]["lighting"].startswith("per vertex")'
run mirror-objects 2 --step 7 --size 160x90 --param mirror_objects=true --param reflection_clear=chapter
check "$work/mirror-objects.json" 'passes["planar reflection"]["status"] == "runs" and r["glErrors"] == 0 and finite and r["facts"]["reflectionMirrors"].startswith("the objects") and r["facts"]["reflectionClear"].startswith("the chapter")'
# The bench changes the light count between frames without an update(): one light must give another
# picture than the reference's 1024 (the list is uploaded where the frame is built).
"$exe" --bench --size 64x36 --bench-frames 1 --bench-values 1 --knob light_count --bench-out "$work/bench" \
  >"$work/bench.log" 2>&1 || fail "the light_count bench exited with an error: $(tail -5 "$work/bench.log")"
# Columns: 5 knob, 6 value, 12 RMSE.
awk -F, 'NR > 1 { gsub(/"/, "", $6) } NR > 1 && $5 == "light_count" && $6 == "1" { found = 1; if ($12 + 0 <= 0) bad = 1 }
         END { exit (found && !bad) ? 0 : 1 }' "$work/bench/bench.csv" ||
  fail "one light gives the reference picture in the bench: $(cat "$work/bench/bench.csv")"

[ "$status" -eq 0 ] && echo "lesson 10 scene and size checks passed"
exit "$status"
