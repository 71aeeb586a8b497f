#!/usr/bin/env bash
# Every shader a lesson builds passes Khronos' reference compiler. The lesson runs every step headless
# (one frame, a small size), its last step again with the overlay, the inspector open on a texture
# and the compare view (the overlay's own programs), and its bench sweep (every knob's every value and
# the references, one frame each, at a tiny size: the sweep is what builds the knobs' variants), all
# with --dump-shaders into one folder; validate_shaders.py then checks each file with glslangValidator
# as GLSL 4.50 core (no error, no warning; a file the driver refused must be refused there too).
#   run_portability_check.sh <lesson exe> <work dir>
# Exits 77 (skipped) when glslangValidator is not installed (Debian package glslang-tools).
set -uo pipefail
exe="$1" work="$2"
here="$(cd "$(dirname "$0")" && pwd)"
name="$(basename "$exe")"
if ! command -v glslangValidator >/dev/null; then
  echo "SKIP: glslangValidator is not installed (Debian package glslang-tools)"; exit 77
fi
rm -rf "$work" && mkdir -p "$work"
export FXLAB_CONFIG_DIR="$work/config"  # never the teacher's ui.json
shaders="$work/shaders"
steps="$("$exe" --list-steps 2>/dev/null | grep -c '^[0-9][0-9]*\. ')"
if [ "${steps:-0}" -lt 1 ]; then echo "FAIL: $name --list-steps lists no steps"; exit 1; fi
status=0
for ((k = 1; k <= steps; k++)); do
  if ! "$exe" --headless --size 64x36 --frames 1 --step "$k" --report "$work/step-$k.json" \
       --dump-shaders "$shaders" >"$work/step-$k.log" 2>&1; then
    echo "FAIL: $name step $k exited with an error:"; tail -n 20 "$work/step-$k.log"; status=1
  fi
done
# The overlay's programs: the inspector on the last step's first written texture, the compare view (F3).
shown="$(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(next(w for p in r["passes"] if p["executed"] for w in p["writes"]))' "$work/step-$steps.json" 2>/dev/null)"
if ! "$exe" --headless --overlay --size 320x180 --frames 2 --step "$steps" ${shown:+--inspect "$shown"} --press F3@1 \
     --dump-shaders "$shaders" >"$work/overlay.log" 2>&1; then
  echo "FAIL: $name with the overlay exited with an error:"; tail -n 20 "$work/overlay.log"; status=1
fi
# The sweep: a lesson without knobs says so and builds nothing more.
if ! "$exe" --bench --size 32x18 --bench-frames 1 --bench-out "$work/bench" --dump-shaders "$shaders" \
     >"$work/bench.log" 2>&1; then
  echo "FAIL: $name's bench sweep exited with an error:"; tail -n 20 "$work/bench.log"; status=1
fi
python3 "$here/validate_shaders.py" "$shaders" --min-files 2 || status=1
[ "$status" -eq 0 ] && echo "$name: every shader of every step and knob value passes glslangValidator"
exit "$status"
