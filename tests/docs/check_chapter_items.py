#!/usr/bin/env python3
"""Fails when docs/chapters.md says a chapter item lives somewhere that does not exist.

The page's "Where each item lives" tables name, in backticks, where an item is shown or tested:
  `gl:Suite.Name`, `unit:Suite.Name`   a GoogleTest test: TEST(Suite, Name) or TEST_F(Suite, Name) in
                                       tests/gl/ or tests/unit/ (`gl_app:` for tests/gl_app/);
  `ctest:name`                         a CTest test added by name (add_test(NAME name ...)) in a
                                       tests/**/CMakeLists.txt; a name ending in ".*" matches a prefix;
  `file:path`                          a file of the repository (lesson.md sections, scripts).
Each reference that names nothing is reported with its line. A page without any reference is an error
of its own: a checker that reads nothing would pass everything.

  check_chapter_items.py [ROOT]               check the tree at ROOT (default: this repository)
  check_chapter_items.py ROOT --expect FILE   check the checker: what it reports at ROOT must be exactly
                                              the lines of FILE
Standard library only (python3 is on CI).
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import checker_cli  # noqa: E402 (tests/checker_cli.py: the command line every checker shares)

PAGE = "docs/chapters.md"
REFERENCE = re.compile(r"`(gl|unit|gl_app|ctest|file):([^`\s]+)`")
GTEST = re.compile(r"\bTEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\)")
ADD_TEST = re.compile(r"add_test\(\s*NAME\s+([^\s)]+)")


def gtests(root, layer):
    """{"Suite.Name"} defined under tests/<layer>/."""
    found = set()
    for source in sorted((root / "tests" / layer).rglob("*.cpp")):
        for suite, name in GTEST.findall(source.read_text(encoding="utf-8")):
            found.add(f"{suite}.{name}")
    return found


def ctest_names(root):
    """Every add_test NAME under tests/ (with ${...} left as written, matched as a wildcard)."""
    names = []
    for cmake in sorted((root / "tests").rglob("CMakeLists.txt")):
        names += ADD_TEST.findall(cmake.read_text(encoding="utf-8"))
    return names


def ctest_exists(wanted, names):
    prefix = wanted[:-1] if wanted.endswith(".*") else None
    for name in names:
        pattern = "^" + re.sub(r"\\\$\\\{[^}]*\\\}", ".+", re.escape(name)) + "$"
        if prefix is not None:
            if name.startswith(prefix) or re.match(pattern, prefix + "x"):
                return True
        elif re.match(pattern, wanted):
            return True
    return False


def check(root):
    page = root / PAGE
    if not page.is_file():
        return [f"{PAGE}: missing"]
    tests = {layer: None for layer in ("gl", "unit", "gl_app")}
    names = None
    problems = []
    references = 0
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
        for kind, target in REFERENCE.findall(line):
            references += 1
            where = f"{PAGE}:{number}"
            if kind in tests:
                if tests[kind] is None:
                    tests[kind] = gtests(root, kind)
                if target not in tests[kind]:
                    problems.append(f"{where}: no test {target} in tests/{kind}/")
            elif kind == "ctest":
                if names is None:
                    names = ctest_names(root)
                if not ctest_exists(target, names):
                    problems.append(f"{where}: no CTest test named {target} in tests/**/CMakeLists.txt")
            elif not (root / target.split("#")[0]).is_file():
                problems.append(f"{where}: no file {target.split('#')[0]}")
    if references == 0:
        problems.append(f"{PAGE}: names no test or file (expected `gl:Suite.Name`, `ctest:name`, `file:path`)")
    return problems


def main(args):
    return checker_cli.run("check_chapter_items", check, lambda root: f"every test and file {PAGE} names exists",
                           __doc__, args[1:])


if __name__ == "__main__":
    sys.exit(main(sys.argv))
