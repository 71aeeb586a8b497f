#!/usr/bin/env bash
# The GPU run of docs/bench-gpu.md: on a machine with a GPU and no display (EGL device), every lesson's
# smoke steps against their goldens, the GPU timer path (--timing gpu), and the benches of lessons 06
# (the bloom chain's finish, in copies), 07 (three particle paths at 100 to 100,000 particles), 08 (the
# clouds' quality combinations) and 10 (the deferred light sweep), into one folder with a summary and a
# bench-gpu.md. The same script runs on llvmpipe in the test suite (--short --not-a-gpu), so it is known
# to work end to end before a GPU is lent; every figure it writes then says it is not a GPU's.
#
#   tools/gpu/run.sh [--bin DIR] [--short] [--not-a-gpu] OUT_DIR
#     --bin DIR    the programs: a bundle from tools/gpu/bundle.sh (with its lib/), or a build folder
#                  (default: build/ beside this script's checkout)
#     --short      the suite's quick mode: step 1 of each lesson, the timer path at 64x36, each bench
#                  one value of its knob at 64x36 and one frame, the light sweep at 64x36 once
# Full run: every step at 320x180, the timer path at 1920x1080 (30 frames), lesson 06 at 1280x720 (its
# 3-copy target's size), 07 at 640x360, 08 at 320x180 with 16 frames and the light sweep at 320x180,
# three runs: the sizes docs/bench.md measured llvmpipe at.
#     --not-a-gpu  the renderer is a software one: run all the same and mark every result so; without
#                  it, a software renderer (llvmpipe) stops the run before it writes any figure
#   OUT_DIR        results (written afresh): summary.md, smoke.csv, smoke/, timer/, bench/, bench-gpu.md
#
# The golden images were rendered by llvmpipe; a hardware rasteriser differs at edges (coverage,
# filtering, rounding). Each step's difference is recorded (smoke.csv, and the pictures of any step
# over the tolerance in smoke/) and judged against FXLAB_GPU_TOLERANCE (RMSE,MAX in 8-bit levels,
# default 4,255: a provisional bound until a first GPU run's differences have been looked at; the
# suite's own tolerance for llvmpipe is 1.5,64). The run exits 1 when any check fails, after writing
# everything it could.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
bin="" short=0 notgpu=0 out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --bin) bin="$2"; shift 2 ;;
    --short) short=1; shift ;;
    --not-a-gpu) notgpu=1; shift ;;
    -h|--help) sed -n '2,26p' "$0"; exit 0 ;;
    -*) echo "run.sh: unknown option $1" >&2; exit 2 ;;
    *) out="$1"; shift ;;
  esac
done
[ -n "$out" ] || { echo "usage: tools/gpu/run.sh [--bin DIR] [--short] [--not-a-gpu] OUT_DIR" >&2; exit 2; }
bin="${bin:-$root/build}"
bin="$(cd "$bin" 2>/dev/null && pwd)" || { echo "run.sh: --bin: no folder $bin" >&2; exit 2; }
# A bundle has the programs at its top and its libraries in lib/; a build folder has them where CMake put them.
find_program() {
  local name="$1" found
  for found in "$bin/$name" "$bin/lessons/$name" "$bin/tests/smoke/$name" "$bin/tools/bench/$name"; do
    [ -x "$found" ] && [ -f "$found" ] && { echo "$found"; return 0; }
  done
  return 1
}
[ -d "$bin/lib" ] && export LD_LIBRARY_PATH="$bin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export FXLAB_ROOT="$root"                 # shaders/ and res/ from this checkout
export FXLAB_CONFIG_DIR="$out/.config"    # never a teacher's ui.json
checker="$(find_program fx_smoke_check)" || { echo "run.sh: no fx_smoke_check in $bin" >&2; exit 2; }
plotter="$(find_program fx_series_plot)" || { echo "run.sh: no fx_series_plot in $bin" >&2; exit 2; }
lessons=()
for f in "$bin"/fxlab-[0-9][0-9]-* "$bin"/lessons/fxlab-[0-9][0-9]-*; do [ -x "$f" ] && [ -f "$f" ] && lessons+=("$f"); done
[ "${#lessons[@]}" -gt 0 ] || { echo "run.sh: no lesson programs in $bin" >&2; exit 2; }
lesson() { local f; for f in "${lessons[@]}"; do [[ "$(basename "$f")" == fxlab-$1-* ]] && { echo "$f"; return 0; }; done; return 1; }

rm -rf "$out" && mkdir -p "$out/smoke" "$out/timer" "$out/bench" "$FXLAB_CONFIG_DIR"
status=0
note() { echo "$*" | tee -a "$out/run.log"; }
failed() { note "FAIL: $*"; status=1; }
start=$(date +%s)

# --- The machine: a program that cannot load, or a GPU that turns out to be llvmpipe, stops here ---
missing="$(for f in "${lessons[@]}" "$checker" "$plotter"; do ldd "$f" 2>&1 | grep -E 'not found|version .* not found'; done | sort -u)"
if [ -n "$missing" ]; then
  note "FAIL: the programs cannot load here (carry these with tools/gpu/bundle.sh, or build on this machine):"
  note "$missing"; exit 1
fi
probe="$out/probe.json"
if ! "$(lesson 01)" --headless --size 64x36 --frames 1 --report "$probe" >"$out/probe.log" 2>&1; then
  note "FAIL: no OpenGL 4.5 context here:"; cat "$out/probe.log" | tee -a "$out/run.log"; exit 1
fi
renderer="$(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(r["renderer"] + " | " + r["glVersion"] + " | " + r["context"])' "$probe")"
software=0
grep -qiE 'llvmpipe|softpipe|swrast|software' <<<"$renderer" && software=1
if [ "$software" = 1 ] && [ "$notgpu" = 0 ]; then
  note "FAIL: the renderer is a software one ($renderer), not a GPU. On the GPU machine, point EGL at the"
  note "      GPU's vendor library (__EGL_VENDOR_LIBRARY_FILENAMES, see docs/bench-gpu.md); to run anyway,"
  note "      marking every figure as not a GPU's, pass --not-a-gpu."
  exit 1
fi
kind="GPU"; [ "$notgpu" = 1 ] && kind="NOT A GPU (software renderer)"
note "renderer: $renderer ($kind)"

# --- Every lesson's smoke steps against the goldens (320x180, 3 frames: the smoke test's run) ---
tolerance="${FXLAB_GPU_TOLERANCE:-4,255}"
echo "lesson,step,result,rmse,max_abs,texels_differing" >"$out/smoke.csv"
for exe in "${lessons[@]}"; do
  name="$(basename "$exe")"
  steps="$("$exe" --list-steps 2>/dev/null | grep -c '^[0-9][0-9]*\. ')"
  [ "$short" = 1 ] && steps=1
  for ((k = 1; k <= steps; k++)); do
    dir="$out/smoke/$name/step-$k"
    mkdir -p "$dir"
    if ! "$exe" --headless --size 320x180 --frames 3 --step "$k" --capture "$dir" --report "$dir/report.json" \
         >"$dir/run.log" 2>&1; then
      failed "$name step $k exited with an error (smoke/$name/step-$k/run.log)"; echo "$name,$k,error,,," >>"$out/smoke.csv"; continue
    fi
    expect=()
    grep -q '"expectErrorsInStep": true' "$dir/report.json" && expect=(--expect-gl-errors)
    "$checker" "$dir" "$dir/report.json" "$root/tests/smoke/golden/$name/step-$k.png" "$dir" \
      --tolerance "$tolerance" "${expect[@]}" >"$dir/check.log" 2>&1
    code=$?
    # "RMSE r, max difference m, n texels differ": the measured difference, whatever the verdict.
    nums="$(grep -oE 'RMSE [0-9.e+-]+, max difference [0-9]+, [0-9]+ texels' "$dir/check.log" | sed -n 1p |
            sed -E 's/RMSE ([^,]+), max difference ([0-9]+), ([0-9]+) texels/\1,\2,\3/')"
    result=pass; [ "$code" -eq 0 ] || { result=fail; failed "$name step $k: $(grep -m1 FAIL "$dir/check.log")"; }
    echo "$name,$k,$result,${nums:-,,}" >>"$out/smoke.csv"
    # Keep the pictures and the report only; the intermediate textures stay behind (the folder travels back).
    find "$dir" -name '*.png' ! -name 'final.png' ! -name '*.diff.png' ! -name '*.actual.png' -delete
  done
done
note "smoke: $(grep -c ',pass,' "$out/smoke.csv") of $(($(wc -l <"$out/smoke.csv") - 1)) steps within $tolerance of the goldens"

# --- The GPU timer path: timer queries, read without stalling, must time every pass ---
size=1920x1080; frames=30
[ "$short" = 1 ] && size=64x36 && frames=8
if "$(lesson 06)" --headless --size "$size" --frames "$frames" --step 5 --timing gpu --report "$out/timer/report.json" \
     >"$out/timer/run.log" 2>&1; then
  python3 - "$out/timer/report.json" "$software" >"$out/timer/summary.txt" <<'PY' || failed "the GPU timer path: $(cat "$out/timer/summary.txt")"
import json, sys
r = json.load(open(sys.argv[1]))
method = r["timing"]["method"]
ran = [p for p in r["passes"] if p["executed"]]
timed = [p for p in ran if p["timeMs"] is not None]
print(f"method: {method} ({r['timing']['reason']}); {len(timed)} of {len(ran)} passes timed")
for p in timed:
    print(f"  {p['name']}: {p['timeMs']:.4f} ms")
ok = "GL_TIME" in method.upper() and len(timed) == len(ran) and len(ran) > 0
# On a GPU the timer measures the work; on llvmpipe it does not (DESIGN.md), so only its plumbing counts.
if sys.argv[2] == "0":
    ok = ok and all(p["timeMs"] > 0 for p in timed)
sys.exit(0 if ok else 1)
PY
else
  failed "the GPU timer path: lesson 06 exited with an error (timer/run.log)"
fi
note "timer: $(head -1 "$out/timer/summary.txt" 2>/dev/null)"

# --- The benches, each at the size docs/bench.md measured llvmpipe at, so the two stand side by side ---
bench() {  # bench <lesson> <knob> <size> [extra flags]
  local number="$1" knob="$2" size="$3"; shift 3
  local dir="$out/bench/$number" extra=(--size "$size" "$@")
  [ "$short" = 1 ] && extra=(--size 64x36 --bench-frames 1 --bench-values 1)
  if ! "$(lesson "$number")" --bench --knob "$knob" "${extra[@]}" --bench-out "$dir" >"$dir.log" 2>&1; then
    failed "bench $number --knob $knob exited with an error (bench/$number.log)"; return
  fi
  [ -s "$dir/bench.csv" ] || failed "bench $number wrote no bench.csv"
}
bench 06 finish 1280x720
bench 07 workload 640x360
bench 08 quality 320x180 --bench-frames 16
sweep=(320x180 3)
[ "$short" = 1 ] && sweep=(64x36 1)
if ! "$root/tools/bench/lesson10_light_sweep.sh" "$(lesson 10)" "$plotter" "$out/bench/10" "${sweep[@]}" \
     >"$out/bench/10.log" 2>&1; then
  failed "the lesson 10 light sweep exited with an error (bench/10.log)"
fi
note "benches: $(ls "$out/bench" | grep -vc '\.log$') written"

# --- bench-gpu.md and the summary ---
python3 "$here/write_report.py" "$out" --renderer "$renderer" --kind "$kind" --tolerance "$tolerance" \
  --seconds "$(($(date +%s) - start))" $([ "$short" = 1 ] && echo --short) || failed "write_report.py failed"
rm -rf "$FXLAB_CONFIG_DIR"
note "done in $(($(date +%s) - start)) s: $([ "$status" -eq 0 ] && echo "every check passed" || echo "some checks FAILED") ($out/summary.md)"
exit "$status"
