#!/usr/bin/env bash
# Makes docs/images/renderdoc-06-bloom-down-1.png: lesson 06 step 5 captured headless with --renderdoc,
# opened in qrenderdoc (Debian's 1.24) on an Xvfb screen of 1600x1000, the Texture Viewer on the pass
# "bloom down 1" with its Inputs tab (source = bloom.down[0]). The clicks are at the places qrenderdoc
# 1.24 puts its widgets on that screen with no window manager; another version may need others.
#   tools/debugging/qrenderdoc_screenshot.sh <build dir> <out.png>
set -euo pipefail
build="$1" out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'kill "${viewer:-}" "${xvfb:-}" 2>/dev/null; rm -rf "$work"' EXIT
export HOME="$work/home" && mkdir -p "$HOME"  # qrenderdoc's first-start questions, asked in a scratch home
"$build/lessons/fxlab-06-bloom" --headless --size 640x360 --frames 3 --step 5 --renderdoc "$work/06.rdc" \
  --capture "$work/out" >"$work/run.log" 2>&1
Xvfb :77 -screen 0 1600x1000x24 >/dev/null 2>&1 & xvfb=$!
export DISPLAY=:77
sleep 2
qrenderdoc "$work/06.rdc" >"$work/qrenderdoc.log" 2>&1 & viewer=$!
sleep 20
xdotool mousemove 332 517 click 1 && sleep 1 && xdotool mousemove 836 555 click 1  # analytics: none, OK
sleep 8
xdotool windowsize "$(xdotool search --name ' - RenderDoc v' | head -1)" 1600 1000 && sleep 2
xdotool mousemove 599 232 click 1 && sleep 1   # the Texture Viewer tab
xdotool mousemove 157 422 click 1 && sleep 4   # the event list's "bloom down 1"
xdotool mousemove 645 298 click 1 && sleep 1   # Fit
xdotool mousemove 1355 365 click 1 && sleep 3  # the Inputs tab
python3 "$here/x_screenshot.py" "$out"
