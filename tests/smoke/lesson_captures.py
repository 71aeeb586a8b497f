"""What a smoke check reads from lesson runs made with --capture DIR/NAME --report DIR/NAME.json: the
report (through report.py), the captured pictures (rows top first, png_pixels.py) and the float
textures of --capture-float. The standard library only."""
import struct

import report as reports
from png_pixels import read_png


def read_pfm(path):
    """(width, height, channels, values) of a PFM file (--capture-float), rows bottom-up as stored."""
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        channels = 3 if kind == b"PF" else 1
        count = width * height * channels
        values = struct.unpack(("<" if scale < 0 else ">") + f"{count}f", f.read(4 * count))
    return width, height, channels, values


class Captures:
    def __init__(self, work):
        self.work = work

    def report(self, name):
        return reports.load(f"{self.work}/{name}.json")

    def fact(self, name, fact):
        return reports.facts(self.report(name)).get(fact)

    def picture(self, name, texture="final"):
        return read_png(f"{self.work}/{name}/{texture}.png")

    def floats(self, name, texture):
        """(width, height, channels, values) of DIR/NAME/TEXTURE.pfm, rows bottom-up as stored."""
        return read_pfm(f"{self.work}/{name}/{texture}.pfm")

    def gl_error_failures(self, names):
        return [f"{name}: GL errors" for name in names if self.report(name)["glErrors"] != 0]
