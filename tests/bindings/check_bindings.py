#!/usr/bin/env python3
"""One source for every uniform location and binding (README.md, "Adding a lesson"; issue 27).

The numbers live in shaders/**/*_bindings.glsl as `const int kName = N;` lines, which the shaders
include and name in their layout qualifiers and the C++ includes too (namespace fx::glsl), so GLSL
and C++ cannot disagree. This check fails on:
  - a `location =` or a buffer or image `binding =` written as a number in a shader (a sampler's
    binding may be: FullscreenPass::draw binds its textures by position),
  - a location, texture unit, buffer or image binding written as a number in a GL call of the C++,
    or a `constexpr GLint` location defined in C++,
  - a bindings file with anything but `const int` lines and comments, a name defined twice, or a
    bindings file no C++ file reads,
  - within one program (its stages together, as the C++ builds them: a vertex and a fragment shader,
    a full-screen fragment shader with common/fullscreen.vert, or a compute shader), two different
    uniforms on one location (arrays take one location per element), or two different buffers,
    images or samplers on one binding.

check_bindings.py [ROOT] [--expect FILE] (tests/checker_cli.py); its fixture is tests/bindings/fixture."""
import os
import re
import sys
import pathlib

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import checker_cli  # noqa: E402 (tests/checker_cli.py: the command line every checker shares)

# Not converted yet: the overlay's shaders and their C++ (common/ui), which the classroom work is
# rewriting as this lands. Everything else is checked.
NOT_YET = ("shaders/ui/", "common/ui/")

CONST = re.compile(r"^\s*const int (\w+) = (\d+);")
LAYOUT = re.compile(r"layout\s*\(([^)]*)\)\s*((?:uniform|buffer|readonly|writeonly|restrict|coherent|\s)+)\s*(\w+)\s*(\w+)?(\s*\[\s*(\d+)\s*\])?")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
CPP_LITERAL = [
    (re.compile(r"\bgl(?:Program)?Uniform\w*\(\s*(?:[^,()]+,\s*)?(\d+)\s*,"), "a uniform location"),
    (re.compile(r"\bglBindTextureUnit\(\s*(\d+)\s*,"), "a texture unit"),
    (re.compile(r"\bglBindBufferBase\(\s*GL_\w+\s*,\s*(\d+)\s*,"), "a buffer binding"),
    (re.compile(r"\bglBindImageTexture\(\s*(\d+)\s*,"), "an image binding"),
    (re.compile(r"\bglBindTextures\(\s*(\d+)\s*,"), "a texture unit"),
]
CPP_CONSTEXPR = re.compile(r"constexpr\s+GL(?:u)?int\s+(k\w*(?:Location|Binding|Unit))\s*=\s*\d+")


def rel(root, path):
    return os.path.relpath(path, root).replace(os.sep, "/")


def walk(root, folder, suffixes):
    for base, _, files in os.walk(os.path.join(root, folder)):
        for f in sorted(files):
            path = os.path.join(base, f)
            if f.endswith(suffixes) and not rel(root, path).startswith(NOT_YET):
                yield path


def strip_comments(text):
    return re.sub(r"//[^\n]*", "", re.sub(r"/\*.*?\*/", "", text, flags=re.S))


def expand(root, path, seen=None):
    """The shader's text with its #includes, each file once (as gl/shader_source does)."""
    seen = set() if seen is None else seen
    real = os.path.realpath(path)
    if real in seen or not os.path.isfile(path):
        return ""
    seen.add(real)
    out = []
    for line in open(path, encoding="utf-8").read().split("\n"):
        m = INCLUDE.match(line)
        if m:
            here = os.path.join(os.path.dirname(path), m.group(1))
            out.append(expand(root, here if os.path.isfile(here) else os.path.join(root, "shaders", m.group(1)), seen))
        else:
            out.append(line)
    return "\n".join(out)


def declarations(text):
    """(kind, name, first, count) for every uniform, sampler, image and buffer with a location or binding."""
    values = {m.group(1): int(m.group(2)) for m in (CONST.match(l) for l in text.split("\n")) if m}
    found = []
    for m in LAYOUT.finditer(strip_comments(text)):
        qualifiers = dict(q.strip().partition("=")[::2] for q in m.group(1).split(",") if "=" in q)
        qualifiers = {k.strip(): v.strip() for k, v in qualifiers.items()}
        storage, type_, name = m.group(2), m.group(3), m.group(4) or ""
        count = int(m.group(6)) if m.group(6) else 1
        def value(v):
            return int(v) if v.isdigit() else values.get(v)
        if "location" in qualifiers and "uniform" in storage:
            found.append(("location", name, value(qualifiers["location"]), count))
        if "binding" in qualifiers:
            kind = "buffer" if "buffer" in storage else "image" if "image" in type_ else "sampler" if "sampler" in type_ else "uniform block"
            found.append((kind + " binding", type_ if kind == "buffer" else name, value(qualifiers["binding"]), 1))
    return found


def programs(root):
    """Each program the C++ builds from literal paths: [(where, [stage paths])]."""
    found = []
    for path in list(walk(root, "common", (".cpp", ".hpp"))) + list(walk(root, "lessons", (".cpp", ".hpp"))):
        text = strip_comments(open(path, encoding="utf-8").read())
        prefix = re.search(r'kDir\s*=\s*"([^"]+)"', text)
        text = re.sub(r'\bshader\("([^"]+)"\)', lambda m: f'"{prefix.group(1) if prefix else ""}{m.group(1)}"', text)
        for statement in re.split(r";", text):
            stages = re.findall(r'"([\w/.]+\.(?:vert|frag|comp))"', statement)
            if not stages:
                continue
            start = text.find(statement)
            line = text[: start + statement.find('"' + stages[0])].count("\n") + 1
            where = f"{rel(root, path)}:{line}"
            vert = [s for s in stages if s.endswith(".vert")]
            frags = [s for s in stages if s.endswith(".frag")]
            for comp in (s for s in stages if s.endswith(".comp")):
                found.append((where, [comp]))
            if vert:
                for frag in frags or [None]:
                    found.append((where, [vert[0]] + ([frag] if frag else [])))
            else:
                for frag in frags:
                    found.append((where, ["common/fullscreen.vert", frag]))
    return found


def check(root):
    problems = []
    # 1. Numbers in the shaders.
    for path in walk(root, "shaders", (".glsl", ".vert", ".frag", ".comp")):
        if path.endswith("_bindings.glsl"):
            continue
        text = strip_comments(open(path, encoding="utf-8").read())
        for m in LAYOUT.finditer(text):
            line = text[: m.start()].count("\n") + 1
            for q in m.group(1).split(","):
                key, _, v = (p.strip() for p in q.partition("="))
                if not v.isdigit():
                    continue
                if key == "location" and "uniform" in m.group(2):
                    problems.append(f"{rel(root, path)}:{line}: location {v} written as a number; name it in a *_bindings.glsl the C++ reads too")
                if key == "binding" and "sampler" not in m.group(3):
                    problems.append(f"{rel(root, path)}:{line}: binding {v} written as a number; name it in a *_bindings.glsl the C++ reads too")
    # 2. Numbers in the C++.
    for path in list(walk(root, "common", (".cpp", ".hpp"))) + list(walk(root, "lessons", (".cpp", ".hpp"))):
        text = strip_comments(open(path, encoding="utf-8").read())
        for pattern, what in CPP_LITERAL:
            for m in pattern.finditer(text):
                line = text[: m.start()].count("\n") + 1
                problems.append(f"{rel(root, path)}:{line}: {what} written as the number {m.group(1)}; use the name from the shader's *_bindings.glsl")
        for m in CPP_CONSTEXPR.finditer(text):
            line = text[: m.start()].count("\n") + 1
            problems.append(f"{rel(root, path)}:{line}: {m.group(1)} is defined in C++; a location or binding is defined once, in a *_bindings.glsl")
    # 3. The bindings files themselves.
    defined = {}
    cpp_text = "\n".join(open(p, encoding="utf-8").read() for p in list(walk(root, "common", (".cpp", ".hpp"))) + list(walk(root, "lessons", (".cpp", ".hpp"))))
    for path in walk(root, "shaders", ("_bindings.glsl",)):
        where = rel(root, path)
        for number, line in enumerate(open(path, encoding="utf-8").read().split("\n"), 1):
            if not line.strip() or line.strip().startswith("//"):
                continue
            m = CONST.match(line)
            if not m:
                problems.append(f"{where}:{number}: only `const int kName = N;` lines and comments (the C++ reads this file too)")
                continue
            if m.group(1) in defined:
                problems.append(f"{where}:{number}: {m.group(1)} is defined again (first: {defined[m.group(1)]})")
            defined.setdefault(m.group(1), f"{where}:{number}")
        if f'#include "{where}"' not in cpp_text:
            problems.append(f"{where}: no C++ file includes it, so its numbers are the shaders' alone")
    # 4. Collisions within each program.
    seen = set()
    for where, stages in programs(root):
        key = tuple(stages)
        if key in seen:
            continue
        seen.add(key)
        paths = [os.path.join(root, "shaders", s) for s in stages]
        if not all(os.path.isfile(p) for p in paths) or any(rel(root, p).startswith(NOT_YET) for p in paths):
            continue
        taken = {}
        for stage, path in zip(stages, paths):
            for kind, name, first, count in declarations(expand(root, path)):
                if first is None:
                    continue
                space = "location" if kind == "location" else kind
                for slot in range(first, first + count):
                    other = taken.setdefault((space, slot), (name, stage))
                    if other[0] != name:
                        problems.append(f"{where}: {' + '.join(stages)}: {kind} {slot} is both {other[0]} ({other[1]}) and {name} ({stage})")
    return problems


def main():
    return checker_cli.run(
        "check_bindings", lambda root: check(str(root)),
        lambda root: f"{len(programs(str(root)))} programs checked: every location and binding is named once",
        __doc__)


if __name__ == "__main__":
    sys.exit(main())
