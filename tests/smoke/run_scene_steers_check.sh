#!/usr/bin/env bash
# Scenes steer the lessons: lesson 06's parameters start from its scene's postEffects, a preset and
# --param override them, each value says where it came from, a parameter takes every value the scene
# format allows (one declaration of the range, scene/scene_settings.cpp) and a scene value outside it is
# refused with the file, the setting and the range, and editing the scene changes the picture.
#   run_scene_steers_check.sh <fxlab-06-bloom> <shipped scene 06_bloom.json> <work dir>
set -uo pipefail
exe="$1" shipped="$2" work="$3"
rm -rf "$work" && mkdir -p "$work"
status=0
source "$(dirname "$0")/scene_copy.sh"  # fail, edit

# A copy of the shipped scene with other post-effect settings (no asset paths in it to resolve).
edit "$work/steered.json" 'd["postEffects"]["bloom"]["intensity"] = 3; d["postEffects"]["toneMap"] = {"operator": "reinhard", "exposure": 0.5}'
edit "$work/bright.json" 'd["postEffects"]["bloom"]["intensity"] = 50'
edit "$work/too_bright.json" 'd["postEffects"]["bloom"]["intensity"] = 500'
edit "$work/no_bloom.json" 'd["postEffects"].pop("bloom"); d["postEffects"].pop("toneMap")'

expect_line() {  # expect_line <listing file> <pattern>
  grep -Eq -- "$2" "$1" || fail "no line matching '$2' in $1:"$'\n'"$(cat "$1")"
}

"$exe" --list-params >"$work/shipped.txt" 2>&1 || fail "--list-params with the shipped scene"
expect_line "$work/shipped.txt" '^intensity = 2  \[scene\]'
expect_line "$work/shipped.txt" '^tone_map = filmic  \[scene\]'
expect_line "$work/shipped.txt" '^reference = false  \[default\]'
expect_line "$work/shipped.txt" 'starts from the scene.s postEffects\.bloom\.intensity'

"$exe" --scene "$work/steered.json" --list-params >"$work/steered.txt" 2>&1 || fail "--list-params with an edited scene"
expect_line "$work/steered.txt" '^intensity = 3  \[scene\]'
expect_line "$work/steered.txt" '^tone_map = reinhard  \[scene\]'
expect_line "$work/steered.txt" '^exposure = 0\.5  \[scene\]'

echo '{"exposure": "2"}' >"$work/preset.json"
"$exe" --scene "$work/steered.json" --preset "$work/preset.json" --param intensity=1 --list-params \
  >"$work/overridden.txt" 2>&1 || fail "--list-params with a preset and --param"
expect_line "$work/overridden.txt" '^intensity = 1  \[command line\]'
expect_line "$work/overridden.txt" '^exposure = 2  \[preset\]'
expect_line "$work/overridden.txt" '^tone_map = reinhard  \[scene\]'

"$exe" --scene "$work/no_bloom.json" --list-params >"$work/no_bloom.txt" 2>&1 || fail "--list-params without bloom"
expect_line "$work/no_bloom.txt" '^intensity = 1  \[default\]'  # the setting's default, as a scene without it gets

"$exe" --scene "$work/bright.json" --list-params >"$work/bright.txt" 2>&1 || fail "a scene intensity of 50 was refused"
expect_line "$work/bright.txt" '^intensity = 50  \[scene\]'
if "$exe" --scene "$work/too_bright.json" --list-params >"$work/too_bright.txt" 2>&1; then
  fail "a scene intensity of 500 was accepted"
fi
expect_line "$work/too_bright.txt" 'too_bright\.json: postEffects\.bloom\.intensity: 500 is out of range \[0, 100\]'

# The picture: step 5 (tone curve and exposure) with the shipped scene and with the edited one.
for scene in "$shipped" "$work/steered.json"; do
  name=$(basename "$scene" .json)
  "$exe" --headless --size 160x90 --frames 1 --step 5 --scene "$scene" --capture "$work/$name" \
    --report "$work/$name/report.json" >"$work/$name.log" 2>&1 || fail "run with $scene: $(cat "$work/$name.log")"
done
if cmp -s "$work/06_bloom/final.png" "$work/steered/final.png"; then
  fail "editing the scene's bloom and tone map did not change the picture"
fi
PYTHONPATH="$(dirname "$0")" python3 - "$work/steered/report.json" <<'PY' || status=1
import sys
from report import load, params as by_name
params = by_name(load(sys.argv[1]))
bad = [n for n, want in (("intensity", "scene"), ("tone_map", "scene"), ("karis", "default")) if params[n]["source"] != want]
if bad or params["tone_map"]["value"] != "reinhard":
    print("FAIL: the report's params:", {n: params[n] for n in ("intensity", "tone_map", "karis")})
    sys.exit(1)
PY
[ "$status" -eq 0 ] && echo "scenes steer lesson 06: sources listed, overrides applied, range refused, picture changed"
exit "$status"
