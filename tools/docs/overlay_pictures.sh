#!/usr/bin/env bash
# Makes every picture of the overlay that README, docs/ and the lessons' text show, from today's code:
# each lesson runs headless with --overlay in a 1280x720 window (the projector the layout is made
# for), and its final.png becomes docs/images/<name>.png. docs/images/overlay-pictures.tsv lists each
# picture with the run that made it, the picture's sha256 and the sha256 of the layout's code
# (common/ui/panel_layout.*) it was made with; the unit test overlay-pictures
# (tests/docs/check_overlay_pictures.py) fails when a shown overlay picture is missing from the list,
# differs from it, or was made with another layout.
#   tools/docs/overlay_pictures.sh [build dir]      (default: build)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$root/build}"
images="$root/docs/images"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
manifest="$work/overlay-pictures.tsv"
layout_hash="$(cat "$root/common/ui/panel_layout.hpp" "$root/common/ui/panel_layout.cpp" | sha256sum | cut -d' ' -f1)"
printf 'picture\tlayout_sha256\tpicture_sha256\trun\n' >"$manifest"

# picture <name> <lesson executable> <arguments...>
picture() {
  local name="$1" exe="$2"
  shift 2
  local out="$work/$name"
  "$build/lessons/$exe" --headless --overlay --size 1280x720 --frames 12 --capture "$out" "$@" \
    >"$out.log" 2>&1 || { echo "overlay_pictures: $exe $* failed:" >&2; cat "$out.log" >&2; exit 1; }
  cp "$out/final.png" "$work/$name.png"
  printf '%s.png\t%s\t%s\t%s\n' "$name" "$layout_hash" "$(sha256sum "$work/$name.png" | cut -d' ' -f1)" \
    "$exe $*" >>"$manifest"
}

picture classroom-layout fxlab-02-skinned-shadows --step 1
picture lesson03-overlay-step-2 fxlab-03-fbo-pipeline --step 2
picture lesson03-overlay-step-5 fxlab-03-fbo-pipeline --step 5 --inspect scene.color
picture lesson04-overlay fxlab-04-colour-matrix --step 4
picture lesson06-japanese fxlab-06-bloom --step 5 --lang ja
picture bloom-chain-strip fxlab-06-bloom --step 3 --inspect "bloom.down[0]"
picture lesson10-japanese-title fxlab-10-deferred-shading --step 4 --lang ja
picture overlay-06-ja fxlab-06-bloom --step 3 --lang ja
picture overlay-10-ja fxlab-10-deferred-shading --step 6 --lang ja

# Only when every picture was made: nothing half-replaced.
for f in "$work"/*.png; do cp "$f" "$images/"; done
cp "$manifest" "$images/overlay-pictures.tsv"
echo "overlay_pictures: $(($(wc -l <"$manifest") - 1)) pictures in $images"
