#!/usr/bin/env bash
# A lesson's frames in RenderDoc (label renderdoc): each step given runs headless with
# --renderdoc (RenderDoc's in-application API captures a frame), --report and --capture-float of the
# same moment, and check_capture.py opens the capture with RenderDoc's Python
# replay module and checks it (names as the pass table gives them, nothing unnamed, no work outside a
# debug group, the floats of the textures asked for against fxlab's own).
#   run_renderdoc_check.sh <lesson exe> <steps: 3,5> [check_capture.py flags] <work dir>
# Replay needs an X display: without one the script runs itself again under xvfb-run -a.
# Exits 77 (skipped) when RenderDoc is missing (Debian packages librenderdoc, librenderdoc-dev and
# python3-renderdoc; ./fxlab test installs them as root).
set -uo pipefail
exe="$1" steps="$2" work="${*: -1}"
flags=("${@:3:$#-3}")
here="$(cd "$(dirname "$0")" && pwd)"
name="$(basename "$exe")"
if [ ! -e /usr/lib/librenderdoc.so ] && ! /sbin/ldconfig -p 2>/dev/null | grep -q 'librenderdoc\.so '; then
  echo "SKIP: RenderDoc's library is not installed (Debian package librenderdoc)"; exit 77
fi
if ! /usr/bin/python3 -c 'import renderdoc' 2>/dev/null; then
  echo "SKIP: RenderDoc's Python module is not installed (Debian package python3-renderdoc)"; exit 77
fi
if [ -z "${DISPLAY:-}" ]; then
  if [ -n "${FXLAB_RENDERDOC_IN_XVFB:-}" ] || ! command -v xvfb-run >/dev/null; then
    echo "FAIL: no display for RenderDoc's replay, and xvfb-run is missing (Debian packages xvfb and xauth)"; exit 1
  fi
  FXLAB_RENDERDOC_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 640x480x24" "$0" "$@"
fi
rm -rf "$work" && mkdir -p "$work"
export FXLAB_CONFIG_DIR="$work/config"
# RenderDoc's own log and settings stay in the work folder, not the user's home.
export HOME="$work/home" && mkdir -p "$HOME"

status=0
for step in ${steps//,/ }; do
  run="$work/step-$step"
  # Frame 2 of 3: the last frame keeps every texture for the captures, so only a frame before it
  # shares pooled textures (the case whose names lied). The clock is paused from the start (space), so
  # frame 2 shows the moment the last frame's --capture-float holds.
  if ! "$exe" --headless --size 160x90 --frames 3 --renderdoc-frame 2 --press space@0 --step "$step" \
      --renderdoc "$run.rdc" --report "$run.json" --capture "$run" --capture-float >"$run.log" 2>&1; then
    if grep -q "built without RenderDoc's header" "$run.log"; then
      echo "SKIP: $(grep -o "fxlab was built without.*" "$run.log")"; exit 77
    fi
    echo "FAIL: $name step $step: the run with --renderdoc failed:"; tail -n 20 "$run.log"; status=1; continue
  fi
  /usr/bin/python3 "$here/check_capture.py" "$run.rdc" "$run.json" "$run" "${flags[@]}" || status=1
done
exit "$status"
