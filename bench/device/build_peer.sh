#!/usr/bin/env bash
# Builds the C++ Flying Edges peer (bench/device/flying_edges_peer.cpp) twice from the same source against Debian 12's
# VTK 9.1 (the runtime libraries of python3-vtk9's libvtk9.1, the headers from the libvtk9-dev and libtbb-dev
# packages, unpacked, not installed, which would pull in about a hundred -dev packages):
#   OUTPUT       strict IEEE float (g++ -O3, no -ffast-math: no reassociation, NaN and Inf kept; g++ in C++ mode still
#                fuses a*b+c into an FMA where -march has one, its default -ffp-contract=fast, as before)
#   OUTPUT-fast  the same with -ffast-math
#
#   build_peer.sh [OUTPUT [MARCH]]   OUTPUT default build/bench/flying_edges_peer; MARCH (g++ -march=) default
#                                    x86-64-v3 (AVX2, FMA), which any current server runs; `native` for a binary run
#                                    only on the machine that builds it (bench/bench_mesh_peers.py builds locally so).
# Each binary prints the flags it was built with as the "flags" field of its JSON (-DPEER_FLAGS).
# Used by bench/bench_mesh_peers.py and bench/device/bundle.sh.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
OUTPUT=${1:-$ROOT/build/bench/flying_edges_peer}
MARCH=${2:-x86-64-v3}
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
LIBS=$(for l in vtkFiltersCore vtkCommonExecutionModel vtkCommonDataModel vtkCommonMisc vtkCommonCore vtksys; do
    echo "$VTKLIB/lib$l-9.1.so.1"
done)
build() { # build BINARY FLAGS...: the flags that set the arithmetic, also compiled in as PEER_FLAGS
    local binary=$1
    shift
    # shellcheck disable=SC2086 # LIBS: one path a word
    g++ -std=c++17 -Wno-deprecated-declarations "$@" -DNDEBUG -pthread -DPEER_FLAGS="\"-std=c++17 $*\"" \
        -o "$binary" "$ROOT/bench/device/flying_edges_peer.cpp" -I"$WORK/usr/include/vtk-9.1" -I"$WORK/usr/include" $LIBS
    strip "$binary"
}
build "$OUTPUT" -O3 -march="$MARCH"
build "$OUTPUT-fast" -O3 -march="$MARCH" -ffast-math
