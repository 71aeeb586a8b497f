#!/usr/bin/env python3
"""Reading a lesson's report (--report FILE, docs/captures.md) in the smoke checks: one reader
for every script instead of one each.

As a command, for shell scripts:
  report.py fact REPORT NAME              a fact's value (facts[NAME]), or "absent"
  report.py field REPORT NAME             a top-level field (glErrors, glExpectedErrors, ...)
  report.py pass REPORT PASS FIELD        a field of the pass named PASS, or "absent"
  report.py check REPORT EXPRESSION       exit 0 when the Python EXPRESSION holds; it sees r (the report),
                                          passes and params (by name), facts, and finite (no NaN or
                                          infinity in any texture's statistics); on failure it prints the
                                          expression and every pass's status and reason
As a module (PYTHONPATH=tests/smoke): load(path) and the helpers below. Values print as Python writes
them (True, False, numbers, strings as they are).
"""
import json
import sys


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def passes(report):
    """{pass name: pass} of a report."""
    return {p["name"]: p for p in report.get("passes", [])}


def params(report):
    """{parameter name: parameter} of a report (value, source, ...)."""
    return {p["name"]: p for p in report.get("params", [])}


def facts(report):
    return report.get("facts", {})


def texture_stats(report):
    """Every channel's statistics of every texture the report lists."""
    return [s for t in report.get("textures", []) for s in t.get("stats", [])]


def non_finite(report):
    """How many NaN and infinite values the report's textures hold."""
    return sum(s["nan"] + s["inf"] for s in texture_stats(report))


def finite(report):
    return non_finite(report) == 0


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    command, path, rest = argv[1], argv[2], argv[3:]
    report = load(path)
    if command == "fact" and len(rest) == 1:
        print(facts(report).get(rest[0], "absent"))
    elif command == "field" and len(rest) == 1:
        print(report[rest[0]])
    elif command == "pass" and len(rest) == 2:
        found = passes(report).get(rest[0])
        print(found[rest[1]] if found is not None else "absent")
    elif command == "check" and len(rest) == 1:
        scope = {"r": report, "passes": passes(report), "params": params(report), "facts": facts(report),
                 "finite": finite(report)}
        if eval(rest[0], {}, scope):
            return 0
        print(f"{path}: does not hold: {rest[0]}")
        print(json.dumps([(p["name"], p.get("status"), p.get("reason")) for p in report.get("passes", [])], indent=1))
        return 1
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
