"""sdfwb: sample, evaluate, audit and mesh signed distance functions written in GLSL (headless, EGL).

The functions live in the native module `sdfwb._native` and are re-exported here. `evaluate` also takes
and returns CPU torch tensors (without copies) when torch is installed; torch is never imported unless a
tensor is passed. Optional adapter: `sdfwb.torch` (SampleStream, an IterableDataset). Recipes (mixtures,
DeepSDF and Occupancy Networks layouts): `sdfwb.recipes`.
"""

import os as _os

from . import _native, recipes  # noqa: F401  (recipes needs numpy only)
from ._native import *  # noqa: F401,F403  (the native functions are the package's API)
from ._native import __version__  # noqa: F401

# A forked child (a DataLoader worker, a Dask nanny) must not use the parent's EGL context: it
# makes its own on first use.
_os.register_at_fork(after_in_child=_native._forget_context_after_fork)


def _is_torch_tensor(value):
    return type(value).__module__.split(".")[0] == "torch" and hasattr(value, "numpy")


def evaluate(sdf, points, params=None, time=0.0, gradient=True, gradient_step=1e-3, entry="", chunk=1 << 18):
    if _is_torch_tensor(points):
        import torch

        if points.device.type != "cpu":
            raise ValueError(f"evaluate: points must be a CPU tensor, not one on {points.device}")
        result = _native.evaluate(sdf, points.detach().numpy(), params, time, gradient, gradient_step, entry, chunk)
        result["distance"] = torch.from_numpy(result["distance"])
        if result["gradient"] is not None:
            result["gradient"] = torch.from_numpy(result["gradient"])
        return result
    return _native.evaluate(sdf, points, params, time, gradient, gradient_step, entry, chunk)


evaluate.__doc__ = (
    "evaluate(sdf, points, params=None, time=0.0, gradient=True, gradient_step=1e-3, entry='', chunk=262144) -> dict\n\n"
    + _native.evaluate.__doc__.split("\n\n", 1)[-1]
    + "\nA CPU torch tensor in gives tensors out that share the returned arrays' memory (float32 C-order input is read\n"
    "in place; anything else is converted once)."
)
