#!/usr/bin/env bash
# Lesson 06 step 6, the Shader effects chapter's whole frame: with the chapter's order the passes the
# frame graph ran do the chapter's per-frame pipeline table in its order (this script holds its own
# copy of the table), and with the colour matrix moved before the bloom they do not. In the chapter's
# order the grayscale matrix greys the glow too (no coloured pixel outside the UI panel); with the
# matrix first the glow keeps its colour. And the panel of step 2 quotes the scene's emitters (the sun
# is about 300, not the thousands it once claimed).
#   run_whole_frame_check.sh <fxlab-06-bloom exe> <work dir>
set -uo pipefail
exe="$1" work="$2"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work"
for order in 0 1; do
  name="order-$order"
  "$exe" --headless --size 320x180 --frames 2 --step 6 --capture "$work/$name" --report "$work/$name.json" \
    --param "frame_order=$(python3 -c "print(['bloom, radial blur, colour matrix', 'colour matrix, then bloom, radial blur'][$order])")" \
    >"$work/$name.log" 2>&1 || { echo "FAIL: $name exited with an error:"; cat "$work/$name.log"; exit 1; }
done
"$exe" --headless --size 64x36 --frames 1 --step 2 --report "$work/step-2.json" >"$work/step-2.log" 2>&1 \
  || { echo "FAIL: step 2 exited with an error:"; cat "$work/step-2.log"; exit 1; }
PYTHONPATH="$here" python3 - "$work" <<'PY'
import re, sys
from png_pixels import read_png
from report import facts, load
work = sys.argv[1]
# The chapter's final per-frame pipeline table, rows 2 to 14, as the fxlab passes that do each row.
TABLE = ["shadow map", "scene", "bloom bright pass", "bloom down", "bloom up", "bloom composite",
         "radial blur", "colour matrix", "output transform", "ui queue"]
def row(p):
    for i, t in enumerate(TABLE):
        if p == t or re.fullmatch(re.escape(t) + r" \d+", p):
            return i
    return None
def follows(executed):
    rows = [r for r in (row(p) for p in executed) if r is not None]
    return rows == sorted(rows) and set(rows) == set(range(len(TABLE)))
failures = []
reports = {}
for order in (0, 1):
    r = load(f"{work}/order-{order}.json")
    reports[order] = r
    if r["glErrors"] != 0:
        failures.append(f"order {order}: {r['glErrors']} GL errors ({r['lastGlError']})")
executed0 = reports[0]["facts"]["executedPassOrder"].split(", ")
executed1 = reports[1]["facts"]["executedPassOrder"].split(", ")
if not follows(executed0):
    failures.append(f"the chapter's order: the graph ran {executed0}, not the chapter's table")
if reports[0]["facts"].get("followsChapterTable") != "yes":
    failures.append(f"the chapter's order: the lesson says {reports[0]['facts'].get('followsChapterTable')}")
if follows(executed1):
    failures.append(f"the colour matrix before the bloom should break the chapter's order: {executed1}")
if not str(reports[1]["facts"].get("followsChapterTable", "")).startswith("no"):
    failures.append(f"order 1: the lesson should say it leaves the chapter's order")
emitters = facts(load(f"{work}/step-2.json")).get("brightestEmitters", "")
if "sun 300" not in emitters or "firefly 900" not in emitters:
    failures.append(f"step 2: the panel should quote the scene's emitters (sun 300, firefly 900): {emitters!r}")
def coloured(order):
    rows = read_png(f"{work}/order-{order}/final.png")
    h, w = len(rows), len(rows[0])
    # The UI panel: 8 px from the bottom-right corner, at most 160x32 (effects/post/ui_queue_pass.cpp).
    def in_panel(x, y):
        return x >= w - 8 - 160 - 1 and y >= h - 8 - 32 - 1
    return sum(1 for y in range(h) for x in range(w)
               if not in_panel(x, y) and max(rows[y][x]) - min(rows[y][x]) > 6)
c0, c1 = coloured(0), coloured(1)
if c0 != 0:
    failures.append(f"the chapter's order: {c0} coloured pixels outside the UI; the matrix should grey the glow")
if c1 < 200:
    failures.append(f"colour matrix first: only {c1} coloured pixels; the glow should keep its colour")
print(f"coloured pixels outside the UI: chapter's order {c0}, matrix first {c1}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY
status=$?
[ "$status" -eq 0 ] && echo "lesson 06 whole-frame check passed"
exit "$status"
