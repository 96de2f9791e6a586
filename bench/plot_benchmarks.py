#!/usr/bin/env python3
"""Draws the plots of docs/benchmarks.md from the CSV tables `sdfwb --batch bench` writes.

    /usr/bin/python3 bench/plot_benchmarks.py CSV_FOLDER IMAGE_FOLDER

Writes bench_tracer.png, bench_samplers.png, bench_gradients.png and bench_audit.png. Time
spreads (min to max of the repeats) are drawn as horizontal bars, error spreads as the 50th
(marker) and 99th (faint marker, same colour) percentiles.
"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(folder, name):
    with open(os.path.join(folder, name), newline="") as handle:
        return list(csv.DictReader(handle))


def grouped(rows, *keys):
    groups = defaultdict(list)
    for row in rows:
        groups[tuple(row[k] for k in keys)].append(row)
    return groups


def floats(rows, key):
    return [float(r[key]) for r in rows]


def time_bars(rows, prefix="ms"):
    median = floats(rows, f"{prefix}_median")
    low = [m - float(r[f"{prefix}_min"]) for m, r in zip(median, rows)]
    high = [float(r[f"{prefix}_max"]) - m for m, r in zip(median, rows)]
    return median, [low, high]


def finish(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


COLORS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown"]


def plot_tracer(rows, path):
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    markers = {"plain": "o", "over-relaxed 1.6": "s", "step factor 0.7": "^", "plain + cone pass": "D"}
    shapes = sorted({r["sdf"] for r in rows})
    for (sdf, method), points in sorted(grouped(rows, "sdf", "method").items()):
        points.sort(key=lambda r: float(r["steps_hits"]))
        color = COLORS[shapes.index(sdf)]
        style = dict(color=color, marker=markers.get(method, "x"))
        label = f"{sdf}, {method}"
        p50, p99 = floats(points, "error_p50"), floats(points, "error_p99")
        axes[0].plot(floats(points, "steps_hits"), p50, label=label, **style)
        axes[0].plot(floats(points, "steps_hits"), p99, linestyle=":", alpha=0.5, **style)
        ms, spread = time_bars(points)
        axes[1].errorbar(ms, p50, xerr=spread, linestyle="none", capsize=2, label=label, **style)
    axes[0].set_xlabel("mean sphere-tracing steps per hit pixel")
    axes[0].set_title("Hit error against steps (solid: median pixel, dotted: 99th percentile)")
    axes[1].set_xlabel("frame time (ms; median, bars: min to max of the repeats)")
    axes[1].set_title("Median hit error against frame time")
    for axis in axes:
        axis.set_yscale("log")
        axis.set_ylabel("|t - t*| along the ray (scene units)")
        axis.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    finish(fig, path)


def plot_samplers(rows, path):
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    shapes = sorted({r["sdf"] for r in rows})
    for axis, pattern, ylabel in (
        (axes[0], "surface", "exact distance of the sample to the surface (scene units)"),
        (axes[1], "near", "| written f - exact signed distance | (scene units)"),
    ):
        for (sdf,), points in sorted(grouped([r for r in rows if r["pattern"] == pattern], "sdf").items()):
            points.sort(key=lambda r: float(r["surface_tolerance"]), reverse=True)
            color = COLORS[shapes.index(sdf)]
            ms, spread = time_bars(points)
            axis.errorbar(ms, floats(points, "error_p50"), xerr=spread, color=color, marker="o", capsize=2, label=f"{sdf}: median")
            axis.plot(ms, floats(points, "error_p99"), color=color, marker="v", linestyle=":", alpha=0.6, label=f"{sdf}: 99th percentile")
            for r, x in zip(points, ms):
                axis.annotate(f"tol {float(r['surface_tolerance']):g}", (x, float(r["error_p50"])), fontsize=7,
                              textcoords="offset points", xytext=(4, 4))
        axis.set_xlabel(f"time for {rows[0]['samples']} samples (ms; bars: min to max)")
        axis.set_ylabel(ylabel)
        axis.set_yscale("log")
        axis.set_title(f"'{pattern}' pattern: error against time over the surface tolerance")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=7)
    finish(fig, path)


def plot_gradients(rows, path):
    fig, axes = plt.subplots(1, 3, figsize=(16, 5))
    schemes = sorted({r["scheme"] for r in rows})
    for (scheme,), points in sorted(grouped(rows, "scheme").items()):
        points.sort(key=lambda r: float(r["step"]))
        color = COLORS[schemes.index(scheme)]
        h = floats(points, "step")
        axes[0].plot(h, floats(points, "angle_p50_deg"), color=color, marker="o", label=f"{scheme}: median")
        axes[0].plot(h, floats(points, "angle_p99_deg"), color=color, marker="v", linestyle=":", label=f"{scheme}: 99th percentile")
        axes[1].plot(h, floats(points, "length_error_p50"), color=color, marker="o", label=f"{scheme}: median")
        axes[1].plot(h, floats(points, "length_error_p99"), color=color, marker="v", linestyle=":", label=f"{scheme}: 99th percentile")
    for axis, ylabel, title in (
        (axes[0], "angle to the analytic gradient (degrees)", "Direction error against the step"),
        (axes[1], "| |g| - 1 |", "Length error against the step"),
    ):
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel("difference step h (scene units)")
        axis.set_ylabel(ylabel)
        axis.set_title(title)
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=7)
    timing = [next(iter(points)) for _, points in sorted(grouped(rows, "scheme").items())]
    ms, spread = time_bars(timing)
    axes[2].bar([r["scheme"] for r in timing], ms, yerr=spread, capsize=4, color=[COLORS[schemes.index(r["scheme"])] for r in timing])
    axes[2].set_ylabel("time per dispatch (ms; bars: min to max)")
    axes[2].set_title("Cost (same points; 6 against 4 evaluations)")
    axes[2].grid(True, axis="y", alpha=0.3)
    finish(fig, path)


def plot_audit(rows, path):
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    fields = sorted({r["sdf"] for r in rows})
    for (sdf,), points in sorted(grouped(rows, "sdf").items()):
        points.sort(key=lambda r: float(r["samples"]))
        color = COLORS[fields.index(sdf)]
        n = floats(points, "samples")
        ratio = floats(points, "ratio_median")
        low = [m - float(r["ratio_min"]) for m, r in zip(ratio, points)]
        high = [float(r["ratio_max"]) - m for m, r in zip(ratio, points)]
        axes[0].errorbar(n, ratio, yerr=[low, high], color=color, marker="o", capsize=3, label=f"{sdf}: estimate (99.9th pct.)")
        axes[0].plot(n, floats(points, "max_ratio_median"), color=color, marker="^", linestyle=":", alpha=0.7,
                     label=f"{sdf}: largest quotient seen")
        seconds, spread = time_bars(points, "seconds")
        axes[1].errorbar(seconds, ratio, xerr=spread, yerr=[low, high], color=color, marker="o", capsize=3, label=f"{sdf}: estimate")
    axes[0].set_xlabel("random points N (as many near-surface and surface points)")
    axes[1].set_xlabel("audit time (s; median, bars: min to max over seeds)")
    for axis in axes:
        axis.set_xscale("log")
        axis.axhline(1.0, color="grey", linestyle="--", linewidth=1)
        axis.set_ylabel("Lipschitz estimate / true constant (bars: min to max over seeds)")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=7)
    axes[0].set_title("Audit: Lipschitz estimate against samples")
    axes[1].set_title("Audit: Lipschitz estimate against time")
    finish(fig, path)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    folder, images = sys.argv[1], sys.argv[2]
    os.makedirs(images, exist_ok=True)
    plot_tracer(read(folder, "tracer.csv"), os.path.join(images, "bench_tracer.png"))
    plot_samplers(read(folder, "samplers.csv"), os.path.join(images, "bench_samplers.png"))
    plot_gradients(read(folder, "gradients.csv"), os.path.join(images, "bench_gradients.png"))
    plot_audit(read(folder, "audit.csv"), os.path.join(images, "bench_audit.png"))


if __name__ == "__main__":
    main()
