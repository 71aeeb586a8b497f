#!/usr/bin/env bash
# Lesson 10: the lighting pass's time (plus the culling pass's, when it runs) against the number of
# point lights, with and without tiled culling, at one size, in one session: a CSV of every run and a
# log-log SVG plot of the medians. The bench (./fxlab bench 10) sweeps one knob at a time with the
# others at their reference; this sweeps light_count for both culling settings.
#   tools/bench/lesson10_light_sweep.sh <fxlab-10-deferred-shading> <out dir> [WxH] [runs]
set -euo pipefail
exe="$1" out="$2" size="${3:-320x180}" runs="${4:-3}"
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
python3 - "$csv" "$out/light_sweep.svg" "$size" <<'PY'
import csv, math, statistics, sys
from collections import defaultdict
runs = defaultdict(list)
for r in csv.DictReader(open(sys.argv[1])):
    runs[(int(r["lights"]), r["culling"])].append(float(r["lighting_ms"]) + float(r["culling_ms"]))
med = {k: statistics.median(v) for k, v in runs.items()}
counts = sorted({k[0] for k in med})
W, H, L, R, T, B = 720, 440, 80, 150, 50, 60
lo_y = 10 ** math.floor(math.log10(min(med.values())))
hi_y = 10 ** math.ceil(math.log10(max(med.values())))
def px(n): return L + (W - L - R) * math.log(n / counts[0]) / math.log(counts[-1] / counts[0])
def py(ms): return H - B - (H - T - B) * math.log(ms / lo_y) / math.log(hi_y / lo_y)
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="13">',
       f'<rect width="{W}" height="{H}" fill="white"/>',
       f'<text x="{L}" y="28" font-size="15">lesson 10: lighting (+ culling) time against point lights, {sys.argv[3]}, median</text>']
d = lo_y
while d <= hi_y * 1.0001:
    svg.append(f'<line x1="{L}" x2="{W-R}" y1="{py(d):.1f}" y2="{py(d):.1f}" stroke="#e2e2e2"/>'
               f'<text x="{L-8}" y="{py(d)+4:.1f}" text-anchor="end">{d:g}</text>')
    d *= 10
for n in counts:
    svg.append(f'<line x1="{px(n):.1f}" x2="{px(n):.1f}" y1="{T}" y2="{H-B}" stroke="#e2e2e2"/>'
               f'<text x="{px(n):.1f}" y="{H-B+18}" text-anchor="middle">{n}</text>')
svg.append(f'<text x="{(L+W-R)/2}" y="{H-15}" text-anchor="middle">point lights (log)</text>')
svg.append(f'<text x="20" y="{(T+H-B)/2}" transform="rotate(-90 20 {(T+H-B)/2})" text-anchor="middle">ms (log)</text>')
for c, colour in (("none", "#cc0000"), ("tiled", "#3465a4")):
    pts = " ".join(f"{px(n):.1f},{py(med[(n, c)]):.1f}" for n in counts)
    svg.append(f'<polyline points="{pts}" fill="none" stroke="{colour}" stroke-width="2"/>')
    for n in counts:
        svg.append(f'<circle cx="{px(n):.1f}" cy="{py(med[(n, c)]):.1f}" r="4" fill="{colour}"/>')
    y = T + 20 + (0 if c == "none" else 22)
    svg.append(f'<line x1="{W-R+15}" x2="{W-R+40}" y1="{y}" y2="{y}" stroke="{colour}" stroke-width="2"/>'
               f'<text x="{W-R+46}" y="{y+4}">culling {c}</text>')
svg.append("</svg>")
open(sys.argv[2], "w").write("\n".join(svg) + "\n")
for n in counts:
    print(f"{n:5d} lights: none {med[(n, 'none')]:9.1f} ms, tiled {med[(n, 'tiled')]:8.1f} ms")
PY
