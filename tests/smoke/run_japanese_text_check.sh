#!/usr/bin/env bash
# A lesson's Japanese text (lesson.ja.md) headless with the overlay on: every step of the lesson is
# translated, and the overlay's font got every glyph the text uses from the IPA font (a glyph not in it
# would be drawn as '?'). The window test of lesson 06 checks the same on screen.
#   run_japanese_text_check.sh <lesson executable>
set -uo pipefail
exe="$1"
log=$("$exe" --headless --overlay --lang ja --frames 1 --size 320x180 2>&1) || { echo "FAIL: the run failed:"; echo "$log"; exit 1; }
text=$(grep -o 'lesson text: .*lesson\.ja\.md translates [0-9]* of [0-9]* steps' <<<"$log" | tail -1)
read -r done all < <(sed -n 's/.*translates \([0-9]*\) of \([0-9]*\) steps/\1 \2/p' <<<"$text")
if [ -z "${done:-}" ] || [ "$done" != "$all" ]; then
  echo "FAIL: expected lesson.ja.md to translate every step; the log says: ${text:-nothing}"; echo "$log"; exit 1
fi
font=$(grep -o 'overlay font: [0-9]* glyphs of the lesson text merged from [^ ]* ([0-9]* not in the font)' <<<"$log" | tail -1)
missing=$(sed -n 's/.*(\([0-9]*\) not in the font)/\1/p' <<<"$font")
if [ "${missing:-x}" != 0 ]; then
  echo "FAIL: every glyph of the Japanese text must be in the overlay's font; the log says: ${font:-nothing}"; exit 1
fi
echo "$text; $font"
