#!/usr/bin/env bash
# Lesson 08's pitfalls, shown by its parameters and checked on the pictures they make:
#  - sky_distance: a sky that writes depth (step 5) leaves every pixel that was not sky as it was and
#    takes the clouds off sky pixels (those seen past the ground's edge, below the horizon);
#  - depth_lookup_bug: step 9 at half resolution, the depth read at the layer's own pixels (the size of
#    the depth it reads is twice the layer's) cuts the clouds by the wrong part of the scene;
#  - mipmaps: the density read at the level of the pixel's footprint leaves less high-frequency energy
#    near the horizon (step 3) than the chapter's one level, which shimmers there.
#   run_cloud_pitfalls_check.sh <fxlab-08-clouds> <work dir>
set -uo pipefail
exe="$1" work="$2"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work"
run() {  # run <name> <args...>
  local name="$1"; shift
  "$exe" --headless --size 320x180 --frames 3 --capture "$work/$name" --report "$work/$name.json" "$@" \
    >"$work/$name.log" 2>&1 || { echo "FAIL: $name exited with an error:"; cat "$work/$name.log"; exit 1; }
}
run step5 --step 5
run step5-sky --step 5 --param sky_distance=60
run step9-half --step 9 --param resolution=half
run step9-half-bug --step 9 --param resolution=half --param depth_lookup_bug=true
run step3 --step 3
run step3-mipmaps --step 3 --param mipmaps=true
PYTHONPATH="$here" python3 - "$work" <<'PY'
import sys
from lesson_captures import Captures
runs = Captures(sys.argv[1])
failures = runs.gl_error_failures(("step5", "step5-sky", "step9-half", "step9-half-bug", "step3", "step3-mipmaps"))

# sky_distance: scene.depth as stored (a depth PNG is written directly: 255 is depth 1).
if not float(runs.fact("step5-sky", "skyDepth") or "1") < 1.0:
    failures.append(f"sky_distance: skyDepth is {runs.fact('step5-sky', 'skyDepth')}, not below 1")
depth, fine, sky = runs.picture("step5", "scene.depth"), runs.picture("step5"), runs.picture("step5-sky")
sky_pixels = changed = darker = 0
for y, row in enumerate(depth):
    for x, d in enumerate(row):
        if d[0] < 255:
            if fine[y][x] != sky[y][x]:
                failures.append(f"sky_distance changed a pixel that is not sky at ({x}, {y})")
                break
            continue
        sky_pixels += 1
        if max(abs(a - b) for a, b in zip(fine[y][x], sky[y][x])) > 8:
            changed += 1
            darker += sum(sky[y][x]) < sum(fine[y][x])
if changed < 0.01 * sky_pixels or darker < 0.9 * changed:
    failures.append(f"sky_distance: of {sky_pixels} sky pixels {changed} changed, {darker} of them darker: "
                    "the clouds behind the sky should go")

# depth_lookup_bug
facts = runs.report("step9-half")["facts"], runs.report("step9-half-bug")["facts"]
if facts[0].get("depthTexelsPerPixel") != "2" or not facts[1].get("depthTexelsPerPixel", "").startswith("1"):
    failures.append(f"depth_lookup_bug: depthTexelsPerPixel {facts[0].get('depthTexelsPerPixel')} and "
                    f"{facts[1].get('depthTexelsPerPixel')}")
fine, bug = runs.picture("step9-half"), runs.picture("step9-half-bug")
moved = sum(1 for a, b in zip(fine, bug) for p, q in zip(a, b) if max(abs(u - v) for u, v in zip(p, q)) > 30)
if moved < 0.01 * len(fine) * len(fine[0]):
    failures.append(f"depth_lookup_bug: only {moved} pixels changed by more than 30")

# mipmaps: the high-frequency energy of the band just below the horizon (40 % to 50 % down).
def energy(rows):
    h, e = len(rows), 0
    for y in range(int(0.40 * h), int(0.50 * h)):
        for x in range(len(rows[y]) - 1):
            a = sum(rows[y][x])
            e += abs(a - sum(rows[y][x + 1])) + abs(a - sum(rows[y + 1][x]))
    return e
one_level, mipmapped = energy(runs.picture("step3")), energy(runs.picture("step3-mipmaps"))
if not mipmapped < 0.9 * one_level:
    failures.append(f"mipmaps: high-frequency energy near the horizon {mipmapped} against {one_level} with one level")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY
status=$?
[ "$status" -eq 0 ] && echo "lesson 08 pitfall checks passed"
exit "$status"
