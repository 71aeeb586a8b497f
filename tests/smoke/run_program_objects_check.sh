#!/usr/bin/env bash
# Lesson 01, end to end: step 1 shows what an unchecked broken program does (the sphere drawn with it
# is gone, and the only trace is GL errors, counted as expected), step 2 shows the check catching the
# same mistake (its log, no GL error, the sphere drawn by the last good program), and steps 1, 2 and 5
# give three different pictures. With nothing broken, the unchecked and checked programs draw the
# same picture. No step but step 2 shows a shader error.
#   run_program_objects_check.sh <fxlab-01-program-objects exe> <work dir>
set -uo pipefail
exe="$1" work="$2"
rm -rf "$work" && mkdir -p "$work"
run() {  # run <name> <args...>
  local name="$1"; shift
  "$exe" --headless --size 160x90 --frames 2 --capture "$work/$name" --report "$work/$name.json" "$@" \
    >"$work/$name.log" 2>&1 || { echo "FAIL: $name exited with an error:"; cat "$work/$name.log"; exit 1; }
}
for step in 1 2 3 4 5; do run "step-$step" --step "$step"; done
run step-1-none --step 1 --param broken_shader=none
run step-2-none --step 2 --param broken_shader=none
PYTHONPATH="$(dirname "$0")" python3 - "$work" <<'PY'
import sys
from report import load
work = sys.argv[1]
def report(name):
    return load(f"{work}/{name}.json")
def final(name):
    with open(f"{work}/{name}/final.png", "rb") as f:
        return f.read()
failures = []
r1, r2 = report("step-1"), report("step-2")
if r1["facts"].get("expectErrorsInStep") is not True or r1["glExpectedErrors"] <= 0:
    failures.append(f"step 1: the unchecked broken program should raise (expected) GL errors: "
                    f"{r1['glExpectedErrors']} expected, expectErrorsInStep {r1['facts'].get('expectErrorsInStep')}")
if r1["shaderErrors"]:
    failures.append(f"step 1: nothing checks, so no shader error can be known: {r1['shaderErrors']}")
if len(r2["shaderErrors"]) != 1 or "broken_syntax.frag" not in r2["shaderErrors"][0]:
    failures.append(f"step 2: the check should report the broken file's log once: {r2['shaderErrors']}")
if r2["glExpectedErrors"] != 0:
    failures.append(f"step 2: the checked program raises no GL error: {r2['glExpectedErrors']}")
for name in ("step-1", "step-2", "step-3", "step-4", "step-5", "step-1-none", "step-2-none"):
    r = report(name)
    if r["glErrors"] != 0:
        failures.append(f"{name}: {r['glErrors']} unexpected GL errors ({r['lastGlError']})")
    if name not in ("step-2",) and r["shaderErrors"]:
        failures.append(f"{name}: a shader error where nothing is broken on purpose: {r['shaderErrors']}")
for name in ("step-1-none", "step-2-none"):
    if report(name)["glExpectedErrors"] != 0:
        failures.append(f"{name}: GL errors with nothing broken")
pictures = {n: final(n) for n in ("step-1", "step-2", "step-5")}
for a, b in (("step-1", "step-2"), ("step-1", "step-5"), ("step-2", "step-5")):
    if pictures[a] == pictures[b]:
        failures.append(f"{a} and {b} give the same picture")
if final("step-1-none") != final("step-2-none"):
    failures.append("with nothing broken, the unchecked and checked programs should draw the same picture")
if final("step-1-none") == pictures["step-1"]:
    failures.append("step 1: the broken program changes nothing in the picture")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY
status=$?
[ "$status" -eq 0 ] && echo "lesson 01 check passed"
exit "$status"
