#!/usr/bin/env bash
# `fxlab check --all --class` of the Windows build under Wine, for a class kept in a Japanese folder
# (クラス) with two students: 解答 handed in every exercise's solution and must pass all of them,
# 初期 handed in every starter unchanged and must fail all of them. Each check runs in the
# watchdog's child (child_watchdog_win.cpp), which gets the paths as UTF-8 through CreateProcessW.
#   run_windows_exercises.sh <wine_run.sh> <fxlab-exercise.exe> <source root> <work dir>
set -uo pipefail
wine="$1" tool="$2" root="$3" work="$4"
rm -rf "$work" && mkdir -p "$work"
class="$work/クラス"
count=0
for dir in "$root"/exercises/[0-9][0-9]-[0-9]*/; do
  id="$(basename "$dir")"
  file="$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["file"])' "$dir/exercise.json")"
  mkdir -p "$class/解答/$id" "$class/初期/$id"
  cp "$root/exercises/solutions/$id/$file" "$class/解答/$id/$file"
  cp "$dir/$file" "$class/初期/$id/$file"
  count=$((count + 1))
done
"$wine" "$tool" check --all --json --class "$class" >"$work/class.json" 2>"$work/class.log"
code=$?
python3 - "$work/class.json" "$count" "$code" <<'PY'
import json, sys
report = json.load(open(sys.argv[1], encoding="utf-8"))
count, code = int(sys.argv[2]), int(sys.argv[3])
students = {s["student"]: s for s in report["students"]}
failures = []
if code != 1: failures.append(f"a class with a failing student exits 1, got {code}")
if sorted(students) != sorted(["解答", "初期"]): failures.append(f"the students' Japanese names: {sorted(students)}")
solved, started = students.get("解答", {}), students.get("初期", {})
if solved.get("total") != count or solved.get("passed") != count:
    failures.append(f"every solution passes: {solved.get('passed')}/{solved.get('total')} of {count}: "
                    + "; ".join(f"{v['id']}: {v['message']}" for v in solved.get("exercises", []) if not v["passed"]))
if started.get("total") != count or started.get("passed") != 0:
    failures.append(f"every starter fails: {started.get('passed')} passed of {started.get('total')}")
for v in started.get("exercises", []):
    if "did not finish" in v.get("message", "") or "could not start" in v.get("message", ""):
        failures.append(f"{v['id']}: the check itself failed: {v['message']}")
for f in failures: print("FAIL:", f)
print(f"windows exercises: {count} solutions and {count} starters, {len(failures)} failures")
sys.exit(1 if failures else 0)
PY
