#!/usr/bin/env python3
"""Pictures of the overlay in README, docs/ and the lessons' text are made from today's layout.

tools/docs/overlay_pictures.sh makes them and lists each in docs/images/overlay-pictures.tsv with the
sha256 of the layout's code (common/ui/panel_layout.*) it ran with and the picture's own sha256.
This fails when a text shows an overlay picture (a name with "overlay", "layout", "japanese" or
"chain-strip") that the list does not hold, when a listed picture differs from its sha256 (edited or
replaced by hand), or when the layout's code changed since the pictures were made: run the script.

  check_overlay_pictures.py <project root>
"""
import hashlib
import re
import sys
from pathlib import Path

OVERLAY_NAME = re.compile(r"overlay|layout|japanese|chain-strip")
PICTURE = re.compile(r"!\[[^\]]*\]\(<?([^)>\s]+\.png)>?\)")


def main():
    root = Path(sys.argv[1])
    images = root / "docs" / "images"
    manifest = images / "overlay-pictures.tsv"
    failures = []
    listed = {}
    if manifest.exists():
        for line in manifest.read_text(encoding="utf-8").splitlines()[1:]:
            name, layout, picture, run = line.split("\t")
            listed[name] = (layout, picture, run)
    else:
        failures.append(f"{manifest} is missing: run tools/docs/overlay_pictures.sh")
    layout_now = hashlib.sha256(b"".join(
        (root / "common" / "ui" / f).read_bytes() for f in ("panel_layout.hpp", "panel_layout.cpp"))).hexdigest()
    texts = [root / "README.md", *sorted((root / "docs").glob("*.md")), *sorted((root / "lessons").glob("*/lesson*.md"))]
    shown = set()
    for text in texts:
        for m in PICTURE.finditer(text.read_text(encoding="utf-8")):
            path = (text.parent / m.group(1)).resolve()
            if path.parent == images.resolve() and OVERLAY_NAME.search(path.name) and not path.name.startswith("bench-"):
                shown.add(path.name)
                if path.name not in listed:
                    failures.append(f"{text.relative_to(root)} shows {path.name}, which "
                                    "tools/docs/overlay_pictures.sh does not make")
    for name, (layout, picture, run) in listed.items():
        path = images / name
        if not path.exists():
            failures.append(f"{manifest.name} lists {name}, which is not in docs/images")
            continue
        if hashlib.sha256(path.read_bytes()).hexdigest() != picture:
            failures.append(f"docs/images/{name} is not the picture `{run}` made (its sha256 differs): "
                            "run tools/docs/overlay_pictures.sh")
        if layout != layout_now:
            failures.append(f"docs/images/{name} was made with another layout (common/ui/panel_layout.* "
                            "changed since): run tools/docs/overlay_pictures.sh")
    for f in failures:
        print("FAIL:", f)
    print(f"overlay pictures: {len(listed)} listed, {len(shown)} shown in the texts, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
