#!/usr/bin/env bash
# Scenes decide what lesson 07 does: without an emitter there is no particle buffer, no dispatch and no
# particle pass (each listed with the scene's reason, 0 bytes of pool); an emitter outside the view is
# simulated but not drawn (the pass says why); a rate below 0 and a sprite missing from disk are
# refused with the field and the path named. Step 3 counts pairs out of order only unsorted.
#   run_fire_scene_check.sh <fxlab-07-fire-emitter> <shipped scene 07_fire_emitter.json> <work dir>
set -uo pipefail
exe="$1" shipped="$2" work="$3"
rm -rf "$work" && mkdir -p "$work"
status=0
source "$(dirname "$0")/scene_copy.sh"  # fail, edit

# The copies live in the work folder; their emitters draw soft dots (no sprite path to resolve),
# except the one whose sprite is missing on purpose.
dir="$work"
tag="scene"
nosprite='for e in d["emitters"]: e.pop("sprite", None)'
edit "$dir/.check-$tag-none.json" 'd.pop("emitters")'
edit "$dir/.check-$tag-behind.json" "$nosprite"'
for e in d["emitters"]: e["position"] = [-2, 0.7, 30]'
edit "$dir/.check-$tag-negative.json" "$nosprite"'
d["emitters"][0]["rate"] = -5'
edit "$dir/.check-$tag-nosprite.json" 'd["emitters"][0]["sprite"] = "no_such_sprite.png"'

report_py="$(dirname "$0")/report.py"
pass_field() { python3 "$report_py" pass "$@"; }  # pass_field <report> <pass> <field>
fact() { python3 "$report_py" fact "$@"; }        # fact <report> <name>

for step in 4 5; do
  "$exe" --headless --size 64x36 --frames 2 --step $step --scene "$dir/.check-$tag-none.json" \
    --report "$work/none-$step.json" >"$work/none-$step.log" 2>&1 || fail "step $step without emitters exited with an error"
  for p in particles.simulate $([ $step = 4 ] && echo particles.draw || echo particles.offscreen particles.composite); do
    [ "$(pass_field "$work/none-$step.json" $p executed)" = "False" ] || fail "step $step: $p ran without an emitter"
    [ "$(pass_field "$work/none-$step.json" $p reason)" = "scene has no particle emitter" ] ||
      fail "step $step: $p gives '$(pass_field "$work/none-$step.json" $p reason)'"
  done
  [ "$(fact "$work/none-$step.json" poolBytes)" = "0" ] || fail "step $step without emitters: pool bytes not 0"
done

"$exe" --headless --size 64x36 --frames 2 --step 4 --scene "$dir/.check-$tag-behind.json" \
  --report "$work/behind.json" >"$work/behind.log" 2>&1 || fail "emitters behind the camera: exited with an error"
[ "$(pass_field "$work/behind.json" particles.draw reason)" = "every emitter's bounds are outside the view" ] ||
  fail "emitters behind the camera: particles.draw gives '$(pass_field "$work/behind.json" particles.draw reason)'"
[ "$(pass_field "$work/behind.json" particles.simulate executed)" = "True" ] || fail "the simulation should keep running"

if "$exe" --headless --size 64x36 --frames 1 --scene "$dir/.check-$tag-negative.json" >"$work/negative.log" 2>&1; then
  fail "a negative rate was accepted"
fi
grep -q 'emitters\[0\].rate' "$work/negative.log" || fail "the negative rate's error does not name emitters[0].rate: $(cat "$work/negative.log")"

if "$exe" --headless --size 64x36 --frames 1 --scene "$dir/.check-$tag-nosprite.json" >"$work/nosprite.log" 2>&1; then
  fail "a missing sprite was accepted"
fi
grep -q 'no_such_sprite.png' "$work/nosprite.log" || fail "the missing sprite's error does not name the path: $(cat "$work/nosprite.log")"

# Hard case 24 in the lesson's own count: step 3's 2000 particles drawn in spawn order leave pairs
# drawn front before back (the fact outOfOrder); sorted back to front, none.
for sort in false true; do
  "$exe" --headless --size 64x36 --frames 3 --step 3 --param sort=$sort --report "$work/order-$sort.json" \
    >"$work/order-$sort.log" 2>&1 || fail "step 3 with sort=$sort exited with an error"
done
[ "$(fact "$work/order-false.json" outOfOrder)" -gt 0 ] 2>/dev/null ||
  fail "step 3 in spawn order counts $(fact "$work/order-false.json" outOfOrder) pairs out of order"
[ "$(fact "$work/order-true.json" outOfOrder)" = "0" ] ||
  fail "step 3 sorted back to front still counts $(fact "$work/order-true.json" outOfOrder) pairs out of order"

[ "$status" -eq 0 ] && echo "lesson 07: scene checks passed"
exit "$status"
