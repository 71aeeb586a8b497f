#!/usr/bin/env bash
# The command for the lent GPU machine (docs/bench-gpu.md says how to call it): NVIDIA's EGL vendor
# library instead of any other, the programs from the carried bundle (.gpu-bundle, made here by
# tools/gpu/bundle.sh), tools/gpu/run.sh into /tmp, then the results packed into $OUT, where at most
# eight files two folders deep come back: gpu-results.tar.gz (everything), bench-gpu.md, summary.md.
# The run is stopped after FXLAB_GPU_RUN_LIMIT seconds (default 360), so that whatever it wrote is
# packed even when it runs long: give the device call a timeout_s a minute above that.
#   tools/gpu/on_device.sh [run.sh options]
set -uo pipefail
cd "$(dirname "$0")/../.."
: "${OUT:?on_device.sh writes into \$OUT (the device tool sets it)}"
for vendor in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
  [ -f "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor" && break
done
# The driver's own libraries (libEGL_nvidia.so.0 and what it loads), wherever the image keeps them.
for dir in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do
  [ -d "$dir" ] && export LD_LIBRARY_PATH="$dir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
done
results=/tmp/gpu-results
{ nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader; echo "EGL vendor: ${__EGL_VENDOR_LIBRARY_FILENAMES:-(default)}"; } \
  >/tmp/machine.txt 2>&1
timeout "${FXLAB_GPU_RUN_LIMIT:-360}" tools/gpu/run.sh --bin .gpu-bundle "$@" "$results"
code=$?
[ "$code" -eq 124 ] && echo "on_device.sh: run.sh stopped after ${FXLAB_GPU_RUN_LIMIT:-360} s" >>"$results/run.log"
cp /tmp/machine.txt "$results/machine.txt" 2>/dev/null
tar -C /tmp -czf "$OUT/gpu-results.tar.gz" gpu-results
cp "$results/bench-gpu.md" "$results/summary.md" "$OUT/" 2>/dev/null
exit "$code"
