#!/usr/bin/env python3
"""Every sampling pattern on a mesh's own field, run through the CLI as a user runs it, with Mesa's
shader cache off (each run compiles its program cold): the rows a second of the sampling, the set-up
(mesh, hierarchy, shader compile), the bad rows, and where the rows lie (the share within 0.01 and
0.05 of the surface, the median |f|). metropolis_curvature runs twice on llvmpipe: as shipped (its
chains in passes of 8 steps) and in one pass (SDFWB_CHAIN_PASS_STEPS=0), where the driver's loop
budget cuts chains; a cut chain is a bad row. Prints Markdown; scripts/sampling_throughput calls it.

    bench/mesh_patterns.py [MESH_FOLDER]
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SDFWB = os.path.join(ROOT, "build", "app", "sdfwb")
MESHES = sys.argv[1] if len(sys.argv) > 1 else os.path.normpath(os.path.join(ROOT, "..", "shared", "data", "meshes"))
PATTERNS = ["grid", "image", "jitter", "rand", "surface", "near", "metropolis", "metropolis_curvature"]
ROWS = {"metropolis": 10000, "metropolis_curvature": 10000}  # the chains: 160 steps a row
DEFAULT_ROWS = 200000


def run(mesh, pattern, rows, work, extra_env=None):
    out = os.path.join(work, "rows.npz")
    env = dict(os.environ, MESA_SHADER_CACHE_DISABLE="true")
    env.pop("DISPLAY", None)
    env.update(extra_env or {})
    command = [SDFWB, "--batch", "sample", "--sdf", mesh, "--normalize", "unit-cube", "--pattern", pattern,
               "-n", str(rows), "--output", out, "--json", "--quiet"]
    done = subprocess.run(command, env=env, capture_output=True, text=True, check=True)
    report = json.loads(done.stdout)
    distance = np.abs(np.load(out)["distance"])
    finite = distance[np.isfinite(distance)]
    os.remove(out)
    return {
        "rows": rows,
        "rate": rows / report["seconds"],
        "setup": report["setup_seconds"],
        "bad": report["bad_rows"],
        "within_001": float(np.mean(finite < 0.01)) if finite.size else float("nan"),
        "within_005": float(np.mean(finite < 0.05)) if finite.size else float("nan"),
        "median": float(np.median(finite)) if finite.size else float("nan"),
        "renderer": report["gl_renderer"],
    }


def main():
    meshes = [("spot", "spot.obj"), ("stanford-bunny", "stanford-bunny.obj")]
    lines = []
    renderer = ""
    with tempfile.TemporaryDirectory() as work:
        for name, file in meshes:
            path = os.path.join(MESHES, file)
            runs = [(pattern, "", {}) for pattern in PATTERNS]
            runs.append(("metropolis_curvature", " (one pass)", {"SDFWB_CHAIN_PASS_STEPS": "0"}))
            for pattern, label, env in runs:
                r = run(path, pattern, ROWS.get(pattern, DEFAULT_ROWS), work, env)
                renderer = r["renderer"]
                shares = "- | - | -" if r["bad"] == r["rows"] else (
                    f"{100 * r['within_001']:.1f} % | {100 * r['within_005']:.1f} % | {r['median']:.4f}")
                lines.append(f"| {name} | {pattern}{label} | {r['rows']:,} | {r['rate']:,.0f} | {r['setup']:.2f} | "
                             f"{r['bad']:,} | {shares} |")
                print(f"{name} {pattern}{label}: {r}", file=sys.stderr, flush=True)
    print("Each pattern on a mesh's own field (`--sdf MESH --normalize unit-cube`), through the CLI, "
          f"Mesa's shader cache off ({renderer}). Rows a second: the sampling and writing, after the set-up; "
          "set-up: the mesh, its hierarchy and the shader's compile. A bad row is NaN (a ray that missed, a chain "
          "the driver cut). The metropolis patterns target exp(-|f|/0.01): most rows within a few hundredths.")
    print()
    print("| mesh | pattern | rows | rows/s | set-up (s) | bad rows | \\|f\\| < 0.01 | \\|f\\| < 0.05 | median \\|f\\| |")
    print("|---|---|---|---|---|---|---|---|---|")
    for line in lines:
        print(line)


if __name__ == "__main__":
    main()
