#!/usr/bin/env bash
# Builds bench/mesh_sdf_reference.cpp (the C++ reference of bench_mesh_sdf.py) into the directory $1,
# one binary per compile variant, each holding both engines (Embree 3 and CGAL 5.5):
#   mesh_sdf_reference-O3-native           -O3 -march=native
#   mesh_sdf_reference-O3-native-fastmath  -O3 -march=native -ffast-math
# Every variant also gets -std=c++20 -fopenmp -DNDEBUG (a release build: CGAL's assertions off); the
# binary reports all of its flags as compiler_flags. Prints each compile line before running it.
# Needs g++ (or $CXX), libembree-dev, libcgal-dev, libgmp-dev and libmpfr-dev.
set -euo pipefail

if [ $# -ne 1 ]; then
    echo "usage: $0 OUTPUT_DIRECTORY" >&2
    exit 1
fi
out=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source_file="$here/mesh_sdf_reference.cpp"
cxx=${CXX:-g++}
mkdir -p "$out"

build() {
    local name=$1 flags="-std=c++20 $2 -fopenmp -DNDEBUG"
    local -a split
    read -r -a split <<<"$flags"
    echo "$(printf '%q' "$cxx") $flags '-DREF_FLAGS=\"$flags\"' $(printf '%q' "$source_file") -o $(printf '%q' "$out/$name")" \
        "-lembree3 -lgmp -lmpfr"
    "$cxx" "${split[@]}" "-DREF_FLAGS=\"$flags\"" "$source_file" -o "$out/$name" -lembree3 -lgmp -lmpfr
}

build mesh_sdf_reference-O3-native "-O3 -march=native"
build mesh_sdf_reference-O3-native-fastmath "-O3 -march=native -ffast-math"
