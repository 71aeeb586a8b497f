#!/usr/bin/env bash
# Lesson 06 in a real GLFW window with the inspector opened on the bloom chain (--inspect
# bloom.down[0]), and the same frames with the overlay hidden. fx_bloom_inspector_check then checks
# that every level of both chains was made and is finite, that the inspector is on the screenshot,
# and that neither run reported a GL error or fell back to headless.
#   run_bloom_window_test.sh <lesson exe> <checker exe> <work dir>
# Without a display it runs itself again under xvfb-run -a (a free display number each time).
set -uo pipefail
exe="$1" checker="$2" work="$3"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  if [ -n "${FXLAB_WINDOW_TEST_IN_XVFB:-}" ] || ! command -v xvfb-run >/dev/null; then
    echo "FAIL: no display, and xvfb-run is missing (Debian packages xvfb and xauth)"; exit 1
  fi
  FXLAB_WINDOW_TEST_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi
name="$(basename "$exe")"
rm -rf "$work" && mkdir -p "$work"
status=0
for mode in with without; do
  flags=()
  [ "$mode" = without ] && flags=(--no-overlay)
  if ! "$exe" --size 1200x800 --frames 6 --step 4 --inspect 'bloom.down[0]' "${flags[@]}" --capture "$work/$mode" \
       --report "$work/$mode/report.json" >"$work/$mode.log" 2>&1; then
    echo "FAIL: $name ($mode overlay) exited with an error:"; cat "$work/$mode.log"; status=1
  fi
done
[ "$status" -eq 0 ] || exit 1
if ! "$checker" "$work/with" "$work/without"; then
  echo "FAIL: $name: the inspector on the bloom chain is not as expected (logs: $work/*.log)"; exit 1
fi
echo "$name: the inspector shows the bloom chain in a GLFW window, no GL errors"
