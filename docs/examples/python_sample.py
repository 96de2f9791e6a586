#!/usr/bin/env python3
"""Samples a dataset shape with the Python module and plots a slice of the points.

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/python_sample.py [OUTPUT.png]

Runs headless (EGL): no display needed. Trains nothing; shows what a data loader gets.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import sdfwb

output = sys.argv[1] if len(sys.argv) > 1 else "python_sample.png"

near = sdfwb.sample("torus", "near", 400_000, seed=0)
uniform = sdfwb.sample("torus", "rand", 400_000, seed=0)
for name, batch in (("near", near), ("rand", uniform)):
    print(f"{name}: position {batch['position'].shape} {batch['position'].dtype}, distance {batch['distance'].shape}, "
          f"gradient {batch['gradient'].shape}, {batch['bad_rows']} bad rows, {batch['seconds']:.2f} s")

# A slab |z| < 0.02 through the middle: near-surface points coloured by the raw gradient (as RGB),
# uniform points coloured by the signed distance.
fig, axes = plt.subplots(1, 2, figsize=(11, 5))
slab = np.abs(near["position"][:, 2]) < 0.02
p, g = near["position"][slab], near["gradient"][slab]
axes[0].scatter(p[:, 0], p[:, 1], s=1, c=np.clip(g * 0.5 + 0.5, 0, 1))
axes[0].set_title(f"near, |z| < 0.02 ({slab.sum()} points): gradient as RGB", fontsize=10)
slab = np.abs(uniform["position"][:, 2]) < 0.02
p, d = uniform["position"][slab], uniform["distance"][slab]
image = axes[1].scatter(p[:, 0], p[:, 1], s=2, c=d, cmap="coolwarm", vmin=-0.3, vmax=0.3)
axes[1].set_title(f"rand, |z| < 0.02 ({slab.sum()} points): distance", fontsize=10)
fig.colorbar(image, ax=axes[1], label="signed distance")
for axis in axes:
    axis.set_aspect("equal")
    axis.set_xlim(-1, 1)
    axis.set_ylim(-1, 1)
    axis.set_xlabel("x")
    axis.set_ylabel("y")
fig.tight_layout()
fig.savefig(output, dpi=100)
print("wrote", output)
