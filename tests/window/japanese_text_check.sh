#!/usr/bin/env bash
# Checks lesson 06 run in a window with --lang ja (run_window_test.sh's checker): the overlay is on the
# screenshot as usual (fx_window_check, named by FXLAB_WINDOW_CHECK), the steps' text came from
# lesson.ja.md, and the overlay's font atlas got every Japanese glyph the text uses from the IPA font
# (none missing: a missing glyph is drawn as '?').
#   japanese_text_check.sh <run with overlay> <run without> <difference.png>
set -uo pipefail
with="$1" without="$2" difference="$3"
log="$with.log"  # run_window_test.sh writes <work>/with.log beside <work>/with/
"$FXLAB_WINDOW_CHECK" "$with" "$without" "$difference" || exit 1
if ! grep -q 'lesson text: .*lessons/06_bloom/lesson\.ja\.md translates 6 of 6 steps' "$log"; then
  echo "FAIL: the log does not say that the step text came from lessons/06_bloom/lesson.ja.md:"; cat "$log"; exit 1
fi
line=$(grep -o 'overlay font: [0-9]* glyphs of the lesson text merged from [^ ]* ([0-9]* not in the font)' "$log" | tail -1)
loaded=$(sed -n 's/overlay font: \([0-9]*\) glyphs.*/\1/p' <<<"$line")
missing=$(sed -n 's/.*(\([0-9]*\) not in the font)/\1/p' <<<"$line")
if [ -z "$loaded" ] || [ "$loaded" -lt 200 ] || [ "$missing" != 0 ]; then
  echo "FAIL: expected at least 200 Japanese glyphs merged into the overlay's font and none missing; the log says: ${line:-nothing}"
  cat "$log"; exit 1
fi
echo "the step text came from lesson.ja.md; $loaded glyphs merged into the overlay's font, none missing"
