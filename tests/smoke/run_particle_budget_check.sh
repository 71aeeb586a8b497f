#!/usr/bin/env bash
# Lesson 07's particle budget (docs/reliability.md, "Budgets"): the shipped scene with its emitters
# replaced by N copies of emitter 0 (the issue's reproduction). Step 4 gives each 100,000 particles:
# at 34 copies the pool once outgrew the pool view's texture (GL_INVALID_VALUE), at 256 (the scene's
# limit) it asked for 1.66 GB. Now the pool is fitted to the device and the budget: no GL error, the
# facts say what was asked and what was allowed, the simulation runs (particles alive), and a warning
# names the emitters and the totals. One copy stays as it was asked.
#   run_particle_budget_check.sh <fxlab-07-fire-emitter> <shipped 07_fire_emitter.json> <work dir>
set -uo pipefail
exe="$1" shipped="$2" work="$3"
rm -rf "$work" && mkdir -p "$work"
status=0
source "$(dirname "$0")/scene_copy.sh"  # fail, edit

report_py="$(dirname "$0")/report.py"
fact() { python3 "$report_py" fact "$@"; }          # fact <report> <name>
report_field() { python3 "$report_py" field "$@"; }  # report_field <report> <field>

# The copies' sprite resolves from the work folder: the copies draw soft dots instead.
for n in 1 34 256; do
  scene="$work/.budget-$n.json"
  edit "$scene" "e = d['emitters'][0]; e.pop('sprite', None)
d['emitters'] = [dict(e, name='fire %d' % i) for i in range($n)]"
  "$exe" --headless --size 32x18 --frames 2 --step 4 --scene "$scene" --report "$work/$n.json" \
    >"$work/$n.log" 2>&1 || fail "$n emitters: exit code $?: $(tail -2 "$work/$n.log")"
  [ -f "$work/$n.json" ] || { fail "$n emitters: no report"; continue; }
  [ "$(report_field "$work/$n.json" glErrors)" = 0 ] || fail "$n emitters: GL errors: $(grep -m1 'GL error' "$work/$n.log")"
  budget="$(fact "$work/$n.json" particleBudget)"
  live="$(fact "$work/$n.json" live)"
  capacity="$(fact "$work/$n.json" capacity)"
  if [ "$n" = 1 ]; then
    case "$budget" in *" of "*" slots") ;; *) fail "1 emitter: budget fact '$budget' says it was clamped" ;; esac
  else
    case "$budget" in *"slots asked; 2097152 allowed"*) ;; *) fail "$n emitters: budget fact '$budget'" ;; esac
    [ "$capacity" -le 2097152 ] 2>/dev/null || fail "$n emitters: $capacity slots, more than the budget"
    grep -q "$n emitters ('fire 0', 'fire 1', 'fire 2', 'fire 3' and $((n - 4)) more) ask for" "$work/$n.log" ||
      fail "$n emitters: no warning naming the emitters: $(grep -m1 warning "$work/$n.log")"
  fi
  [ "$live" -gt 0 ] 2>/dev/null || fail "$n emitters: $live particles alive: the simulation did not run"
  echo "$n emitters: $budget; $live alive in $capacity slots"
done

[ $status = 0 ] && echo "the particle pool fits the device and the budget at every emitter count"
exit $status
