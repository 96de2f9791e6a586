#!/usr/bin/env python3
"""Reads sdfwb's sample files with the tools ML users have: numpy.load(allow_pickle=False) for
.npz, numpy.fromfile for the paper's .bin layout, and meshio (a common mesh reader) for .ply.
Usage: check_outputs_with_numpy.py SDFWB_BINARY WORK_FOLDER"""
import os
import subprocess
import sys

import meshio
import numpy as np

binary, folder = sys.argv[1], sys.argv[2]
os.makedirs(folder, exist_ok=True)
env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
N = 5000


def sample(output, *extra):
    subprocess.run([binary, "--batch", "sample", "--sdf", "sphere", "--pattern", "near", "-n", str(N), "--seed", "9",
                    "--output", output, "--quiet", *extra], check=True, env=env)


npz, bin_, ply = (os.path.join(folder, "s." + e) for e in ("npz", "bin", "ply"))
sample(npz)
sample(bin_)
sample(ply)

z = np.load(npz, allow_pickle=False)
assert z["position"].shape == (N, 3) and z["position"].dtype == np.float32, z["position"].shape
assert z["distance"].shape == (N,) and z["gradient"].shape == (N, 3)
assert str(z["sdf"]) == "sphere" and str(z["pattern"]) == "near" and int(z["seed"]) == 9, (z["sdf"], z["pattern"], z["seed"])
assert int(z["total_count"]) == N and int(z["first_index"]) == 0
# The Sphere dataset SDF has radius 0.8: distance = |p| - 0.8, gradient = p / |p|.
r = np.linalg.norm(z["position"], axis=1)
assert np.max(np.abs(z["distance"] - (r - 0.8))) < 1e-5
assert np.max(np.abs(z["gradient"] - z["position"] / r[:, None])) < 5e-3

raw = np.fromfile(bin_, dtype="<u4", count=1)[0]
assert raw == N and os.path.getsize(bin_) == 4 + 28 * N
body = np.fromfile(bin_, dtype="<f4", offset=4)
assert np.array_equal(body[: 3 * N].reshape(N, 3), z["position"])
assert np.array_equal(body[3 * N: 4 * N], z["distance"])
assert np.array_equal(body[4 * N:].reshape(N, 3), z["gradient"])

mesh = meshio.read(ply)
assert mesh.points.shape == (N, 3) and np.array_equal(mesh.points.astype(np.float32), z["position"])
assert np.array_equal(mesh.point_data["distance"], z["distance"])
assert np.array_equal(np.stack([mesh.point_data[k] for k in ("gx", "gy", "gz")], axis=1), z["gradient"])
print(f"numpy and meshio read {N} rows from .npz, .bin and .ply identically")
