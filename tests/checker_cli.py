"""The command line every checker with a fixture shares (tests/*/check_*.py):

  CHECKER [ROOT]                 check the tree at ROOT (default: this repository): print each problem
                                 and exit 1, or say what was checked and exit 0
  CHECKER ROOT --expect FILE     check the checker on its fixture: what it reports at ROOT must be the
                                 lines of FILE, in order (blank lines in FILE are ignored)
Usage errors exit 2 with the checker's own documentation. Standard library only.
"""
import pathlib
import sys

REPOSITORY = pathlib.Path(__file__).resolve().parents[1]


def run(name, check, passed, doc, argv=None, failed=None):
    """Runs `check(root) -> [problem lines]` as the command line above says.

    passed(root) says what a clean tree was checked for; failed(root, problems), where given, is a
    last line under the problems (how to fix them), or None."""
    args = list(sys.argv[1:] if argv is None else argv)
    expect = None
    if len(args) == 3 and args[1] == "--expect":
        expect = pathlib.Path(args[2])
        args = args[:1]
    if len(args) > 1 or (args and args[0].startswith("-")):
        print(doc, file=sys.stderr)
        return 2
    root = pathlib.Path(args[0]) if args else REPOSITORY
    problems = check(root)
    if expect is not None:
        return matches_fixture(name, root, problems, expect)
    for line in problems:
        print(line)
    if problems:
        advice = failed(root, problems) if failed is not None else None
        if advice:
            print(f"{name}: {advice}")
        return 1
    print(f"{name}: {passed(root)}")
    return 0


def matches_fixture(name, root, problems, expect):
    wanted = [line for line in expect.read_text(encoding="utf-8").splitlines() if line.strip()]
    if problems == wanted:
        print(f"{name}: reports at {root} exactly the {len(wanted)} expected line(s)")
        return 0
    print(f"{name}: at {root} the findings differ from {expect}:")
    for line in problems:
        print(("  ok:       " if line in wanted else "  found:    ") + line)
    for line in wanted:
        if line not in problems:
            print("  missed:   " + line)
    return 1
