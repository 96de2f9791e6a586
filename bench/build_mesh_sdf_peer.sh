#!/usr/bin/env bash
# Builds bench/mesh_sdf_peer.cpp (the C++ references on Embree 3 and CGAL) into folder $1 in every
# variant a demanding user would try: -O3 -march=native with and without -ffast-math. Prints each
# compile line. Needs libembree-dev, libcgal-dev (scripts/bootstrap installs them).
set -euo pipefail
out=${1:?usage: build_mesh_sdf_peer.sh FOLDER}
mkdir -p "$out"
source=$(cd "$(dirname "$0")" && pwd)/mesh_sdf_peer.cpp
for variant in "O3-native:-O3 -march=native" "O3-native-fastmath:-O3 -march=native -ffast-math"; do
  name=${variant%%:*}
  flags=${variant#*:}
  binary="$out/mesh_sdf_peer-$name"
  if [ -x "$binary" ] && [ "$binary" -nt "$source" ]; then
    echo "g++ -std=c++17 $flags -fopenmp -DNDEBUG (up to date: $binary)"
    continue
  fi
  line="g++ -std=c++17 $flags -fopenmp -DNDEBUG -DREF_FLAGS=\"$flags -fopenmp\" $source -o $binary -lembree3 -lgmp -lmpfr"
  echo "$line"
  g++ -std=c++17 $flags -fopenmp -DNDEBUG "-DREF_FLAGS=\"$flags -fopenmp\"" "$source" -o "$binary" -lembree3 -lgmp -lmpfr
done
