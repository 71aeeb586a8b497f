#!/usr/bin/env python3
"""A teacher's grading run: `fxlab-exercise check --all --json --class DIR` over a class of two
students, one who handed in every solution and one who handed in a starter and a scene past the
limits. The JSON says who passed what, the failing verdicts carry their measure and hint, the exit
status is 1, and no student's progress.json is written; `check --all --json` for the passing student
alone exits 0 and records the progress."""
import json
import os
import shutil
import subprocess
import sys
import tempfile

tool, root = sys.argv[1], sys.argv[2]
exercises = sorted(d for d in os.listdir(os.path.join(root, "exercises")) if d[:2].isdigit())
failures = []


def expect(condition, what):
    if not condition:
        failures.append(what)


def starter_name(exercise):
    with open(os.path.join(root, "exercises", exercise, "exercise.json")) as f:
        return json.load(f)["file"]


with tempfile.TemporaryDirectory(prefix="fx_class_") as klass:
    for exercise in exercises:
        name = starter_name(exercise)
        os.makedirs(os.path.join(klass, "alice", exercise))
        shutil.copy(os.path.join(root, "exercises", "solutions", exercise, name), os.path.join(klass, "alice", exercise, name))
    os.makedirs(os.path.join(klass, "bob", "05-1"))
    shutil.copy(os.path.join(root, "exercises", "05-1", starter_name("05-1")), os.path.join(klass, "bob", "05-1"))
    os.makedirs(os.path.join(klass, "bob", "07-2"))
    shutil.copy(os.path.join(root, "exercises", "solutions", "07-2", "wrong-past-limits.json"),
                os.path.join(klass, "bob", "07-2", starter_name("07-2")))

    # Issue 40: a student folder whose name is not UTF-8 aborted the grading (type_error.316), and a
    # one-line #include of the solution, or a link to it, passed.
    odd = os.fsdecode(b"st\xffudent")
    os.makedirs(os.path.join(klass, odd, "05-1"))
    solution = os.path.join(root, "exercises", "solutions", "05-1", starter_name("05-1"))
    with open(os.path.join(klass, odd, "05-1", starter_name("05-1")), "w") as f:
        f.write(f'#include "{solution}"\n')
    os.makedirs(os.path.join(klass, odd, "09-1"))
    os.symlink(os.path.join(root, "exercises", "solutions", "09-1", starter_name("09-1")),
               os.path.join(klass, odd, "09-1", starter_name("09-1")))

    run = subprocess.run([tool, "check", "--all", "--json", "--class", klass], capture_output=True, text=True,
                         errors="replace", timeout=600)
    expect(run.returncode == 1, f"a class with a failing student exits 1, got {run.returncode}: {run.stderr}")
    report = json.loads(run.stdout)
    students = {s["student"]: s for s in report["students"]}
    expect(sorted(students) == ["alice", "bob", "st\\xffudent"], f"every student graded: {sorted(students)}")
    if "st\\xffudent" in students:
        cheats = {v["id"]: v for v in students["st\\xffudent"]["exercises"]}
        expect(students["st\\xffudent"]["passed"] == 0, "an #include of the solution or a link to it passes nothing")
        expect("inside the exercises' answers" in cheats["05-1"]["message"], f"05-1's #include: {cheats['05-1']}")
        expect("one of the exercises' answers" in cheats["09-1"]["message"], f"09-1's link: {cheats['09-1']}")
    alice, bob = students["alice"], students["bob"]
    expect(alice["total"] == len(exercises) and alice["passed"] == len(exercises),
           f"alice passes all {len(exercises)}: {alice['passed']}/{alice['total']}")
    expect(bob["passed"] == 0, f"bob passes nothing: {bob['passed']}")
    verdicts = {v["id"]: v for v in bob["exercises"]}
    blur = verdicts["05-1"]
    expect(not blur["passed"] and blur["nonFiniteTexels"] > 0 and "0 / 0" in blur["hint"], f"05-1's NaN and hint: {blur}")
    expect(blur["measured"] is None, "an infinite measure is null in JSON")
    scene = verdicts["07-2"]
    expect(not scene["passed"] and "emitters[0].rate" in scene["message"] and scene["hint"], f"07-2 past the limits: {scene}")
    missing = verdicts["01-1"]
    expect(not missing["passed"] and "no such file" in missing["message"], f"a missing file: {missing}")
    for student in ("alice", "bob"):
        expect(not os.path.exists(os.path.join(klass, student, "progress.json")), f"{student}'s progress left alone")

    env = dict(os.environ, FXLAB_EXERCISES=os.path.join(klass, "alice"))
    one = subprocess.run([tool, "check", "--all", "--json"], capture_output=True, text=True, env=env, timeout=600)
    expect(one.returncode == 0, f"one passing student exits 0, got {one.returncode}")
    expect(json.loads(one.stdout)["passed"] == len(exercises), "alice alone passes everything")
    expect(os.path.exists(os.path.join(klass, "alice", "progress.json")), "a student's own run records progress")

for failure in failures:
    print("FAIL:", failure)
print(f"exercise class test: {len(failures)} failures over {len(exercises)} exercises")
sys.exit(1 if failures else 0)
