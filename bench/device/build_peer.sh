#!/usr/bin/env bash
# Builds the C++ Flying Edges peer (bench/device/flying_edges_peer.cpp) into OUTPUT (default
# build/bench/flying_edges_peer) against Debian 12's VTK 9.1: the runtime libraries of python3-vtk9's
# libvtk9.1, the headers from the libvtk9-dev and libtbb-dev packages, unpacked (not installed, which
# would pull in about a hundred -dev packages). Used by bench/bench_mesh_peers.py and bench/device/bundle.sh.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
OUTPUT=${1:-$ROOT/build/bench/flying_edges_peer}
WORK=${TMPDIR:-/tmp}/sdfwb-vtk-headers
VTKLIB=/usr/lib/x86_64-linux-gnu
if [ ! -e "$VTKLIB/libvtkFiltersCore-9.1.so.1" ]; then
    echo "build_peer.sh: Debian's libvtk9.1 is missing (apt-get install python3-vtk9)" >&2
    exit 1
fi
if [ ! -d "$WORK/usr/include/tbb" ]; then # VTK's SMP headers include TBB's
    mkdir -p "$WORK"
    (cd "$WORK" && apt-get download libvtk9-dev libtbb-dev && for deb in ./*.deb; do dpkg -x "$deb" .; done)
fi
mkdir -p "$(dirname "$OUTPUT")"
# -march=x86-64-v3 (AVX2, FMA): this VM and any current server run it; -march=native here could name
# instructions another machine's processor lacks.
g++ -std=c++17 -Wno-deprecated-declarations -O3 -march=x86-64-v3 -DNDEBUG -pthread -o "$OUTPUT" \
    "$ROOT/bench/device/flying_edges_peer.cpp" -I"$WORK/usr/include/vtk-9.1" -I"$WORK/usr/include" \
    $(for l in vtkFiltersCore vtkCommonExecutionModel vtkCommonDataModel vtkCommonMisc vtkCommonCore vtksys; do
        echo "$VTKLIB/lib$l-9.1.so.1"
    done)
strip "$OUTPUT"
