#!/usr/bin/env python3
"""Checks bench/peer_fields.py: every NumPy field against sdfwb's own evaluation of the same SDF.

    env -u DISPLAY PYTHONPATH=build/python /usr/bin/python3 bench/check_peer_fields.py [--only NAME,...]

Per field: 200,000 uniform points in [-1, 1]^3 (seed 0), |NumPy - sdfwb.evaluate(gradient=False)|: its maximum and
99.9th percentile; that the field keeps float32 and the broadcast shape on a 129^3 lattice (x, y, z of shapes
(1, 1, N), (1, N, 1), (N, 1, 1)) and agrees there with itself on (N,) columns; and the lattice's NumPy time (one
thread, the best of five). Exits 1 when a maximum difference exceeds its bound: 1e-4 for every field.
"""
import os
import sys
import time

import numpy as np

import sdfwb

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_fields  # noqa: E402  (bench/peer_fields.py)

BOUND = 1e-4
N_POINTS = 200_000
LATTICE = 129
args = sys.argv[1:]
ONLY = set(args[args.index("--only") + 1].split(",")) if "--only" in args else set()


def lattice_axes(n):
    axis = np.linspace(-1.0, 1.0, n, dtype=np.float32)
    return axis[None, None, :], axis[None, :, None], axis[:, None, None]


def best_time(function, repeats=5):
    best = float("inf")
    for _ in range(repeats):
        started = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - started)
    return best


points = np.random.default_rng(0).uniform(-1.0, 1.0, (N_POINTS, 3)).astype(np.float32)
columns = points[:, 0].copy(), points[:, 1].copy(), points[:, 2].copy()
x, y, z = lattice_axes(LATTICE)
sample = np.random.default_rng(1).integers(0, LATTICE, (10_000, 3))  # lattice nodes (k, j, i) for the self-check

failures = []
print(f"{'field':<24} {'max |diff|':>11} {'p99.9':>11} {'bound':>7} {'lattice self':>12} {'129^3 s':>8}  verdict")
for name, field in peer_fields.FIELDS.items():
    if ONLY and name not in ONLY:
        continue
    ours = field(*columns)
    reference = sdfwb.evaluate(peer_fields.SDFWB_SOURCES[name], points, gradient=False)["distance"]
    diff = np.abs(ours.astype(np.float64) - reference.astype(np.float64))
    worst, p999 = float(np.max(diff)), float(np.percentile(diff, 99.9))

    values = field(x, y, z)
    problems = []
    if ours.dtype != np.float32 or values.dtype != np.float32:
        problems.append(f"dtype {ours.dtype}/{values.dtype}")
    if ours.shape != (N_POINTS,) or values.shape != (LATTICE,) * 3:
        problems.append(f"shape {ours.shape}/{values.shape}")
    axis = x.ravel()
    at = field(axis[sample[:, 2]], axis[sample[:, 1]], axis[sample[:, 0]])
    self_diff = float(np.max(np.abs(values[sample[:, 0], sample[:, 1], sample[:, 2]] - at))) if not problems else np.nan
    seconds = best_time(lambda: field(x, y, z))
    if not np.isfinite(worst) or worst > BOUND:
        problems.append(f"max {worst:.3g} > {BOUND:g}")
    if not self_diff <= BOUND:
        problems.append(f"lattice differs from columns by {self_diff:.3g}")
    if problems:
        failures.append(f"{name}: {', '.join(problems)}")
    print(f"{name:<24} {worst:11.3e} {p999:11.3e} {BOUND:7.0e} {self_diff:12.1e} {seconds:8.3f}  "
          f"{'ok' if not problems else 'FAIL: ' + ', '.join(problems)}")

if failures:
    print("\nFAILED:\n" + "\n".join(f"- {f}" for f in failures))
    sys.exit(1)
print("\nall fields agree with sdfwb")
