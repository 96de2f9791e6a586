"""Sampling recipes: patterns mixed by ratio, occupancy labels, float16 storage, and named layouts that follow
published descriptions. Every file written carries its recipe, seed, parameters, bounds and normalisation in
an `sdfwb_metadata` entry (a JSON string), and a recipe warns when the surface leaves its sampling box.

    rows = sdfwb.recipes.mix("Torus", {"rand": 1, "near": 4}, 100000, seed=3, occupancy=True)
    sdfwb.recipes.deepsdf("Torus", "torus.npz")      # pos / neg (N, 4): x, y, z, sdf
    sdfwb.recipes.occnet("Torus", "points.npz")      # points (float16), occupancies (packed bits), loc, scale
"""

from __future__ import annotations

import json
import os
import tempfile
import warnings
import zipfile
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, BinaryIO, NotRequired, TypedDict, Union, cast

import numpy as np
import numpy.typing as npt

from . import _native

if TYPE_CHECKING:
    from ._native import ParamValue

__all__ = ["DEEPSDF", "OCCNET", "MixResult", "atomic_write", "deepsdf", "metadata_of", "mix", "occnet", "save_npz",
           "surface_leaves_box"]

# A part of a mix: (pattern, ratio) or (pattern, ratio, options for sdfwb.sample).
_Part = Union[tuple[str, float], tuple[str, float, Mapping[str, Any]]]


class MixResult(TypedDict):
    """What mix() returns: position (n, 3), distance (n,), gradient (n, 3) in mix's dtype, part (n,) (the row's
    part index), occupancy (n,) bool when asked for, and metadata."""

    position: npt.NDArray[np.floating[Any]]
    distance: npt.NDArray[np.floating[Any]]
    gradient: npt.NDArray[np.floating[Any]]
    part: npt.NDArray[np.uint8]
    occupancy: NotRequired[npt.NDArray[np.bool_]]
    metadata: dict[str, Any]


DEEPSDF = (
    "DeepSDF (Park et al., CVPR 2019, Sec. 5 and its PreprocessMesh tool): 500,000 points per shape, 47/50 of them "
    "surface points moved by Gaussian noise of variance 0.005 or 0.0005 (standard deviations 0.0707 and 0.0224, "
    "in equal parts), 3/50 uniform in the bounding cube [-1, 1]^3; stored as pos (sdf > 0) and neg (sdf <= 0) "
    "float32 arrays of rows x, y, z, sdf. Coordinates are the SDF's own (it is already in the unit cube; no "
    "mesh normalisation applies)."
)
OCCNET = (
    "Occupancy Networks (Mescheder et al., CVPR 2019, Sec. 4 and its sample_mesh.py): 100,000 points uniform in the "
    "unit cube of the normalised shape padded by 10 % on each side (padding 0.1), stored as points (float16), "
    "occupancies as packed bits (numpy.packbits, 1 = inside), and the normalisation loc (3,) and scale, where "
    "world = points * scale + loc."
)


def _part_seed(seed: int, part: int) -> int:
    # splitmix64 of (seed, part): each part of a mix draws from its own random streams.
    z = (int(seed) + 0x9E3779B97F4A7C15 * (part + 1)) & 0xFFFFFFFFFFFFFFFF
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & 0xFFFFFFFFFFFFFFFF
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & 0xFFFFFFFFFFFFFFFF
    return z ^ (z >> 31)


def _counts(ratios: Sequence[float], n: int) -> list[int]:
    # Largest remainder: the counts sum to n exactly and follow the ratios as closely as integers can.
    total = float(sum(ratios))
    exact = [n * r / total for r in ratios]
    counts = [int(e) for e in exact]
    for k in sorted(range(len(ratios)), key=lambda k: exact[k] - counts[k], reverse=True)[: n - sum(counts)]:
        counts[k] += 1
    return counts


def surface_leaves_box(sdf: str, bounds: Sequence[float] = (-1, -1, -1, 1, 1, 1), resolution: int = 64,
                       params: Mapping[str, ParamValue] | None = None, time: float = 0.0, entry: str = "",
                       sign: str = "", normalize: str = "") -> float:
    """The fraction of a resolution^2 grid on each face of the box where the field is negative (inside the
    shape): 0 when the surface stays inside the box.

    Args:
        sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sdfwb.sample.
        bounds (Sequence[float]): the box, (minx, miny, minz, maxx, maxy, maxz). Default [-1, 1]^3.
        resolution (int): >= 1, grid points per side of each face. Default 64.
        params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sdfwb.sample.
            Default None: the declared defaults.
        time (float): seconds, for animated SDFs. Default 0.
        entry (str): the SDF's function when it is not `sdf`, as for sdfwb.sample. Default ''.
        sign (str): a mesh SDF's inside test, as for sdfwb.sample. Default '': winding numbers.
        normalize (str): a mesh SDF's scaling, as for sdfwb.sample. Default '': none.

    Returns:
        float: the fraction, 0 to 1.

    Raises:
        ValueError, TypeError, RuntimeError: as sdfwb.evaluate raises them.
    """
    lo, hi = np.array(bounds[:3], np.float32), np.array(bounds[3:], np.float32)
    u = (np.arange(resolution, dtype=np.float32) + 0.5) / resolution
    a, b = [g.ravel() for g in np.meshgrid(u, u, indexing="ij")]
    faces = []
    for axis in range(3):
        for side in (lo[axis], hi[axis]):
            p = np.empty((a.size, 3), np.float32)
            others = [k for k in range(3) if k != axis]
            p[:, axis] = side
            p[:, others[0]] = lo[others[0]] + a * (hi[others[0]] - lo[others[0]])
            p[:, others[1]] = lo[others[1]] + b * (hi[others[1]] - lo[others[1]])
            faces.append(p)
    values = _native.evaluate(sdf, np.concatenate(faces), params, time, False, 1e-3, entry, 1 << 18, sign,
                              normalize)["distance"]
    return float(np.mean(values < 0.0))


def _warn_if_outside(sdf: str, bounds: Sequence[float], params: Mapping[str, ParamValue] | None, time: float,
                     entry: str, mesh: Mapping[str, Any]) -> float:
    fraction = surface_leaves_box(sdf, bounds, params=params, time=time, entry=entry, sign=mesh.get("sign", ""),
                                  normalize=mesh.get("normalize", ""))
    if fraction > 0.0:
        warnings.warn(f"{sdf if len(sdf) < 80 else 'the SDF'}: the surface leaves the sampling box {tuple(bounds)} "
                      f"(the field is negative on {100 * fraction:.2f} % of its faces): samples miss part of the shape",
                      RuntimeWarning, stacklevel=3)
    return fraction


def mix(sdf: str, parts: Mapping[str, float] | Sequence[_Part], n: int, seed: int = 0, occupancy: bool = False,
        dtype: npt.DTypeLike = np.float32, params: Mapping[str, ParamValue] | None = None, time: float = 0.0,
        entry: str = "", shuffle: bool = False, bounds: Sequence[float] = (-1, -1, -1, 1, 1, 1)) -> MixResult:
    """`n` samples from several patterns by ratio. Counts follow the ratios by largest remainder; each part has its
    own seed derived from `seed`. Warns (RuntimeWarning) when the surface leaves `bounds`.

    Args:
        sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sdfwb.sample.
        parts (Mapping[str, float] | Sequence[tuple]): {pattern: ratio}, or a list of (pattern, ratio) or
            (pattern, ratio, options) with options for sdfwb.sample (e.g. {"near_widths": "0.005:0.5,0.05:0.5"});
            at least one part, every ratio > 0 (part indices are stored as uint8: up to 256 parts).
        n (int): >= 1, the total number of rows.
        seed (int): >= 0. Default 0.
        occupancy (bool): also return `occupancy`. Default False.
        dtype (numpy dtype): float32 or float16 (halves storage) for position, distance and gradient.
            Default float32.
        params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sdfwb.sample.
            Default None: the declared defaults.
        time (float): seconds, for animated SDFs. Default 0.
        entry (str): the SDF's function when it is not `sdf`, as for sdfwb.sample. Default ''.
        shuffle (bool): shuffle the rows (by a generator seeded with `seed`) instead of keeping the parts in
            order. Default False.
        bounds (Sequence[float]): the sampling box checked for the surface leaving it, (minx, miny, minz, maxx,
            maxy, maxz); recorded in the metadata. Default [-1, 1]^3.

    Returns:
        dict: position (n, 3), distance (n,), gradient (n, 3) in `dtype`; part (n,) uint8, the row's part index;
        occupancy (n,) bool (inside = distance < 0) when asked; metadata (recipe, seed, parts with their counts
        and seeds, parameters, bounds, normalisation, dtype, surface_outside_box, sampling_seconds, version).

    Raises:
        ValueError: no parts, a ratio <= 0, another dtype, or what sdfwb.sample raises.
        TypeError, RuntimeError: as sdfwb.sample raises them.
    """
    given: list[Any] = list(parts.items()) if isinstance(parts, Mapping) else list(parts)
    items: list[tuple[str, float, Mapping[str, Any]]] = [(p[0], p[1], p[2] if len(p) > 2 else {}) for p in given]
    if not items or any(r <= 0 for _, r, _ in items):
        raise ValueError("mix: give at least one pattern, every ratio positive")
    if np.dtype(dtype) not in (np.float32, np.float16):
        raise ValueError("mix: dtype must be float32 or float16")
    counts = _counts([r for _, r, _ in items], int(n))
    # A mesh's sign and normalisation, as the parts give them (the first part's; parts that differ make no sense).
    mesh = {key: items[0][2][key] for key in ("sign", "normalize") if key in items[0][2]}
    fraction = _warn_if_outside(sdf, bounds, params, time, entry, mesh)
    out: dict[str, list[npt.NDArray[Any]]] = {"position": [], "distance": [], "gradient": [], "part": []}
    parameters: dict[str, Any] = {}
    seconds = 0.0
    for k, ((pattern, _, options), count) in enumerate(zip(items, counts)):
        if count == 0:
            continue
        rows = _native.sample(sdf, pattern, count, seed=_part_seed(seed, k), time=time, entry=entry, params=params,
                              **options)
        out["position"].append(rows["position"])
        out["distance"].append(rows["distance"])
        out["gradient"].append(rows["gradient"])
        out["part"].append(np.full(count, k, np.uint8))
        parameters, seconds = rows["parameters"], seconds + rows["seconds"]
    result: dict[str, Any] = {key: np.concatenate(values) for key, values in out.items()}
    if shuffle:
        order = np.random.default_rng(seed).permutation(len(result["distance"]))
        result = {key: values[order] for key, values in result.items()}
    if occupancy:
        result["occupancy"] = result["distance"] < 0.0
    for key in ("position", "distance", "gradient"):
        result[key] = result[key].astype(dtype, copy=False)
    result["metadata"] = {
        "recipe": "mix", "sdf": sdf, "entry": entry, "seed": int(seed), "time": float(time), "n": int(n),
        "parts": [{"pattern": p, "ratio": r, "count": c, "seed": _part_seed(seed, k), **o}
                  for k, ((p, r, o), c) in enumerate(zip(items, counts))],
        "parameters": parameters, "bounds": list(bounds), "normalisation": {"loc": [0.0, 0.0, 0.0], "scale": 1.0},
        "dtype": np.dtype(dtype).name, "occupancy": bool(occupancy), "surface_outside_box": fraction,
        "sampling_seconds": seconds, "version": _native.__version__,
    }
    return cast(MixResult, result)


def atomic_write(path: str, write: Callable[[BinaryIO], object]) -> None:
    """Calls write(stream) on a temporary file beside `path` (named .NAME.partial-XXXXXXXX, as the C++ writers
    name theirs, so `sdfwb --batch run` can clear what a killed item left), syncs it and renames it into place
    (mode 0644). Nothing is left behind when write raises.

    Args:
        path (str): the file to write; its folder must exist.
        write (Callable[[BinaryIO], object]): writes the content to the binary stream it is given.

    Returns:
        None

    Raises:
        OSError: the file cannot be created, written or renamed; and whatever write raises.
    """
    folder = os.path.dirname(os.path.abspath(path))
    handle, temporary = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".partial-", dir=folder)
    try:
        with os.fdopen(handle, "wb") as stream:
            write(stream)
            stream.flush()
            os.fsync(stream.fileno())
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def save_npz(path: str, arrays: Mapping[str, npt.ArrayLike], metadata: Mapping[str, Any]) -> None:
    """Writes arrays and the metadata (as the JSON string `sdfwb_metadata`) as an .npz that np.load reads, atomically
    (atomic_write). The same arrays and metadata give the same bytes: members carry a fixed date, unlike np.savez's,
    so reruns and resumed runs can be compared (and deduplicated) by content.

    Args:
        path (str): the .npz file to write; its folder must exist.
        arrays (Mapping[str, array_like]): the members, by name (no object arrays).
        metadata (Mapping[str, Any]): JSON-serialisable values, stored as the member `sdfwb_metadata`.

    Returns:
        None

    Raises:
        TypeError: metadata that json cannot write.
        ValueError: an object array (pickles are not written).
        OSError: the file cannot be written.
    """
    members = dict(arrays, sdfwb_metadata=np.array(json.dumps(metadata)))

    def write(stream: BinaryIO) -> None:
        with zipfile.ZipFile(stream, "w", zipfile.ZIP_STORED, allowZip64=True) as archive:
            for key, value in members.items():
                info = zipfile.ZipInfo(key + ".npy", date_time=(1980, 1, 1, 0, 0, 0))
                with archive.open(info, "w", force_zip64=True) as member:
                    array = np.asanyarray(value)
                    # numpy types np.lib.format's functions as untyped
                    np.lib.format.write_array(member, array, allow_pickle=False)  # type: ignore[no-untyped-call]

    atomic_write(path, write)


def metadata_of(path: str) -> dict[str, Any]:
    """The metadata dict a recipe wrote into `path`.

    Args:
        path (str): an .npz written by save_npz (mix's rows saved with it, deepsdf, occnet).

    Returns:
        dict: the `sdfwb_metadata` member, decoded from JSON.

    Raises:
        OSError: the file cannot be read.
        KeyError: the file has no `sdfwb_metadata` member.
    """
    with np.load(path) as data:
        metadata: dict[str, Any] = json.loads(str(data["sdfwb_metadata"]))
        return metadata


def deepsdf(sdf: str, path: str, n: int = 500000, seed: int = 0, params: Mapping[str, ParamValue] | None = None,
            time: float = 0.0, entry: str = "", sign: str = "", normalize: str = "") -> dict[str, Any]:
    """Writes a DeepSDF-style .npz (see DEEPSDF for the description it follows): pos (sdf > 0) and neg (sdf <= 0),
    float32 (N, 4) rows x, y, z, sdf. Rows that are not finite (near rays that found no surface) are dropped.

    Args:
        sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sdfwb.sample.
        path (str): the .npz file to write (atomically); its folder must exist.
        n (int): >= 1, points before dropping non-finite rows. Default 500000 (DeepSDF's).
        seed (int): >= 0. Default 0.
        params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sdfwb.sample.
            Default None: the declared defaults.
        time (float): seconds, for animated SDFs. Default 0.
        entry (str): the SDF's function when it is not `sdf`, as for sdfwb.sample. Default ''.
        sign (str): a mesh SDF's inside test (winding, parity or pseudonormal), as for sdfwb.sample. Default '':
            winding numbers.
        normalize (str): a mesh SDF's scaling (none, unit-cube or unit-sphere), as for sdfwb.sample. Default '':
            none. On a mesh the near points are drawn on its triangles (docs/mesh-sdf.md).

    Returns:
        dict: the metadata written into the file (see metadata_of), with rows_dropped, plus sampling_seconds.

    Raises:
        ValueError, TypeError, RuntimeError: as sdfwb.sample raises them; OSError when the file cannot be written.
    """
    near = "%.6g:1,%.6g:1" % (0.005 ** 0.5, 0.0005 ** 0.5)
    mesh = {key: value for key, value in (("sign", sign), ("normalize", normalize)) if value}
    rows = mix(sdf, [("near", 47, dict(mesh, near_widths=near)), ("rand", 3, mesh)], n, seed=seed, params=params,
               time=time, entry=entry)
    table = np.concatenate([rows["position"], rows["distance"][:, None]], axis=1).astype(np.float32)
    table = table[np.isfinite(table).all(axis=1)]  # a near ray that found no surface is a NaN row
    positive = table[:, 3] > 0.0
    metadata = dict(rows["metadata"], recipe="deepsdf", description=DEEPSDF, rows_dropped=int(n - len(table)))
    seconds = metadata.pop("sampling_seconds")  # a timing, not a property of the data: kept out of the file
    save_npz(path, {"pos": table[positive], "neg": table[~positive]}, metadata)
    return dict(metadata, sampling_seconds=seconds)


def occnet(sdf: str, path: str, n: int = 100000, seed: int = 0, padding: float = 0.1,
           params: Mapping[str, ParamValue] | None = None, time: float = 0.0, entry: str = "",
           bounds: Sequence[float] = (-1, -1, -1, 1, 1, 1)) -> dict[str, Any]:
    """Writes an Occupancy-Networks-style points .npz (see OCCNET for the description it follows): points (n, 3)
    float16 in the normalised unit cube, occupancies (numpy.packbits of inside = distance < 0), loc (3,) and
    scale, where world = points * scale + loc. Warns (RuntimeWarning) when the surface leaves `bounds`.

    Args:
        sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sdfwb.sample.
        path (str): the .npz file to write (atomically); its folder must exist.
        n (int): >= 1, points. Default 100000 (Occupancy Networks').
        seed (int): >= 0, seeds numpy.random.default_rng. Default 0.
        padding (float): >= 0, the unit cube's padding: points are uniform in [-(1 + padding) / 2,
            (1 + padding) / 2]^3. Default 0.1.
        params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sdfwb.sample.
            Default None: the declared defaults.
        time (float): seconds, for animated SDFs. Default 0.
        entry (str): the SDF's function when it is not `sdf`, as for sdfwb.sample. Default ''.
        bounds (Sequence[float]): the shape's box (minx, miny, minz, maxx, maxy, maxz): loc is its centre, scale its
            longest side. Default [-1, 1]^3.

    Returns:
        dict: the metadata written into the file (see metadata_of), plus sampling_seconds.

    Raises:
        ValueError, TypeError, RuntimeError: as sdfwb.evaluate raises them; OSError when the file cannot be written.
    """
    lo, hi = np.array(bounds[:3], np.float64), np.array(bounds[3:], np.float64)
    loc, scale = (lo + hi) / 2.0, float(np.max(hi - lo))
    fraction = _warn_if_outside(sdf, bounds, params, time, entry, {})
    rng = np.random.default_rng(seed)
    normalised = ((rng.random((int(n), 3)) - 0.5) * (1.0 + padding)).astype(np.float16)
    world = (normalised.astype(np.float32) * np.float32(scale) + loc.astype(np.float32)).astype(np.float32)
    values = _native.evaluate(sdf, world, params, time, False, 1e-3, entry, 1 << 18)
    inside = values["distance"] < 0.0
    metadata = {
        "recipe": "occnet", "description": OCCNET, "sdf": sdf, "entry": entry, "seed": int(seed), "time": float(time),
        "n": int(n), "padding": float(padding), "parameters": params or {}, "bounds": list(bounds),
        "normalisation": {"loc": loc.tolist(), "scale": scale}, "surface_outside_box": fraction,
        "inside_fraction": float(inside.mean()), "version": _native.__version__,
    }
    save_npz(path, {"points": normalised, "occupancies": np.packbits(inside), "loc": loc.astype(np.float32),
                    "scale": np.float32(scale)}, metadata)
    return dict(metadata, sampling_seconds=values["seconds"])
