# Type stubs for sdfwb._native, the pybind11 module built from python/module.cpp and the files beside it.
#
# Every function of the module is here with its exact parameter names and defaults (the docstrings in
# python/*.cpp say what each one takes); python/tests/test_package.py compares them with the signatures
# pybind11 writes into the native docstrings, so the two cannot drift apart. The TypedDicts describe the
# dicts the functions return (the same test compares their keys with the dicts); they exist for type
# checkers only (import them under TYPE_CHECKING).

from collections.abc import Mapping, Sequence
from typing import Any, NotRequired, TypedDict, type_check_only

import numpy as np
import numpy.typing as npt

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

__version__: str

# A parameter value given to an SDF: a bool, a number (int or float), or 1 to 4 numbers for a vector.
ParamValue = bool | float | Sequence[float]
# A parameter value as the functions return it: bools as bool, int parameters as int, scalars as
# float, vectors as tuples of floats.
ParamSetting = bool | int | float | tuple[float, ...]

@type_check_only
class SampleResult(TypedDict):
    position: npt.NDArray[np.float32]
    distance: npt.NDArray[np.float32]
    gradient: npt.NDArray[np.float32]
    bad_rows: int
    seconds: float
    parameters: dict[str, ParamSetting]
    mesh_source: dict[str, Any] | None

@type_check_only
class EvaluateResult(TypedDict):
    distance: npt.NDArray[np.float32]
    gradient: npt.NDArray[np.float32] | None
    bad_rows: int
    seconds: float
    mesh_source: dict[str, Any] | None
    mesh_nodes: dict[str, int] | None

@type_check_only
class SampleMetadata(TypedDict):
    sdf: str
    pattern: str
    seed: int
    time: float
    first_index: int
    total_count: int
    version: str
    parameters: NotRequired[dict[str, Any]]

@type_check_only
class LoadResult(TypedDict):
    position: npt.NDArray[np.float32]
    distance: npt.NDArray[np.float32]
    gradient: npt.NDArray[np.float32]
    metadata: NotRequired[SampleMetadata]

@type_check_only
class MeshResult(TypedDict):
    vertices: npt.NDArray[np.float32]
    faces: npt.NDArray[np.uint32]
    report: dict[str, Any]

@type_check_only
class ParameterInfo(TypedDict):
    name: str
    type: str
    default: list[float]
    minimum: float | None
    maximum: float | None
    step: float | None
    log: bool
    color: bool
    label: str
    line: int
    column: int

@type_check_only
class ParamsReport(TypedDict):
    sdf: str
    parameters: list[ParameterInfo]
    warnings: list[str]

@type_check_only
class SdfEntry(TypedDict):
    name: str
    category: str
    declared_type: str
    animated: bool
    path: str
    author: str
    license: str

def sample(
    sdf: str,
    pattern: str,
    n: int,
    seed: int = 0,
    time: float = 0.0,
    gradient_step: float = 0.0,
    chunk: int = 0,
    surface_tolerance: float = 1e-5,
    entry: str = "",
    params: Mapping[str, ParamValue] | None = None,
    first_index: int = 0,
    near_widths: str = "",
    near_truncate: float = 0.0,
    sign: str = "",
    normalize: str = "",
    level: float = 0.0,
) -> SampleResult: ...
def evaluate(
    sdf: str,
    points: npt.ArrayLike,
    params: Mapping[str, ParamValue] | None = None,
    time: float = 0.0,
    gradient: bool = True,
    gradient_step: float = 0.0,
    entry: str = "",
    chunk: int = 0,
    sign: str = "",
    normalize: str = "",
    level: float = 0.0,
) -> EvaluateResult: ...
def _forget_context_after_fork() -> None: ...
def _job_kinds() -> list[tuple[str, bool, str]]: ...
def load(path: str) -> LoadResult: ...
def save(
    path: str,
    position: npt.ArrayLike,
    distance: npt.ArrayLike,
    gradient: npt.ArrayLike,
    format: str = "",
    sdf: str = "",
    pattern: str = "",
    seed: int = 0,
    time: float = 0.0,
) -> None: ...
def audit(
    sdf: str,
    samples: int = 100000,
    seed: int = 0,
    time: float = 0.0,
    entry: str = "",
    truncation_reach: float = 3.0,
    params: Mapping[str, ParamValue] | None = None,
    sign: str = "",
    normalize: str = "",
    level: float = 0.0,
    probe_distance: float | None = None,
) -> dict[str, Any]: ...
def run(request: dict[str, Any] | str) -> dict[str, Any]: ...
def params(sdf: str, entry: str = "") -> ParamsReport: ...
def mesh(
    sdf: str,
    resolution: int = 128,
    bounds: Sequence[float] | None = None,
    time: float = 0.0,
    lipschitz: float | None = None,
    error_samples: int = 0,
    seed: int = 0,
    entry: str = "",
    params: Mapping[str, ParamValue] | None = None,
    sign: str = "",
    normalize: str = "",
    level: float = 0.0,
    refine: int = 0,
) -> MeshResult: ...
def evaluate_mesh(
    mesh: str,
    sdf: str,
    tau: float = 0.01,
    points: int = 100000,
    occupancy_resolution: int = 128,
    edge_radius: float = 0.02,
    edge_angle: float = 30.0,
    seed: int = 0,
    time: float = 0.0,
    entry: str = "",
    params: Mapping[str, ParamValue] | None = None,
) -> dict[str, Any]: ...
def list_sdfs() -> list[SdfEntry]: ...
