#!/usr/bin/env python3
"""Fails when a file includes a header from a layer it does not build on.

The layers, and what each one builds on, are read from common/CMakeLists.txt: the fx_add_layer()
calls that also decide what links with what, so the rule cannot drift from the build. A file in
common/<layer>/ or tests/unit/<layer>/ may include "<other>/..." only when <other> is <layer> or a
layer below it (directly or through the layers it builds on), and may include the headers of a
third-party target (<glad/...>, <imgui...>) only when one of those layers links that target.

  check_layers.py ROOT                       check the tree at ROOT; exit 1 listing every violation
  check_layers.py ROOT --expect FILE         check the checker: the violations found at ROOT must be
                                             exactly the lines of FILE
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import checker_cli  # noqa: E402 (tests/checker_cli.py: the command line every checker shares)

LAYER_CALL = re.compile(r"^\s*fx_add_layer\(\s*(\w+)([^)]*)\)", re.M)
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)
SOURCE_SUFFIXES = {".h", ".hpp", ".cpp"}
# Third-party headers that belong to one CMake target: including one needs that target linked.
EXTERNAL_HEADERS = {"glad/": "fx_glad", "imgui": "fx_imgui"}


def read_layers(cmake_file):
    """{layer: (layers it builds on directly, other targets it links)} from the fx_add_layer calls."""
    calls = LAYER_CALL.findall(cmake_file.read_text())
    names = {name for name, _ in calls}
    layers = {}
    for name, arguments in calls:
        targets = [word for word in arguments.split() if word not in ("PUBLIC", "PRIVATE")]
        below = {t[len("fx_"):] for t in targets if t.startswith("fx_") and t[len("fx_"):] in names}
        linked = {t for t in targets if not (t.startswith("fx_") and t[len("fx_"):] in names)}
        layers[name] = (below, linked)
    return layers


def builds_on(layers, layer):
    """The layer itself and every layer below it."""
    seen, pending = set(), [layer]
    while pending:
        current = pending.pop()
        if current not in seen:
            seen.add(current)
            pending.extend(layers[current][0])
    return seen


def violations(root):
    layers = read_layers(root / "common" / "CMakeLists.txt")
    found = []
    for base in (root / "common", root / "tests" / "unit"):
        for layer in sorted(layers):
            folder = base / layer
            if not folder.is_dir():
                continue
            allowed = builds_on(layers, layer)
            linked = set().union(*(layers[l][1] for l in allowed))
            for path in sorted(p for p in folder.rglob("*") if p.suffix in SOURCE_SUFFIXES):
                text = path.read_text(errors="replace")
                for match in INCLUDE.finditer(text):
                    line = text.count("\n", 0, match.start()) + 1
                    where = f"{path.relative_to(root).as_posix()}:{line}"
                    name = match.group(2)
                    if match.group(1) == '"':
                        other = name.split("/", 1)[0]
                        if "/" in name and other in layers and other not in allowed:
                            below = ", ".join(sorted(allowed - {layer})) or "nothing"
                            found.append(f'{where}: includes "{name}" from layer {other}, which {layer} '
                                         f"does not build on (it builds on: {below})")
                    else:
                        for prefix, target in EXTERNAL_HEADERS.items():
                            if name.startswith(prefix) and target not in linked:
                                found.append(f"{where}: includes <{name}> of {target}, which no layer "
                                             f"{layer} builds on links")
    return found


def main(argv):
    return checker_cli.run(
        "check_layers", violations,
        lambda root: f"every include in {root / 'common'} and {root / 'tests' / 'unit'} respects the layers",
        __doc__, argv[1:],
        failed=lambda root, found: f"{len(found)} include(s) break the layering (README.md, Layout; common/CMakeLists.txt)")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
