"""Every public function of sdfwb called with correctly typed arguments, its results used as their types say.

Never run (it is not a test_*.py file and nothing calls its functions): test_package.py type-checks it with mypy
against the stubs (sdfwb/_native.pyi) and the package's annotations, which must accept all of it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, BinaryIO

import numpy as np
import numpy.typing as npt
import torch
from distributed import Client

import sdfwb
import sdfwb.dask
import sdfwb.recipes
import sdfwb.torch

if TYPE_CHECKING:
    from sdfwb._native import (EvaluateResult, LoadResult, MeshResult, ParameterInfo, ParamsReport, SampleMetadata,
                               SampleResult, SdfEntry)


def native(path: str, glsl: str) -> list[object]:
    version: str = sdfwb.__version__
    rows: SampleResult = sdfwb.sample(
        "Torus", "near", 1000, seed=3, time=0.5, gradient_step=1e-3, chunk=1 << 16, surface_tolerance=1e-5, entry="",
        params={"majorRadius": 0.5, "capped": True, "offset": (0.0, 0.1, 0), "count": 3}, first_index=1000,
        near_widths="0.005:0.8,0.05:0.2", near_truncate=3.0)
    position: npt.NDArray[np.float32] = rows["position"]
    distance: npt.NDArray[np.float32] = rows["distance"]
    bad_rows: int = rows["bad_rows"]
    seconds: float = rows["seconds"]
    radius = rows["parameters"]["majorRadius"]
    again = sdfwb.sample(glsl, "rand", 10, params=rows["parameters"])  # the values a result holds go back in

    field: EvaluateResult = sdfwb.evaluate("Torus", position, params=None, time=0.0, gradient=False,
                                           gradient_step=1e-3, entry="", chunk=1024)
    gradient: npt.NDArray[np.float32] | None = field["gradient"]
    if gradient is not None:
        gradient = gradient / np.linalg.norm(gradient, axis=1, keepdims=True)
    from_lists = sdfwb.evaluate("Sphere", [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])["distance"]
    from_float64 = sdfwb.evaluate("Sphere", np.zeros((4, 3)))["distance"]
    tensors: dict[str, Any] = sdfwb.evaluate("Sphere", torch.zeros((4, 3)))

    sdfwb.save(path, rows["position"], rows["distance"], rows["gradient"], format="npz", sdf="Torus", pattern="near",
               seed=3, time=0.5)
    loaded: LoadResult = sdfwb.load(path)
    seed: int | None = None
    if "metadata" in loaded:
        metadata: SampleMetadata = loaded["metadata"]
        seed = metadata["seed"] + len(metadata["pattern"])

    report: dict[str, Any] = sdfwb.audit("Torus", samples=1000, seed=1, time=0.0, entry="", truncation_reach=3.0,
                                         params={"tubeRadius": 0.1})
    verdict = report["verdict"]
    listed = sdfwb.run({"kind": "list"})
    rendered = sdfwb.run('{"kind": "render", "sdf": "torus", "output": "t.png"}')
    declared: ParamsReport = sdfwb.params("Torus", entry="")
    first: ParameterInfo = declared["parameters"][0]
    minimum: float | None = first["minimum"]
    mesh: MeshResult = sdfwb.mesh("Torus", resolution=64, bounds=(-1, -1, -1, 1, 1, 1), time=0.0, lipschitz=1.5,
                                  error_samples=1000, seed=0, entry="", params={"majorRadius": 0.5})
    faces: npt.NDArray[np.uint32] = mesh["faces"]
    graded: dict[str, Any] = sdfwb.evaluate_mesh("torus.ply", "Torus", tau=0.01, points=1000, occupancy_resolution=0,
                                                 seed=0, time=0.0, entry="", params=None)
    entries: list[SdfEntry] = sdfwb.list_sdfs()
    animated: bool = entries[0]["animated"]
    return [version, distance, bad_rows, seconds, radius, again, gradient, from_lists, from_float64, tensors, seed,
            report, verdict, listed, rendered, minimum, faces, graded, animated]


def recipes(folder: str) -> list[object]:
    outside: float = sdfwb.recipes.surface_leaves_box("Torus", bounds=(-1, -1, -1, 1, 1, 1), resolution=32,
                                                      params=None, time=0.0, entry="")
    rows: sdfwb.recipes.MixResult = sdfwb.recipes.mix(
        "Torus", {"rand": 1, "near": 4}, 1000, seed=3, occupancy=True, dtype=np.float16, params={"majorRadius": 0.5},
        time=0.0, entry="", shuffle=True, bounds=[-1.0, -1.0, -1.0, 1.0, 1.0, 1.0])
    listed = sdfwb.recipes.mix("Torus", [("near", 47, {"near_widths": "0.07:1,0.02:1"}), ("rand", 3)], 1000)
    inside: npt.NDArray[np.bool_] | None = rows["occupancy"] if "occupancy" in rows else None
    part: npt.NDArray[np.uint8] = listed["part"]

    def write(stream: BinaryIO) -> None:
        stream.write(b"bytes")

    sdfwb.recipes.atomic_write(folder + "/raw.bin", write)
    sdfwb.recipes.save_npz(folder + "/rows.npz", {"position": rows["position"]}, rows["metadata"])
    metadata: dict[str, Any] = sdfwb.recipes.metadata_of(folder + "/rows.npz")
    deepsdf: dict[str, Any] = sdfwb.recipes.deepsdf("Torus", folder + "/deepsdf.npz", n=1000, seed=0, params=None,
                                                    time=0.0, entry="")
    occnet: dict[str, Any] = sdfwb.recipes.occnet("Torus", folder + "/occnet.npz", n=1000, seed=0, padding=0.1,
                                                  params=None, time=0.0, entry="", bounds=(-1, -1, -1, 1, 1, 1))
    description: str = sdfwb.recipes.DEEPSDF + sdfwb.recipes.OCCNET
    return [outside, inside, part, metadata, deepsdf, occnet, description]


def adapters(client: Client) -> list[object]:
    stream = sdfwb.torch.SampleStream("Torus", pattern="near", batch_size=1024, batches_per_epoch=4, seed=1,
                                      params={"majorRadius": 0.5}, time=0.0, entry="", gradient_step=1e-3, rank=0,
                                      world_size=1)
    stream.set_epoch(2)
    batches: range = stream.batch_indices(worker=0, workers=2)
    positions: list[torch.Tensor] = []
    first_indices: list[int] = []
    for batch in sdfwb.torch.loader(stream, num_workers=2, pin_memory=False):
        positions.append(batch["position"])
        first_indices.append(batch["first_index"])
    states: list[dict[str, Any]] = sdfwb.dask.items("shapes.jsonl", status=None, binary=None)
    summary: sdfwb.dask.ManifestSummary = sdfwb.dask.run_manifest("shapes.jsonl", client, status=None,
                                                                  item_timeout=600.0, binary=None, items_per_task=4)
    done: int = summary["done"]
    return [batches, positions, first_indices, states, done]
