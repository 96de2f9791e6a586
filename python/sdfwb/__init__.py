"""sdfwb: sample, evaluate, audit and mesh signed distance functions written in GLSL (headless, EGL).

The functions live in the native module `sdfwb._native` and are re-exported here; help(sdfwb.sample) and
the others say what each argument takes. `evaluate` also takes and returns CPU torch tensors (without
copies) when torch is installed; torch is never imported unless a tensor is passed. Optional adapters:
`sdfwb.torch` (SampleStream, an IterableDataset) and `sdfwb.dask` (manifests on a Dask cluster). Recipes
(mixtures, DeepSDF and Occupancy Networks layouts): `sdfwb.recipes`.

Type checkers read sdfwb/_native.pyi (the package is marked typed by py.typed); the dicts the functions
return are TypedDicts there (`from sdfwb._native import SampleResult` under typing.TYPE_CHECKING).
"""

from __future__ import annotations

import os as _os
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Protocol, overload

from . import _native
from . import recipes as recipes  # noqa: F401  (NumPy only; the `as` form re-exports it for type checkers)
from ._native import __version__ as __version__  # noqa: F401
from ._native import audit, evaluate_mesh, list_sdfs, load, mesh, params, run, sample, save

if TYPE_CHECKING:
    import numpy.typing as npt

    from ._native import EvaluateResult, ParamValue

__all__ = [
    "audit",
    "evaluate",
    "evaluate_mesh",
    "list_sdfs",
    "load",
    "mesh",
    "params",
    "run",
    "sample",
    "save",
]

# A forked child (a DataLoader worker, a Dask nanny) must not use the parent's EGL context: it
# makes its own on first use.
_os.register_at_fork(after_in_child=_native._forget_context_after_fork)


class _CpuTensor(Protocol):
    """What evaluate needs of a torch.Tensor, named without importing torch."""

    @property
    def device(self) -> Any: ...

    def detach(self) -> Any: ...

    def numpy(self) -> Any: ...


def _is_torch_tensor(value: object) -> bool:
    return type(value).__module__.split(".")[0] == "torch" and hasattr(value, "numpy")


@overload
def evaluate(sdf: str, points: _CpuTensor, params: Mapping[str, ParamValue] | None = None, time: float = 0.0,
             gradient: bool = True, gradient_step: float = 0.0, entry: str = "",
             chunk: int = 0, sign: str = "", normalize: str = "", level: float = 0.0) -> dict[str, Any]: ...


@overload
def evaluate(sdf: str, points: npt.ArrayLike, params: Mapping[str, ParamValue] | None = None, time: float = 0.0,
             gradient: bool = True, gradient_step: float = 0.0, entry: str = "",
             chunk: int = 0, sign: str = "", normalize: str = "", level: float = 0.0) -> EvaluateResult: ...


def evaluate(sdf: str, points: Any, params: Mapping[str, ParamValue] | None = None, time: float = 0.0,
             gradient: bool = True, gradient_step: float = 0.0, entry: str = "",
             chunk: int = 0, sign: str = "", normalize: str = "", level: float = 0.0) -> EvaluateResult | dict[str, Any]:
    """The field of `sdf` at the caller's points, through the samplers' own stage: bit-equal to what the
    samplers write at the same positions with the same gradient_step.

    Args:
        sdf (str): a dataset name (any case, see list_sdfs()), a path to a .glsl file or a triangle mesh
            (.obj .ply .stl .off .glb ...), or GLSL source text (anything containing both '{' and '('), as
            for sample().
        points (array_like or torch.Tensor): shape (N, 3), N <= 4294967295 (N = 0 gives empty arrays);
            float32 C-order arrays are read in place, anything else is converted to float32 once. A CPU
            torch tensor gives tensors out that share the returned arrays' memory.
        params (Mapping[str, bool | float | Sequence[float]] | None): values for the SDF's declared
            parameters, e.g. {'radius': 0.3, 'offset': (0, 0.1, 0)} (sdfwb.params(sdf) lists them).
            Default None: the declared defaults.
        time (float): seconds, finite, for animated SDFs. Default 0.
        gradient (bool): also return the gradient; False evaluates the field once per point instead of
            seven times. Default True.
        gradient_step (float): > 0, world units: the step of the central differences. Default 0: 1e-3,
            except that a mesh's own field gives its exact gradient (from the closest point).
        entry (str): the SDF's function when it is not `sdf` (e.g. 'map'), as for sample(). Default ''.
        chunk (int): points per GPU dispatch, 1 to 33554432; does not change the values. Default 0: chosen
            per driver (262144 on llvmpipe, 2097152 on a GPU).
        sign (str): for a mesh file: 'winding' (generalized winding numbers), 'parity' or 'pseudonormal',
            as for sample(). Default '': winding.
        normalize (str): for a mesh file: 'none', 'unit-cube' or 'unit-sphere', as for sample().
            Default '': none.
        level (float): a GLSL field's surface is where it equals this (the field becomes f - level), as for
            sample(). Default 0.

    Returns:
        dict: distance (N,) float32; gradient (N, 3) float32 (raw central differences), or None when
        gradient=False; bad_rows (int: rows with NaN or Inf); seconds (float); mesh_source (dict for a
        mesh file, as for sample(); None for GLSL). For a tensor in, distance and gradient are torch tensors.

    Raises:
        ValueError: points not of shape (N, 3), a tensor on a device other than the CPU, an argument out of
            range, an unknown SDF or parameter, or GLSL errors (with file:line:column).
        TypeError: params is not a mapping of numbers, bools or sequences of numbers.
        RuntimeError: no EGL/GL, a GPU failure, or a process forked after its parent used the GPU.

    The GIL is released while the GPU works.
    """
    if _is_torch_tensor(points):
        import torch

        if points.device.type != "cpu":
            raise ValueError(f"evaluate: points must be a CPU tensor, not one on {points.device}")
        result: dict[str, Any] = dict(
            _native.evaluate(sdf, points.detach().numpy(), params, time, gradient, gradient_step, entry, chunk, sign,
                             normalize, level))
        result["distance"] = torch.from_numpy(result["distance"])
        if result["gradient"] is not None:
            result["gradient"] = torch.from_numpy(result["gradient"])
        return result
    return _native.evaluate(sdf, points, params, time, gradient, gradient_step, entry, chunk, sign, normalize, level)
