"""Mesh files for the benchmarks, with NumPy alone (no sdfwb, no Open3D): OBJ in and out, binary
PLY out, midpoint subdivision. Run as a script it writes a mesh subdivided N times as a binary PLY,
the 1.1 M-triangle bunny of issue 46 for a machine that has NumPy and nothing else (the device run):

    python3 bench/mesh_io.py IN.obj OUT.ply [ROUNDS=2]
"""

import sys

import numpy as np


def read_obj(path):
    # OBJ's v and f lines (polygons as fans, v/vt/vn and negative indices), the way assimp reads them
    # for sdfwb: Open3D 0.16's reader returns no vertices for suzanne.obj.
    vertices, faces = [], []
    with open(path) as obj:
        for line in obj:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                vertices.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                index = [int(token.split("/")[0]) for token in parts[1:]]
                index = [i - 1 if i > 0 else len(vertices) + i for i in index]
                faces += [[index[0], index[k], index[k + 1]] for k in range(1, len(index) - 1)]
    return np.asarray(vertices, np.float64), np.asarray(faces, np.int64)


def write_obj(path, vertices, faces):
    with open(path, "w") as out:
        out.write("".join("v %.9g %.9g %.9g\n" % tuple(v) for v in vertices))
        out.write("".join("f %d %d %d\n" % tuple(f + 1) for f in faces))
    return path


def subdivide(vertices, faces):
    # Every triangle into four at its edges' midpoints (shared edges share their midpoint).
    edges = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    unique, inverse = np.unique(edges, axis=0, return_inverse=True)
    mids = len(vertices) + inverse.reshape(3, -1).T  # per face: midpoints of ab, bc, ca
    vertices = np.concatenate([vertices, (vertices[unique[:, 0]] + vertices[unique[:, 1]]) / 2])
    a, b, c = faces.T
    ab, bc, ca = mids.T
    faces = np.concatenate([np.stack(t, axis=1) for t in ((a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca))])
    return vertices, faces


def write_ply(path, vertices, faces):
    with open(path, "wb") as out:
        out.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\nproperty float x\n"
                  f"property float y\nproperty float z\nelement face {len(faces)}\n"
                  "property list uchar int vertex_indices\nend_header\n".encode())
        out.write(vertices.astype("<f4").tobytes())
        rows = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", 3)])
        rows["n"], rows["i"] = 3, faces
        out.write(rows.tobytes())


if __name__ == "__main__":
    vertices, faces = read_obj(sys.argv[1])
    for _ in range(int(sys.argv[3]) if len(sys.argv) > 3 else 2):
        vertices, faces = subdivide(vertices, faces)
    write_ply(sys.argv[2], vertices, faces)
    print(f"{sys.argv[2]}: {len(vertices)} vertices, {len(faces)} triangles")
