#!/usr/bin/env bash
# Exactly one sRGB encode a frame (Shader effects §3.4, hard case 8), counted on the pictures by
# count_encodes.py: the sky's linear background from the scene file against what the scene target and
# the final picture hold. Lesson 06 step 6, the chapter's whole frame (no glow, identity matrix, so the
# sky reaches the output transform as it left the scene): encoded 0 times in the scene pass, once in the
# frame. Lesson 03 step 4 (the scene shader still encodes, one pass to the window): 1 and 1; step 5's fix
# 0 and 1; and step 5's washed-out half, the double gamma it shows: 2, so the count is seen to fail.
#   run_one_encode_check.sh <lesson 06 exe> <lesson 03 exe> <work dir>
set -uo pipefail
exe06="$1" exe03="$2" work="$3"
here="$(cd "$(dirname "$0")" && pwd)"
scenes="$(cd "$here/../../res/scenes" && pwd)"
rm -rf "$work" && mkdir -p "$work"
status=0
check() {  # check NAME EXPECTED SCENE EXE ARGS...
  local name="$1" expected="$2" scene="$3" exe="$4"
  shift 4
  if ! "$exe" --headless --size 160x90 --frames 1 --capture "$work/$name" --capture-float "$@" \
      >"$work/$name.log" 2>&1; then
    echo "FAIL: $name exited with an error:"; cat "$work/$name.log"; status=1; return
  fi
  local got
  got="$(PYTHONPATH="$here" python3 "$here/count_encodes.py" "$work/$name" "$scenes/$scene" 2>&1)"
  if [ "$got" != "$expected" ]; then
    echo "FAIL: $name: encodes (scene pass, frame) $got, expected $expected"; status=1
  else
    echo "$name: encodes (scene pass, frame) $got"
  fi
}
check 06-whole-frame "0 1" 06_bloom.json "$exe06" --step 6 --param intensity=0 --param frame_matrix=identity
check 03-step-4 "1 1" 03_fbo_pipeline.json "$exe03" --step 4
check 03-step-5-fix "0 1" 03_fbo_pipeline.json "$exe03" --step 5 --param washout_split=0
check 03-step-5-double-gamma "0 2" 03_fbo_pipeline.json "$exe03" --step 5 --param washout_split=1
exit $status
