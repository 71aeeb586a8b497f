#!/usr/bin/env bash
# `./fxlab list` on a busy machine: run 20 times while CPU burners (started here, ended here by their
# PIDs) keep every core busy, it exits 0 each time and lists every lesson with its title and steps. The
# old `--help | head -1` under `set -o pipefail` killed the lesson with SIGPIPE when head closed the pipe
# before the lesson had written the rest, and `set -e` ended the list there (exit 141, a cut list).
#   run_fxlab_list_check.sh <fxlab script> <build dir> <lessons expected> <work dir>
set -uo pipefail
fxlab="$1" build="$2" expected="$3" work="$4"
rm -rf "$work" && mkdir -p "$work"
burners=()
stop_burners() {
  local pid
  for pid in "${burners[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${burners[@]}"; do wait "$pid" 2>/dev/null; done
  burners=()
}
trap stop_burners EXIT
cores="$(nproc 2>/dev/null || echo 2)"
for _ in $(seq 1 $((cores * 2))); do
  bash -c 'while :; do :; done' &
  burners+=($!)
done
status=0
for run in $(seq 1 20); do
  FXLAB_BUILD_DIR="$build" "$fxlab" list >"$work/list-$run.txt" 2>"$work/list-$run.log"
  code=$?
  lessons="$(grep -cE '^  [0-9][0-9]  .*[^ ] +[1-9][0-9]* steps   \./fxlab run [0-9][0-9]$' "$work/list-$run.txt")"
  if [ "$code" -ne 0 ] || [ "$lessons" -ne "$expected" ]; then
    echo "FAIL: run $run: exit code $code, $lessons of $expected lessons listed:"
    cat "$work/list-$run.txt" "$work/list-$run.log"
    status=1
  fi
done
stop_burners
[ "$status" -eq 0 ] && echo "20 runs under load ($((cores * 2)) CPU burners): $expected lessons every time"
exit "$status"
