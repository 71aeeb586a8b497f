#!/usr/bin/env bash
# Lesson 10: the lighting pass's time (plus the culling pass's, when it runs) against the number of
# point lights, with and without tiled culling, at one size, in one session: a CSV of every run and a
# log-log plot of the medians drawn by fx_series_plot (tools/bench/series_plot.cpp), which also prints
# them. The bench (./fxlab bench 10) sweeps one knob at a time with the others at their reference;
# this sweeps light_count for both culling settings.
#   tools/bench/lesson10_light_sweep.sh <fxlab-10-deferred-shading> <fx_series_plot> <out dir> [WxH] [runs]
set -euo pipefail
exe="$1" plot="$2" out="$3" size="${4:-320x180}" runs="${5:-3}"
mkdir -p "$out"
csv="$out/light_sweep.csv"
echo "lights,culling,run,lighting_ms,culling_ms" >"$csv"
for n in 1 4 16 64 256 1024; do
  for c in none tiled; do
    for r in $(seq 1 "$runs"); do
      "$exe" --headless --size "$size" --frames 4 --step 6 --param light_count=$n --param culling=$c \
        --report "$out/run.json" >/dev/null 2>&1
      python3 - "$out/run.json" "$n" "$c" "$r" >>"$csv" <<'PY'
import json, sys
p = {x["name"]: x for x in json.load(open(sys.argv[1]))["passes"]}
cull = p["light culling"]["timeMs"] if p["light culling"]["status"] == "runs" else 0.0
print(f'{sys.argv[2]},{sys.argv[3]},{sys.argv[4]},{p["deferred lighting"]["timeMs"]:.3f},{cull:.3f}')
PY
    done
  done
done
rm -f "$out/run.json"
"$plot" "$csv" "$out/light_sweep.png" --x lights --series culling --y lighting_ms+culling_ms \
  --title "Lesson 10 at $size: lighting (+ culling) time against point lights" --x-label "point lights" \
  --y-label "ms" --legend "culling"
