#!/usr/bin/env bash
# On the lent GPU machine, from the repository root, with .device/ (bench/device/bundle.sh) and .gl/ carried:
#   bash bench/device/run.sh        (writes $OUT/results.jsonl and $OUT/log.txt)
# Then, here: /usr/bin/python3 bench/device/report.py RESULTS.jsonl  -> docs/meshing-gpu.md
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor
export LD_LIBRARY_PATH=$PWD/.device/lib SDFWB_EGL_PLATFORM=device PYTHONUNBUFFERED=1
nvidia-smi -L
if ! .device/sdfwb --version; then
    ldd .device/sdfwb .device/flying_edges_peer | grep -i "not found"
    exit 1
fi
python3 bench/device/run_device.py "$OUT" --resolutions "${RESOLUTIONS:-128,256,512,1024}" 2>&1 | tee "$OUT/log.txt"
