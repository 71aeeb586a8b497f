#!/usr/bin/env bash
# Bench smoke test: at 0x0 the bench refuses with a reason; a lesson without knobs says so and writes nothing; otherwise a one-value sweep of every knob at a small size writes its CSV, JSON and plots;
# every knob keeps exactly one reference row although the sweep is cut to one value; that row is
# rendered again like the others and its picture matches the reference image (the frame is
# reproducible); and nothing raised a GL error. (A value known to differ showing an error is
# tests/gl/test_bench_sweep.cpp, on a lesson whose pictures are known.)
#   run_bench_smoke.sh <lesson exe> <work dir>
set -uo pipefail
exe="$1" work="$2"
rm -rf "$work" && mkdir -p "$work"
if ! "$exe" --bench --size 160x90 --bench-frames 1 --bench-values 1 --bench-out "$work" >"$work/log" 2>&1; then
  echo "FAIL: the bench exited with an error:"; cat "$work/log"; exit 1
fi
status=0
# At 0x0 nothing is drawn: the bench says so, exits 2 and writes nothing.
"$exe" --bench --size 0x0 --bench-frames 1 --bench-out "$work/empty" >"$work/empty.log" 2>&1
code=$?
if [ "$code" -ne 2 ] || [ -e "$work/empty" ] || ! grep -q "nothing to time" "$work/empty.log"; then
  echo "FAIL: --bench at 0x0 must say there is nothing to time, exit 2 and write nothing (exit $code):"
  cat "$work/empty.log"; status=1
fi
knobs=$("$exe" --list-params | grep -c 'quality knob')
# A lesson without knobs says so, and writes no empty table.
if [ "$knobs" -eq 0 ]; then
  if grep -q "has no quality knobs" "$work/log" && [ ! -e "$work/bench.csv" ]; then
    echo "bench: no knobs, said so"; exit "$status"
  fi
  echo "FAIL: a lesson without knobs must say so instead of writing a table:"; cat "$work/log"; exit 1
fi
for f in bench.csv bench.json; do
  [ -s "$work/$f" ] || { echo "FAIL: no $f"; status=1; }
done
rows=$(($(wc -l <"$work/bench.csv") - 1))
plots=$(find "$work" -name 'bench-*.png' | wc -l)
# One value per knob, plus the reference row when the first value is not it.
[ "$rows" -ge "$knobs" ] || { echo "FAIL: $rows rows for $knobs knobs"; status=1; }
# Column 5 is the knob, column 7 whether the row is the reference: one reference row per knob.
awk -F, 'NR > 1 { seen[$5] = 1; if ($7 == 1) refs[$5]++ }
         END { for (k in seen) if (refs[k] != 1) { print "FAIL: knob " k " has " refs[k] + 0 " reference rows"; bad = 1 }
               exit bad }' "$work/bench.csv" || status=1
[ "$plots" -eq "$knobs" ] || { echo "FAIL: $plots plots for $knobs knobs"; status=1; }
# The reference row's RMSE (the rmse column, found by its header) against the reference image must be 0.
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "rmse") c = i; next }
         $7 == 1 && $c != 0 { print "FAIL: reference row with RMSE " $c; bad = 1 }
         END { if (!c) { print "FAIL: no rmse column"; bad = 1 } exit bad }' "$work/bench.csv" || status=1
# The cost model beside the time (render/pass_traffic.hpp): every row moves bytes at 1920x1080 and says
# its taps per pixel, the same on every machine (docs/bench.md, --cost traffic).
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "traffic_mb_1080p") t = i; if ($i == "taps_per_pixel") p = i }; next }
         !($t > 0) || $p == "" { print "FAIL: row " NR - 1 " has no modelled traffic (" $t ") or taps (" $p ")"; bad = 1 }
         END { if (!t || !p) { print "FAIL: no traffic_mb_1080p or taps_per_pixel column"; bad = 1 } exit bad }' \
  "$work/bench.csv" || status=1
# Where the time goes: passes.csv has every pass of every row, in copies.
[ "$(wc -l <"$work/passes.csv" 2>/dev/null || echo 0)" -gt "$rows" ] || { echo "FAIL: passes.csv lists no passes"; status=1; }
[ "$status" -eq 0 ] && echo "bench: $rows rows, $plots plots" && cat "$work/log" | tail -n +2
exit "$status"
