#!/usr/bin/env bash
# The one rule for every file the app writes (docs/reliability.md), end to end through a lesson's own
# flags: a symbolic link (working or dangling), a device or a FIFO at a file the run would write is
# refused with a message, the run exits 1, and nothing outside the chosen folder changes; a link to
# another folder below --capture DIR is not followed by --all-steps; "-" writes the report to standard
# output.
#   run_write_rule_check.sh <fxlab-01-program-objects> <work dir>
set -uo pipefail
exe="$1" work="$2"
rm -rf "$work" && mkdir -p "$work/elsewhere"
status=0
fail() { echo "FAIL: $*"; status=1; }
run() {  # run <name> <args...>: exit code in $code, output in $work/<name>.log
  local name="$1"; shift
  "$exe" --headless --size 16x16 --frames 1 "$@" >"$work/$name.log" 2>&1
  code=$?
}
expect_refused() {  # expect_refused <name> <message fragment>
  [ "$code" = 1 ] || fail "$1: exit code $code, expected 1"
  grep -qF -- "$2" "$work/$1.log" || fail "$1: no \"$2\" in: $(tail -3 "$work/$1.log")"
}

# A capture whose final.png is a link to a file elsewhere: the file stays as it was.
echo keep >"$work/elsewhere/victim.png"
mkdir -p "$work/capture"
ln -s "$work/elsewhere/victim.png" "$work/capture/final.png"
run capture-link --capture "$work/capture"
expect_refused capture-link "final.png: is a symbolic link"
[ "$(cat "$work/elsewhere/victim.png")" = keep ] || fail "capture-link: the file the link points at was overwritten"
[ -L "$work/capture/final.png" ] || fail "capture-link: the link was replaced"

# A report at a dangling link: refused, the link stays, its target is not made.
ln -s "$work/elsewhere/made.json" "$work/dangling.json"
run report-dangling --report "$work/dangling.json"
expect_refused report-dangling "dangling.json: is a symbolic link"
[ -L "$work/dangling.json" ] || fail "report-dangling: the link was replaced by a file"
[ ! -e "$work/elsewhere/made.json" ] || fail "report-dangling: the link's target was created"

# A report at a working link: refused the same way (one rule), the target unchanged.
echo keep >"$work/elsewhere/real.json"
ln -s "$work/elsewhere/real.json" "$work/working.json"
run report-working --report "$work/working.json"
expect_refused report-working "working.json: is a symbolic link"
[ "$(cat "$work/elsewhere/real.json")" = keep ] || fail "report-working: written through the link"

# A device and a FIFO: refused, never written or waited for.
run report-device --report /dev/null
expect_refused report-device "/dev/null: is a character device"
mkfifo "$work/pipe.json"
run report-fifo --report "$work/pipe.json"
expect_refused report-fifo "pipe.json: is a FIFO"
[ -p "$work/pipe.json" ] || fail "report-fifo: the FIFO was replaced"

# --all-steps: DIR/step-1 a link to another folder is refused, and nothing is written there.
mkdir -p "$work/steps" "$work/elsewhere/steps"
ln -s "$work/elsewhere/steps" "$work/steps/step-1"
"$exe" --size 16x16 --frames 1 --all-steps --capture "$work/steps" >"$work/all-steps.log" 2>&1
code=$?
expect_refused all-steps "step-1: is a symbolic link"
[ -z "$(ls -A "$work/elsewhere/steps")" ] || fail "all-steps: files written through the step-1 link"

# "-" is standard output.
run report-stdout --report -
[ "$code" = 0 ] || fail "report-stdout: exit code $code"
grep -q '"glErrors": 0' "$work/report-stdout.log" || fail "report-stdout: no report on standard output"
[ ! -e ./- ] || fail "report-stdout: a file named - was written"

[ $status = 0 ] && echo "every write refused what it must and wrote what it may"
exit $status
