#!/usr/bin/env bash
# fxlab-handout on bad input: a step whose capture fails, an output folder that has files in it (with
# and without --force), a link or a file where the folder should go. Each gives a clear message and
# leaves nothing half-written: no folder at the target, no hidden ".partial" sibling, and whatever was
# there before untouched. The lessons here are stand-ins (shell scripts named like lessons), so no GL.
#   run_handout_errors.sh <fxlab-handout> <work dir>
set -uo pipefail
tool="$1" work="$2"
rm -rf "$work" && mkdir -p "$work/bin"
status=0
fail() { echo "FAIL: $*"; status=1; }

# A lesson whose second step fails to capture, as --all-steps reports it.
broken="$work/bin/fxlab-98-broken"
cat > "$broken" <<'SH'
#!/bin/sh
echo "fxlab-98-broken: step 2 exited with code 1" >&2
echo "fxlab-98-broken: 1 of 3 steps captured" >&2
exit 1
SH
chmod +x "$broken"

# Nothing there before: nothing there after, and the message quotes the capture's own words.
out="$work/out/handout"
if "$tool" --out "$out" "$broken" >"$work/broken.log" 2>&1; then fail "a failed capture was reported as success"; fi
grep -q "98-broken: capturing the steps failed (exit code 1); the end of its output:" "$work/broken.log" ||
  fail "no message naming the failed capture: $(cat "$work/broken.log")"
grep -q "step 2 exited with code 1" "$work/broken.log" || fail "the capture's log is not quoted"
grep -q "nothing was written at $out" "$work/broken.log" || fail "does not say that nothing was written"
[ -e "$out" ] && fail "a half-written $out was left"
leftovers=$(find "$work/out" -mindepth 1 -maxdepth 1 | wc -l)
[ "$leftovers" -eq 0 ] && echo "ok: a failed capture leaves nothing" || fail "left behind: $(ls -A "$work/out")"

# A folder with files in it is refused without --force, and kept as it was.
mkdir -p "$work/full" && echo "a teacher's notes" > "$work/full/notes.txt"
if "$tool" --out "$work/full" "$broken" >"$work/full.log" 2>&1; then fail "a full folder was accepted"; fi
grep -q "$work/full: a folder with files in it; --force replaces it" "$work/full.log" ||
  fail "no message about the full folder: $(cat "$work/full.log")"
grep -q "capturing" "$work/full.log" && fail "it captured before refusing the folder"
# With --force, a folder fxlab did not write (no marker: a home folder) is refused before anything
# runs, and kept whole (issue 40: it was moved aside and removed).
mkdir -p "$work/full/.ssh" && echo "a key" > "$work/full/.ssh/id_rsa"
if "$tool" --force --out "$work/full" "$broken" >"$work/notours.log" 2>&1; then fail "--force took a folder fxlab did not write"; fi
grep -q "$work/full: a folder with files in it that fxlab did not write" "$work/notours.log" ||
  fail "no message saying why the folder is kept: $(cat "$work/notours.log")"
grep -q "capturing" "$work/notours.log" && fail "it captured before refusing the folder"
[ "$(cat "$work/full/.ssh/id_rsa" 2>/dev/null)" = "a key" ] && echo "ok: --force keeps a folder fxlab did not write" ||
  fail "--force lost a folder fxlab did not write"
# With --force, a run that fails still keeps an earlier handout: it is replaced only by a finished one.
echo "an earlier handout" > "$work/full/.fxlab-handout"
"$tool" --force --out "$work/full" "$broken" >"$work/force.log" 2>&1 && fail "a failed capture succeeded with --force"
grep -q "capturing the steps failed" "$work/force.log" || fail "--force on an earlier handout did not run: $(cat "$work/force.log")"
[ "$(cat "$work/full/notes.txt" 2>/dev/null)" = "a teacher's notes" ] && echo "ok: --force keeps the old folder when the run fails" ||
  fail "--force lost the old folder on a failed run"
[ "$(find "$work" -maxdepth 1 -name '.full.*' | wc -l)" -eq 0 ] || fail "a hidden sibling of full/ was left"

# A symbolic link, a file and a FIFO where the folder should go: refused, even with --force.
mkdir -p "$work/real" && ln -s "$work/real" "$work/link"
echo keep > "$work/file"
mkfifo "$work/fifo"
for target in link file fifo; do
  if "$tool" --force --out "$work/$target" "$broken" >"$work/$target.log" 2>&1; then fail "$target accepted"; fi
  grep -q "$work/$target: " "$work/$target.log" || fail "$target: no message naming it: $(cat "$work/$target.log")"
done
grep -q "symbolic link" "$work/link.log" || fail "the link is not called a link"
[ -L "$work/link" ] && [ -z "$(ls -A "$work/real")" ] || fail "the link or its folder changed"
[ "$(cat "$work/file")" = keep ] || fail "the file changed"
[ -p "$work/fifo" ] || fail "the FIFO was replaced"

# Not a lesson at all.
"$tool" --out "$work/x" /bin/true >"$work/true.log" 2>&1 && fail "/bin/true was taken for a lesson"
grep -q "/bin/true: not a lesson executable (fxlab-NN-name)" "$work/true.log" || fail "no message for /bin/true"

[ "$status" -eq 0 ] && echo "ok: every refusal named its reason and left nothing behind"
exit "$status"
