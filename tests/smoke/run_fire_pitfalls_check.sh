#!/usr/bin/env bash
# Lesson 07 step 1's pitfalls, shown by its parameters and checked on the pictures they make:
#  - hold_alpha: one particle with its alpha held; the bloom's bright pass (threshold 1) is empty at
#    alpha 0.30 (3 x 0.30 = 0.9) and not at 0.40 (1.2), and the fact heldGlows says so;
#  - flip_sprite: the sprite's rows uploaded top first turn the particle over: the teardrop's heavy
#    round end moves from below its centre to above it;
#  - with the bloom's intensity at 0 the flame's most opaque pixel is the fact opaqueFlame, within 1.
#   run_fire_pitfalls_check.sh <fxlab-07-fire-emitter> <work dir>
set -uo pipefail
exe="$1" work="$2"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work"
run() {  # run <name> <args...>
  local name="$1"; shift
  "$exe" --headless --size 320x180 --frames 2 --step 1 --capture "$work/$name" --capture-float \
    --report "$work/$name.json" "$@" >"$work/$name.log" 2>&1 || { echo "FAIL: $name exited with an error:"; cat "$work/$name.log"; exit 1; }
}
run held-0.30 --param hold_alpha=0.30
run held-0.40 --param hold_alpha=0.40
run held-upright --param hold_alpha=1
run held-flipped --param hold_alpha=1 --param flip_sprite=true
run no-bloom --param intensity=0
PYTHONPATH="$here" python3 - "$work" <<'PY'
import sys
from lesson_captures import Captures
runs = Captures(sys.argv[1])
failures = runs.gl_error_failures(("held-0.30", "held-0.40", "held-upright", "held-flipped", "no-bloom"))
for name, glows in (("held-0.30", False), ("held-0.40", True)):
    brightest = max(runs.floats(name, "bloom.down-0")[3])
    if (brightest > 0) != glows:
        failures.append(f"{name}: the bright pass's largest value is {brightest}; it should {'' if glows else 'not '}glow")
    if runs.fact(name, "heldGlows") != ("yes" if glows else "no"):
        failures.append(f"{name}: heldGlows is {runs.fact(name, 'heldGlows')}")
def core_centre_y(name):  # the mean row of the pixels the held particle makes brighter than 1 in red
    width, height, channels, v = runs.floats(name, "scene.color")
    rows = [y for y in range(height) for x in range(width) if v[(y * width + x) * channels] > 1.0]
    return sum(rows) / len(rows) if rows else None
upright, flipped = core_centre_y("held-upright"), core_centre_y("held-flipped")
if upright is None or flipped is None or not flipped > upright + 2:
    failures.append(f"flip_sprite: the particle's mass should move up (rows bottom-up): upright {upright}, flipped {flipped}")
fact = runs.fact("no-bloom", "opaqueFlame") or ""
expected = tuple(int(v) for v in fact.strip("()").split(", ")) if fact.startswith("(") else None
shown = max((p for row in runs.picture("no-bloom") for p in row), key=lambda p: (p[0], p[1], p[2]))
if expected is None or any(abs(a - b) > 1 for a, b in zip(shown, expected)):
    failures.append(f"intensity 0: the most opaque flame pixel is {shown}, the fact opaqueFlame says {fact}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY
status=$?
[ "$status" -eq 0 ] && echo "lesson 07 pitfall checks passed"
exit "$status"
