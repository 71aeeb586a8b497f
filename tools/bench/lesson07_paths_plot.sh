#!/usr/bin/env bash
# Lesson 07's bench as a picture: frame time against particle count for the three simulation paths
# (one draw per particle, one instanced draw, GPU simulation with an indirect draw), log-log, from the
# `workload` rows of the bench.csv that `./fxlab bench 07` writes. Their value reads "<path> <count>";
# this turns them into a table of count, path and time for fx_series_plot, whose y ticks also read in
# full-screen copies of the same run.
#   tools/bench/lesson07_paths_plot.sh <fx_series_plot> <bench.csv> <out.png>
set -euo pipefail
plot="$1" bench="$2" png="$3"
table="$(mktemp)"
trap 'rm -f "$table" "$table.info"' EXIT
# The fields before `value` hold no commas, and a workload value is one quoted word and a number.
awk -F, -v info="$table.info" '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; print "particles,path,ms"; next }
  $col["knob"] == "workload" {
    value = $col["value"]; gsub(/"/, "", value)
    if (split(value, part, " ") != 2) next  # "params": the reference row
    name = part[1] == "objects" ? "one draw per particle" : part[1] == "instanced" ? "one instanced draw" \
         : part[1] == "gpu" ? "GPU sim, indirect draw" : part[1]
    print part[2] ",\"" name "\"," $col["median_ms"]
    copy = $col["copy_ms"]; size = $col["width"] "x" $col["height"]
  }
  END { print copy > info; print size > info }
' "$bench" >"$table"
{ read -r copy; read -r size; } <"$table.info"
if [ -z "$copy" ]; then
  echo "$bench: no workload rows (run ./fxlab bench 07 --knob workload)" >&2
  exit 1
fi
"$plot" "$table" "$png" --x particles --series path --y ms --copy-ms "$copy" \
  --title "Lesson 07 at $size: frame time against particles alive, three paths" --x-label "particles alive" \
  --y-label "ms" --legend "path"
