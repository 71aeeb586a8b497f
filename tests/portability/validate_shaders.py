#!/usr/bin/env python3
"""Validates a --dump-shaders folder with Khronos' reference compiler, glslangValidator.

Every file the driver compiled must pass glslangValidator as the GLSL it declares (#version 450 core)
with no error and no warning; every file the driver refused (lesson 01's deliberate mistakes) must be
refused by glslangValidator too, or the two compilers disagree about it. The index (index.tsv, written
by the app) and the folder must list the same files, and there must be at least --min-files of them.
A message from glslangValidator names a source string ("ERROR: 2:14: ..."); the report turns it into
the file that string came from, using the index.

    validate_shaders.py DIR [--min-files N] [--glslang PATH] [--expect-failure REGEX]
Exit 0 when every file passes, 1 otherwise (each finding on its own line), 2 on a usage error.
--expect-failure checks the checker on a fixture: exit 0 only when the folder fails and the report
matches REGEX (a fixture that passed, or failed for another reason, exits 1).
"""
import argparse
import csv
import os
import re
import subprocess
import sys

STAGES = {"vert", "frag", "comp", "geom", "tesc", "tese"}
MESSAGE = re.compile(r"^(ERROR|WARNING): (\d+):(\d+): (.*)$")


def read_index(folder):
    path = os.path.join(folder, "index.tsv")
    if not os.path.isfile(path):
        return None, f"{path}: no index (was the run given --dump-shaders {folder}?)"
    expected = ["file", "stage", "driver", "program", "sources"]
    with open(path, newline="", encoding="utf-8") as f:
        header = f.readline().rstrip("\n").split("\t")
        if header != expected:
            return None, f"{path}: the header is {header}, not {expected}"
        rows = list(csv.DictReader(f, fieldnames=expected, delimiter="\t", quoting=csv.QUOTE_NONE))
    for row in rows:
        if None in row.values() or row.get("driver") not in ("compiled", "refused"):
            return None, f"{path}: malformed line for {row.get('file')!r}"
    return rows, None


def named(line, sources):
    """glslang's 'ERROR: 2:14: msg' with source string 2 replaced by its file name."""
    m = MESSAGE.match(line)
    if not m:
        return line
    kind, string, number, text = m.groups()
    index = int(string)
    name = sources[index] if index < len(sources) else f"<source string {string}>"
    return f"{kind}: {name}:{number}: {text}"


def validate(glslang, paths):
    """Every file in one glslangValidator run (a process per file costs more than the checks): given
    several files it prints each one's path on a line of its own, then that file's messages (given one,
    the path only when there are messages). Returns {path: [messages]}; a file it never got to (it
    stopped early) is missing from the result."""
    try:
        done = subprocess.run([glslang, *paths], capture_output=True, text=True)
    except FileNotFoundError:
        sys.exit(f"{glslang} is not installed (Debian package glslang-tools)")
    found, current = {}, None
    if len(paths) == 1:
        current = found.setdefault(paths[0], [])
    wanted = set(paths)
    for line in (done.stdout + done.stderr).splitlines():
        line = line.strip()
        if line in wanted:
            current = found.setdefault(line, [])
        elif line and current is not None:
            current.append(line)
    return done.returncode, found


def check(args, out):
    """Appends the report's lines to `out`; returns the exit code."""
    rows, problem = read_index(args.folder)
    if problem:
        out.append(f"FAIL: {problem}")
        return 1
    failures = []
    listed = {row["file"] for row in rows}
    on_disk = {f for f in os.listdir(args.folder) if f.rsplit(".", 1)[-1] in STAGES}
    for f in sorted(on_disk - listed):
        failures.append(f"{f}: in the folder but not in index.tsv")
    for f in sorted(listed - on_disk):
        failures.append(f"{f}: in index.tsv but not in the folder")
    if len(rows) < args.min_files:
        failures.append(f"only {len(rows)} shader files; expected at least {args.min_files}")

    compiled = refused = 0
    present = [row for row in rows if os.path.isfile(os.path.join(args.folder, row["file"]))]
    code, messages = validate(args.glslang, [os.path.join(args.folder, row["file"]) for row in present])
    for row in present:
        path = os.path.join(args.folder, row["file"])
        sources = row["sources"].split(",")
        if path not in messages:
            failures.append(f"{row['file']} ({row['program']}): glslangValidator stopped before it (exit {code})")
            continue
        errors = [l for l in messages[path] if l.startswith("ERROR")]
        problems = [l for l in messages[path] if l.startswith(("ERROR", "WARNING"))]
        if row["driver"] == "compiled":
            compiled += 1
            if problems:
                failures.append(f"{row['file']} ({row['program']}): glslangValidator reports")
                failures.extend("    " + named(l, sources) for l in problems)
        else:
            refused += 1
            if not errors:
                failures.append(f"{row['file']} ({row['program']}): the driver refused it but "
                                f"glslangValidator accepts it")

    for line in failures:
        out.append(("FAIL: " if not line.startswith("    ") else "") + line)
    if failures:
        return 1
    out.append(f"{compiled} shader files pass glslangValidator with no error and no warning; "
          f"{refused} the driver refused are refused by glslangValidator too")
    return 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("folder")
    ap.add_argument("--min-files", type=int, default=1)
    ap.add_argument("--glslang", default="glslangValidator")
    ap.add_argument("--expect-failure", metavar="REGEX")
    args = ap.parse_args()
    lines = []
    code = check(args, lines)
    print("\n".join(lines))
    if args.expect_failure is None:
        return code
    if code == 1 and re.search(args.expect_failure, "\n".join(lines), re.S):
        print(f"as expected: the check failed with {args.expect_failure!r}")
        return 0
    print(f"NOT as expected: exit {code}, and the report should match {args.expect_failure!r}")
    return 1


if __name__ == "__main__":
    sys.exit(main())
