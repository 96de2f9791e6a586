#!/usr/bin/env bash
# Packs what bench/device/run.sh needs on the lent GPU machine (#33 point 5) into .device/ (git-ignored through
# .git/info/exclude), from a built tree (cmake --build --preset default) on Debian 12:
#   - sdfwb, stripped (the batch CLI loads no Qt, OpenImageIO or FFmpeg), and the Debian libraries it links that
#     a CUDA image lacks (assimp, draco, minizip, isa-l, libepoxy);
#   - the Flying Edges peer (bench/device/build_peer.sh), with the VTK and TBB libraries it needs;
#   - the bench's tilted shapes as GLSL files.
# The glvnd EGL loaders travel separately in .gl/ (see /work/.library/device/README.md).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
cd "$ROOT"
OUT=.device
rm -rf "$OUT" && mkdir -p "$OUT/lib"
grep -qx '/.device/' .git/info/exclude || echo '/.device/' >>.git/info/exclude

bash bench/device/build_peer.sh "$OUT/flying_edges_peer"
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
