#!/usr/bin/env bash
# Packs what bench/device/run.sh needs on the lent GPU machine (#33 point 5) into .device/ (git-ignored through
# .git/info/exclude), from a built tree (cmake --build --preset default) on Debian 12:
#   - sdfwb, stripped (the batch CLI loads no Qt, OpenImageIO or FFmpeg), and the Debian libraries it links that
#     a CUDA image lacks (assimp, draco, minizip, isa-l, libepoxy);
#   - the Flying Edges peer (bench/device/flying_edges_peer.cpp) built against Debian's VTK 9.1 (headers from the
#     libvtk9-dev package, unpacked, not installed), with the VTK and TBB libraries it needs;
#   - the bench's tilted shapes as GLSL files.
# The glvnd EGL loaders travel separately in .gl/ (see /work/.library/device/README.md).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
cd "$ROOT"
OUT=.device
WORK=${TMPDIR:-/tmp}/sdfwb-device-bundle
rm -rf "$OUT" && mkdir -p "$OUT/lib" "$WORK"
grep -qx '/.device/' .git/info/exclude || echo '/.device/' >>.git/info/exclude

if [ ! -d "$WORK/vtkdev/usr/include/tbb" ]; then  # VTK's SMP headers include TBB's
    (cd "$WORK" && apt-get download libvtk9-dev libtbb-dev && dpkg -x libvtk9-dev_*.deb vtkdev &&
        dpkg -x libtbb-dev_*.deb vtkdev)
fi
VTKLIB=/usr/lib/x86_64-linux-gnu
VTK_LIBS=(vtkFiltersCore vtkCommonExecutionModel vtkCommonDataModel vtkCommonMisc vtkCommonCore vtksys)
# -march=x86-64-v3 (AVX2, FMA): what this VM and any current server runs; -march=native here could name
# instructions the device's processor lacks.
g++ -std=c++17 -Wno-deprecated-declarations -O3 -march=x86-64-v3 -DNDEBUG -pthread -o "$OUT/flying_edges_peer" \
    bench/device/flying_edges_peer.cpp -I"$WORK/vtkdev/usr/include/vtk-9.1" -I"$WORK/vtkdev/usr/include" \
    $(for l in "${VTK_LIBS[@]}"; do echo "$VTKLIB/lib$l-9.1.so.1"; done)
strip "$OUT/flying_edges_peer"
strip -o "$OUT/sdfwb" build/app/sdfwb

# Every library the two programs load, less those any glibc system has (libc, libm, libstdc++, libgcc_s, ...).
for program in "$OUT/sdfwb" "$OUT/flying_edges_peer"; do
    ldd "$program" | awk '/=> \//{print $1, $3}' | while read -r name path; do
        case "$name" in
        libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | libstdc++.so.* | libgcc_s.so.* | libz.so.*) ;;
        *) [ -e "$OUT/lib/$name" ] || strip -o "$OUT/lib/$name" "$path" ;;
        esac
    done
done

PYTHONPATH=build/python /usr/bin/python3 bench/bench_mesh_peers.py --write-glsl "$OUT"
du -sh "$OUT"
