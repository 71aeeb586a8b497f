#!/usr/bin/env bash
# tools/gpu/run.sh end to end on llvmpipe, as it would run on the GPU machine: the build packed by
# tools/gpu/bundle.sh (stripped programs, their libraries and the GL dispatch libraries in lib/), then
# the run's short mode from that bundle, marked as not a GPU. Checked: every part ran and wrote its
# files, the figures say NOT A GPU and name llvmpipe, and without --not-a-gpu the script refuses to
# take llvmpipe for a GPU before it writes any figure.
#   run_gpu_script_check.sh <build dir> <work dir>
set -uo pipefail
build="$1" work="$2"
root="$(cd "$(dirname "$0")/../.." && pwd)"
rm -rf "$work" && mkdir -p "$work"
status=0
fail() { echo "FAIL: $*"; status=1; }
if ! "$root/tools/gpu/bundle.sh" "$build" "$work/bundle" >"$work/bundle.log" 2>&1; then
  echo "FAIL: bundle.sh:"; cat "$work/bundle.log"; exit 1
fi
[ -x "$work/bundle/fx_smoke_check" ] && [ -f "$work/bundle/lib/libEGL.so.1" ] || fail "the bundle lacks its programs or lib/libEGL.so.1"
if ! "$root/tools/gpu/run.sh" --bin "$work/bundle" --short --not-a-gpu "$work/out" >"$work/run.log" 2>&1; then
  fail "run.sh --short --not-a-gpu exited with an error:"; cat "$work/run.log"
fi
out="$work/out"
lessons=$(ls "$work/bundle" | grep -c '^fxlab-')
[ "$(grep -c ',pass,' "$out/smoke.csv" 2>/dev/null)" = "$lessons" ] || fail "smoke.csv does not have $lessons passing steps"
for f in bench/06/bench.csv bench/06/passes.csv bench/07/bench.csv bench/08/bench.csv bench/10/light_sweep.csv \
         bench/10/light_sweep.png timer/summary.txt summary.md bench-gpu.md; do
  [ -s "$out/$f" ] || fail "run.sh wrote no $f"
done
grep -q 'GL_TIME' "$out/timer/summary.txt" 2>/dev/null || fail "the timer run did not use timer queries: $(head -1 "$out/timer/summary.txt")"
grep -q '^# GPU run (NOT A GPU' "$out/bench-gpu.md" 2>/dev/null || fail "bench-gpu.md is not marked NOT A GPU"
grep -qi 'llvmpipe' "$out/bench-gpu.md" 2>/dev/null || fail "bench-gpu.md does not name the renderer"
# Every section has its table (a "-" row would mean the file lacked the figure).
for section in "Lesson 07" "Lesson 06" "Lesson 08" "Lesson 10"; do
  awk -v s="$section" 'index($0, "## " s) == 1 { on = 1; next } /^## / { on = 0 } on && /^\| [^-|]/ { n++ } END { exit n < 2 }' \
    "$out/bench-gpu.md" || fail "bench-gpu.md has no table rows under $section"
done
# The same run without --not-a-gpu: llvmpipe is refused by name, and no figures are written.
"$root/tools/gpu/run.sh" --bin "$work/bundle" --short "$work/refused" >"$work/refused.log" 2>&1
code=$?
if [ "$code" -eq 0 ] || ! grep -q "is a software one" "$work/refused.log" || [ -e "$work/refused/bench-gpu.md" ]; then
  fail "run.sh took llvmpipe for a GPU (exit $code):"; cat "$work/refused.log"
fi
[ "$status" -eq 0 ] && echo "tools/gpu/run.sh: bundled, run end to end on llvmpipe (short mode, not a GPU), and llvmpipe refused as a GPU"
exit "$status"
