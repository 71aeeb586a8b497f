#!/usr/bin/env python3
"""A lesson is one folder (README.md, "Adding a lesson"): lessons/NN_name/ with lesson.md and
lesson.ja.md, its code in .cpp files, the last line of one of them FX_LESSON(Class, "Title", "scene")
(its main(), app/runner.hpp), the scene a file under res/ or "" (none). No main.cpp, no info() (the
folder gives the number and the slug, cmake/FxLesson.cmake), and no header that only one file
includes (it belongs in that file). Prints one line per violation; exits 1 when there is one.

check_lesson_folders.py [ROOT] [--expect FILE] (tests/checker_cli.py); its fixture is tests/lessons/fixture.
check_lesson_folders.py --readme README.md FILE: README's smallest lesson (the C++ block after "The
smallest lesson") is FILE, the lesson the build compiles and runs, to the letter."""
import os
import re
import sys
import pathlib

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import checker_cli  # noqa: E402 (tests/checker_cli.py: the command line every checker shares)

FOLDER = re.compile(r"^[0-9][0-9]_[a-z0-9]+(_[a-z0-9]+)*$")
MACRO = re.compile(r'^FX_LESSON\(\s*[\w:]+\s*,\s*"[^"]+"\s*,\s*"([^"]*)"\s*\)\s*$')


def check(root):
    problems = []
    lessons = os.path.join(root, "lessons")
    numbers = {}
    for name in sorted(os.listdir(lessons)):
        folder = os.path.join(lessons, name)
        if not os.path.isdir(folder):
            continue
        where = f"lessons/{name}"
        if not FOLDER.match(name):
            problems.append(f"{where}: the folder is not named NN_name (two digits, then lower-case words joined by _)")
            continue
        numbers.setdefault(name[:2], []).append(name)
        files = sorted(os.listdir(folder))
        for text in ("lesson.md", "lesson.ja.md"):
            if text not in files:
                problems.append(f"{where}: no {text}")
        if "main.cpp" in files:
            problems.append(f"{where}/main.cpp: a lesson has no main.cpp (FX_LESSON at the end of its .cpp is its main)")
        sources = {f: open(os.path.join(folder, f), encoding="utf-8").read() for f in files if f.endswith((".cpp", ".hpp"))}
        macros = []
        for f, text in sources.items():
            lines = text.split("\n")
            for i, line in enumerate(lines):
                if line.startswith("FX_LESSON("):
                    macros.append((f, i, lines))
            if re.search(r"\bLessonInfo\s+info\s*\(", text):
                problems.append(f"{where}/{f}: info() is the runner's (the number and slug come from the folder, the title and scene from FX_LESSON)")
        if not macros:
            problems.append(f"{where}: no FX_LESSON(Class, \"Title\", \"scene\") in its .cpp files")
        elif len(macros) > 1:
            problems.append(f"{where}: FX_LESSON appears {len(macros)} times; a lesson has one")
        for f, i, lines in macros:
            if any(line.strip() for line in lines[i + 1:]):
                problems.append(f"{where}/{f}:{i + 1}: FX_LESSON is not the file's last line")
            m = MACRO.match(lines[i])
            if not m:
                problems.append(f"{where}/{f}:{i + 1}: write FX_LESSON(Class, \"Title\", \"scenes/NN_name.json\") on one line")
            elif m.group(1) and not os.path.isfile(os.path.join(root, "res", m.group(1))):
                problems.append(f"{where}/{f}:{i + 1}: the scene res/{m.group(1)} does not exist")
        for header in (f for f in sources if f.endswith(".hpp")):
            users = [f for f, text in sources.items() if f.endswith(".cpp") and f'#include "{header}"' in text]
            if len(users) < 2:
                problems.append(f"{where}/{header}: included by {len(users)} file(s) of the lesson; a header only one .cpp needs belongs in that .cpp")
    for number, names in sorted(numbers.items()):
        if len(names) > 1:
            problems.append(f"lessons: {', '.join(names)} share the number {number}")
    return problems


def readme_block(readme):
    text = open(readme, encoding="utf-8").read()
    at = text.find("The smallest lesson")
    start = text.find("```cpp\n", at)
    if at < 0 or start < 0:
        return None
    start += len("```cpp\n")
    return text[start:text.find("```", start)]


def main():
    args = sys.argv[1:]
    if args[:1] == ["--readme"] and len(args) == 3:
        shown = readme_block(args[1])
        built = open(args[2], encoding="utf-8").read()
        if shown != built:
            print(f"{args[1]}: the smallest lesson it shows is not {args[2]} (the one the build compiles)")
            return 1
        print(f"{args[1]} shows {args[2]} as it is ({built.count(chr(10))} lines)")
        return 0
    return checker_cli.run(
        "check_lesson_folders", lambda root: check(str(root)),
        lambda root: f"every lesson folder under {root / 'lessons'} has the lesson shape", __doc__)


if __name__ == "__main__":
    sys.exit(main())
