"""Counts the sRGB encodes between a lesson's linear scene and its final picture (Shader effects §3.4 and
hard case 8: gamma once, never twice, never zero times).

The scene file gives the background in linear light. The sky pixels of the captured `scene.color`
(PFM, exact floats) are the ones that hold it encoded some number of times (0 when the scene pass keeps
light linear, 1 when its shader encodes for the display); each of them is then looked up in final.png
against the background encoded 0, 1, 2 and 3 times. Pixels the later passes changed (a glow, a blur
edge, the UI) match none of them and are left out; every one that matches must say the same count.
  count_encodes.py CAPTURE_DIR SCENE_JSON   prints "<encodes in the scene pass> <encodes in the frame>",
                                            or fails with what it saw"""
import array
import json
import sys

from png_pixels import read_png


def read_pfm(path):
    """A PFM file (what --capture-float writes) as rows of channel tuples, top row first."""
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        values = array.array("f")
        values.frombytes(f.read())
    if scale > 0:
        values.byteswap()  # a positive scale means big-endian
    channels = 3 if kind == b"PF" else 1
    rows = [[tuple(values[(y * width + x) * channels:(y * width + x + 1) * channels]) for x in range(width)]
            for y in range(height)]
    return rows[::-1]  # PFM stores the bottom row first


def encode(c):
    return 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


def count(capture, scene_file):
    background = json.load(open(scene_file))["background"][:3]
    scene = read_pfm(f"{capture}/scene.color.pfm")
    final = read_png(f"{capture}/final.png")
    candidates = []
    for n in range(4):
        c = list(background)
        for _ in range(n):
            c = [encode(v) for v in c]
        candidates.append([255 * v for v in c])
    for a in candidates:
        for b in candidates:
            if a is not b and max(abs(x - y) for x, y in zip(a, b)) < 3:
                sys.exit(f"FAIL: the background {background} cannot tell encode counts apart")
    # The scene pass's own count: the one whose encoded background most sky texels hold. The target
    # is half float (11 bits of precision).
    def holds(texel, c):
        return all(abs(t - v / 255) <= 1e-3 * v / 255 + 1e-6 for t, v in zip(texel, c))
    in_scene = [sum(holds(t, c) for row in scene for t in row) for c in candidates]
    scene_count = max(range(len(candidates)), key=lambda n: in_scene[n])
    sky, counts = 0, {}
    for y, row in enumerate(scene):
        for x, texel in enumerate(row):
            if not holds(texel, candidates[scene_count]):
                continue
            sky += 1
            shown = final[y][x][:3]
            for n, c in enumerate(candidates):
                if max(abs(s - v) for s, v in zip(shown, c)) <= 1.5:
                    counts[n] = counts.get(n, 0) + 1
    if sky == 0:
        sys.exit(f"FAIL: no pixel of scene.color holds the background {background}, encoded or not")
    matched = sum(counts.values())
    if len(counts) != 1 or matched < sky // 2:
        sys.exit(f"FAIL: {sky} sky pixels, encode counts seen {counts}: not one count for the frame")
    return scene_count, next(iter(counts))

if __name__ == "__main__":
    print(*count(sys.argv[1], sys.argv[2]))
