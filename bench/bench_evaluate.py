#!/usr/bin/env python3
"""sdfwb.evaluate against the same analytic SDFs in PyTorch and NumPy, measured in the same run (#18 point 4).

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_evaluate.py [--points 10000000] [--repeats 3] [--markdown FILE]

Three classes: a sphere (one length), a CSG shape (box intersected with a sphere, minus three cylinders: the
classic CSG tree) and a fractal (Mandelbulb, power 8, 8 iterations, bailout 2). Each is written three times with
the same formulas: GLSL for sdfwb.evaluate (distance only, gradient=False), PyTorch (CPU float32, all threads,
escaped points masked with torch.where: the vectorised form), NumPy (float32, the same masking). Every
implementation gets the same float32 points, uniform in [-1.2, 1.2]^3. The accuracy column is the largest
difference from a float64 NumPy evaluation of the first 100,000 points (finite values only).
Prints medians of --repeats runs and the ratios reference / ours (above 1: we are faster).
"""
import datetime
import os
import platform
import statistics
import sys
import time

import numpy as np
import torch

import sdfwb

args = sys.argv[1:]
N = int(args[args.index("--points") + 1]) if "--points" in args else 10_000_000
REPEATS = int(args[args.index("--repeats") + 1]) if "--repeats" in args else 3
MARKDOWN = args[args.index("--markdown") + 1] if "--markdown" in args else None
torch.set_num_threads(os.cpu_count())

GLSL = {
    "sphere": "float sdf(vec3 p) { return length(p) - 0.8; }",
    "csg": """
float sdBox(vec3 p, vec3 b) { vec3 q = abs(p) - b; return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }
float sdf(vec3 p) {
    float solid = max(sdBox(p, vec3(0.6)), length(p) - 0.8);
    float holes = min(min(length(p.yz), length(p.xz)), length(p.xy)) - 0.3;
    return max(solid, -holes);
}""",
    "fractal": """
float sdf(vec3 p) {
    vec3 z = p; float dr = 1.0; float r = length(z);
    for (int i = 0; i < 8; ++i) {
        r = length(z);
        if (r > 2.0) break;
        float theta = acos(clamp(z.z / r, -1.0, 1.0)) * 8.0;
        float phi = atan(z.y, z.x) * 8.0;
        dr = pow(r, 7.0) * 8.0 * dr + 1.0;
        z = pow(r, 8.0) * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)) + p;
    }
    return 0.5 * log(r) * r / dr;
}""",
}


def make(xp):
    """The three SDFs over an array library with NumPy's names (numpy, or torch through a thin table)."""
    T = xp

    def length(x, y, z):
        return T.sqrt(x * x + y * y + z * z)

    def sphere(x, y, z):
        return length(x, y, z) - 0.8

    def box(x, y, z, b):
        qx, qy, qz = T.abs(x) - b, T.abs(y) - b, T.abs(z) - b
        zero = T.zeros_like(qx)
        outside = length(T.maximum(qx, zero), T.maximum(qy, zero), T.maximum(qz, zero))
        return outside + T.minimum(T.maximum(qx, T.maximum(qy, qz)), zero)

    def csg(x, y, z):
        solid = T.maximum(box(x, y, z, 0.6), length(x, y, z) - 0.8)
        holes = T.minimum(T.minimum(T.sqrt(y * y + z * z), T.sqrt(x * x + z * z)), T.sqrt(x * x + y * y)) - 0.3
        return T.maximum(solid, -holes)

    def fractal(x, y, z):
        zx, zy, zz = x, y, z
        dr = T.ones_like(x)
        r = length(zx, zy, zz)
        active = T.ones_like(x) > 0
        for _ in range(8):
            r_new = length(zx, zy, zz)
            r = T.where(active, r_new, r)
            active = active & (r <= 2.0)
            theta = T.arccos(T.clip(zz / r, -1.0, 1.0)) * 8.0
            phi = T.arctan2(zy, zx) * 8.0
            r7 = r ** 7
            dr = T.where(active, r7 * 8.0 * dr + 1.0, dr)
            r8 = r7 * r
            st = T.sin(theta)
            zx = T.where(active, r8 * st * T.cos(phi) + x, zx)
            zy = T.where(active, r8 * st * T.sin(phi) + y, zy)
            zz = T.where(active, r8 * T.cos(theta) + z, zz)
        return 0.5 * T.log(r) * r / dr

    return {"sphere": sphere, "csg": csg, "fractal": fractal}


class TorchNames:
    """NumPy's function names over torch (the formulas above are written once)."""
    sqrt, abs, maximum, minimum, where = torch.sqrt, torch.abs, torch.maximum, torch.minimum, torch.where
    zeros_like, ones_like, sin, cos, log = torch.zeros_like, torch.ones_like, torch.sin, torch.cos, torch.log
    arccos, arctan2 = torch.acos, torch.atan2

    @staticmethod
    def clip(v, lo, hi):
        return torch.clamp(v, lo, hi)


NUMPY, TORCH = make(np), make(TorchNames)


def timed(work):
    times, result = [], None
    for _ in range(REPEATS):
        start = time.perf_counter()
        result = work()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def error(values, truth):
    values = np.asarray(values[: len(truth)], np.float64)
    finite = np.isfinite(values) & np.isfinite(truth)
    return float(np.max(np.abs(values[finite] - truth[finite])))


points = (np.random.default_rng(7).random((N, 3), dtype=np.float32) * 2.4 - 1.2).astype(np.float32)
columns = [np.ascontiguousarray(points[:, k]) for k in range(3)]
tensors = [torch.from_numpy(c) for c in columns]
check = points[:100_000].astype(np.float64)
rows = []
with np.errstate(all="ignore"):
    for name, source in GLSL.items():
        sdfwb.evaluate(source, points[:1000], gradient=False)  # compile once outside the timing (a cached program)
        truth = NUMPY[name](check[:, 0], check[:, 1], check[:, 2])
        t_ours, ours = timed(lambda: sdfwb.evaluate(source, points, gradient=False)["distance"])
        t_torch, theirs = timed(lambda: TORCH[name](*tensors))
        t_numpy, plain = timed(lambda: NUMPY[name](*columns))
        errors = (error(ours, truth), error(theirs.numpy(), truth), error(plain, truth))
        rows.append((name, t_ours, t_torch, t_numpy) + errors)
        print(f"{name:8s} {N} points: sdfwb {t_ours:6.3f} s, PyTorch {t_torch:6.3f} s ({t_torch / t_ours:5.2f}x), NumPy "
              f"{t_numpy:6.3f} s ({t_numpy / t_ours:5.2f}x); max |error| vs float64 {errors[0]:.2g} / {errors[1]:.2g} / "
              f"{errors[2]:.2g}", flush=True)

if MARKDOWN:
    with open(MARKDOWN, "w") as out:
        out.write("# Evaluating SDFs at given points: sdfwb.evaluate against PyTorch and NumPy\n\n")
        out.write(f"Generated by `PYTHONPATH=build/python /usr/bin/python3 bench/bench_evaluate.py --markdown {MARKDOWN}`; "
                  f"{datetime.date.today().isoformat()}, {platform.node()}, {os.cpu_count()} cores, no GPU (sdfwb on Mesa "
                  f"llvmpipe), torch {torch.__version__} with {torch.get_num_threads()} threads, NumPy {np.__version__}. "
                  f"{N:,} float32 points uniform in [-1.2, 1.2]^3, medians of {REPEATS} runs, all measured in the same run. "
                  "sdfwb: `sdfwb.evaluate(glsl, points, gradient=False)` (the program compiled once before timing, as a "
                  "training loop would). PyTorch and NumPy: the same formulas, vectorised; the fractal's escaped points are "
                  "masked with `where`. Error: the largest difference from float64 NumPy on the first 100,000 points.\n\n")
        out.write("| SDF | sdfwb s | PyTorch s | NumPy s | sdfwb vs PyTorch | sdfwb vs NumPy | max error sdfwb | "
                  "max error PyTorch | max error NumPy |\n|---|---|---|---|---|---|---|---|---|\n")
        for name, t_ours, t_torch, t_numpy, e_ours, e_torch, e_numpy in rows:
            out.write(f"| {name} | {t_ours:.3f} | {t_torch:.3f} | {t_numpy:.3f} | {t_torch / t_ours:.2f}x | "
                      f"{t_numpy / t_ours:.2f}x | {e_ours:.2g} | {e_torch:.2g} | {e_numpy:.2g} |\n")
        out.write("\nThe goal (#18) is at least 5x PyTorch on the CSG and fractal classes.\n")
    print(f"wrote {MARKDOWN}")
