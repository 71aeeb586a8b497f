#!/usr/bin/env bash
# A lesson in a real GLFW window with the overlay on for a few frames, and the same frames with the
# overlay off. The checker gets both runs' captures (the app's own screenshot of the last frame: the
# back buffer read after the overlay drew) and reports, and a path for a difference image: it checks
# that the overlay is where it should be and that neither run reported a GL error or fell back to
# headless.
#   run_window_test.sh <lesson exe> <checker exe> <work dir> [lesson flags, default --size 800x600 --step 1]
# Without a display it runs itself again under xvfb-run -a (a free display number each time).
set -uo pipefail
exe="$1" checker="$2" work="$3"
shift 3
lessonFlags=("$@")
[ "${#lessonFlags[@]}" -eq 0 ] && lessonFlags=(--size 800x600 --step 1)
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  if [ -n "${FXLAB_WINDOW_TEST_IN_XVFB:-}" ] || ! command -v xvfb-run >/dev/null; then
    echo "FAIL: no display, and xvfb-run is missing (Debian packages xvfb and xauth)"; exit 1
  fi
  FXLAB_WINDOW_TEST_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$exe" "$checker" "$work" "${lessonFlags[@]}"
fi
name="$(basename "$exe")"
rm -rf "$work" && mkdir -p "$work"
export FXLAB_CONFIG_DIR="$work/config"  # never the teacher's ui.json
status=0
for mode in with without; do
  flags=()
  # Without the overlay the picture fills the whole window (no 16:9 bars), so the overlay's region is
  # compared with the lesson's picture, not with the dark ground around a letterboxed one.
  [ "$mode" = without ] && flags=(--no-overlay --aspect free)
  if ! "$exe" --frames 6 "${lessonFlags[@]}" "${flags[@]}" --capture "$work/$mode" \
       --report "$work/$mode/report.json" >"$work/$mode.log" 2>&1; then
    echo "FAIL: $name ($mode overlay) exited with an error:"; cat "$work/$mode.log"; status=1
  fi
done
[ "$status" -eq 0 ] || exit 1
if ! "$checker" "$work/with" "$work/without" "$work/difference.png"; then
  echo "FAIL: $name: the window screenshots are not as expected (logs: $work/*.log)"; exit 1
fi
echo "$name ${lessonFlags[*]}: the overlay draws in a GLFW window as expected, no GL errors"
