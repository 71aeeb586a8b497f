"""What a smoke check reads from a lesson run with --capture DIR/NAME --report DIR/NAME.json: the
report, the captured pictures (rows top first, png_pixels) and float textures (--capture-float). The
standard library only."""
import json
import struct

from png_pixels import read_png


class Captures:
    def __init__(self, work):
        self.work = work

    def report(self, name):
        with open(f"{self.work}/{name}.json") as f:
            return json.load(f)

    def fact(self, name, fact):
        return self.report(name)["facts"].get(fact)

    def picture(self, name, texture="final"):
        return read_png(f"{self.work}/{name}/{texture}.png")

    def floats(self, name, texture):
        """(width, height, channels, values) of DIR/NAME/TEXTURE.pfm, rows bottom-up as stored."""
        with open(f"{self.work}/{name}/{texture}.pfm", "rb") as f:
            kind = f.readline().strip()
            width, height = map(int, f.readline().split())
            scale = float(f.readline())
            channels = 3 if kind == b"PF" else 1
            count = width * height * channels
            values = struct.unpack(("<" if scale < 0 else ">") + f"{count}f", f.read(4 * count))
        return width, height, channels, values

    def gl_error_failures(self, names):
        return [f"{name}: GL errors" for name in names if self.report(name)["glErrors"] != 0]
