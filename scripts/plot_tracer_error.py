#!/usr/bin/env python3
"""Plots the sphere tracer's hit error against steps and time from bench_tracer's CSV.

    build/bench/bench_tracer --error-only --csv tracer.csv
    /usr/bin/python3 scripts/plot_tracer_error.py tracer.csv docs/images/tracer_error.png
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
series = defaultdict(list)
for row in rows:
    series[(row["sdf"], row["method"])].append(row)

fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
colors = {"torus": "tab:blue", "box": "tab:orange", "capsule": "tab:green"}
markers = {"plain": "o", "over-relaxed 1.6": "s", "step factor 0.7": "^"}
for (sdf, method), points in series.items():
    points.sort(key=lambda r: float(r["steps_hits"]))
    steps = [float(r["steps_hits"]) for r in points]
    ms = [float(r["milliseconds"]) for r in points]
    error = [float(r["mean_error"]) for r in points]
    kwargs = dict(color=colors.get(sdf, "k"), marker=markers.get(method, "x"), label=f"{sdf}, {method}")
    axes[0].plot(steps, error, **kwargs)
    axes[1].plot(ms, error, linestyle="none", **kwargs)
axes[0].set_xlabel("mean sphere-tracing steps per hit pixel")
axes[1].set_xlabel("frame time, 1280x720 (ms, median of 3, llvmpipe)")
for axis in axes:
    axis.set_yscale("log")
    axis.set_ylabel("mean hit error |f(hit)| (scene units)")
    axis.grid(True, which="both", alpha=0.3)
axes[0].set_title("Error against steps (hit tolerance 4 to 0.1 pixel)")
axes[1].set_title("Error against time")
axes[0].legend(fontsize=7, ncol=1)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
print("wrote", sys.argv[2])
