"""PyTorch adapter (optional: needs python3-torch; `import sdfwb` never imports torch).

SampleStream is an IterableDataset of fresh samples made on the fly, no disk in between. Batch g of the
whole run holds the sample indices [g * batch_size, (g + 1) * batch_size); epoch e owns the batches
e * batches_per_epoch ... (e + 1) * batches_per_epoch - 1, and DataLoader worker w of W takes every W-th
of them starting at w. So seed, epoch and worker decide the counter range: batches are deterministic, and
no two workers or epochs repeat a row. Call set_epoch(e) at the start of each epoch (as with
DistributedSampler); rank and world_size split the batches across processes in the same way.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from typing import TYPE_CHECKING, Any, TypedDict

import torch as _torch
from torch.utils.data import IterableDataset as _IterableDataset

from . import _native

if TYPE_CHECKING:
    from ._native import ParamValue

__all__ = ["SampleBatch", "SampleStream", "loader"]


class SampleBatch(TypedDict):
    """One batch of a SampleStream: float32 CPU tensors over the sampled arrays (no copies)."""

    position: _torch.Tensor  # (batch_size, 3)
    distance: _torch.Tensor  # (batch_size,)
    gradient: _torch.Tensor  # (batch_size, 3), raw (not normalised)
    first_index: int  # the batch's first sample index


class SampleStream(_IterableDataset[SampleBatch]):
    """An IterableDataset of fresh samples of one SDF: each item is a whole batch (a SampleBatch dict of
    position, distance, gradient tensors and first_index), made by sdfwb.sample when it is asked for.

    Args:
        sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sdfwb.sample.
        pattern (str): the sampling pattern, as for sdfwb.sample. Default 'near'.
        batch_size (int): >= 1, rows per batch. Default 65536.
        batches_per_epoch (int): >= 1, batches per epoch over all workers and ranks. Default 16.
        seed (int): >= 0, as for sdfwb.sample. Default 0.
        params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sdfwb.sample.
            Default None: the declared defaults.
        time (float): seconds, for animated SDFs. Default 0.
        entry (str): the SDF's function when it is not `sdf`, as for sdfwb.sample. Default ''.
        gradient_step (float): > 0, the step of the central differences. Default 0: 1e-3, except that a
            mesh's own field writes its exact gradient (from the closest point).
        rank (int): this process's rank, 0 <= rank < world_size. Default 0.
        world_size (int): >= 1, the number of processes sharing the batches (as with DistributedSampler).
            Default 1.

    Raises:
        ValueError: batch_size or batches_per_epoch below 1, or rank outside 0..world_size-1. Iterating raises
            RuntimeError when a batch passes the last sample index 4294967295, and what sdfwb.sample raises.
    """

    def __init__(self, sdf: str, pattern: str = "near", batch_size: int = 65536, batches_per_epoch: int = 16,
                 seed: int = 0, params: Mapping[str, ParamValue] | None = None, time: float = 0.0, entry: str = "",
                 gradient_step: float = 0.0, rank: int = 0, world_size: int = 1) -> None:
        super().__init__()
        if batch_size < 1 or batches_per_epoch < 1:
            raise ValueError("SampleStream: batch_size and batches_per_epoch must be at least 1")
        if not 0 <= rank < world_size:
            raise ValueError(f"SampleStream: rank {rank} is not in 0..world_size-1 ({world_size})")
        self.sdf, self.pattern, self.batch_size = sdf, pattern, int(batch_size)
        self.batches_per_epoch, self.seed, self.params, self.time = int(batches_per_epoch), int(seed), params, float(time)
        self.entry, self.gradient_step, self.rank, self.world_size = entry, float(gradient_step), int(rank), int(world_size)
        self.epoch = 0

    def set_epoch(self, epoch: int) -> None:
        """Chooses the epoch the next iteration yields (call it at the start of each epoch).

        Args:
            epoch (int): >= 0; epoch e yields the batches e * batches_per_epoch ... (e + 1) * batches_per_epoch - 1.
        """
        self.epoch = int(epoch)

    def batch_indices(self, worker: int = 0, workers: int = 1) -> range:
        """The global batch numbers this rank's worker yields this epoch, in order.

        Args:
            worker (int): the DataLoader worker's id, 0 <= worker < workers. Default 0.
            workers (int): >= 1, the DataLoader's number of workers (1 without workers). Default 1.

        Returns:
            range: the batch numbers g; batch g holds the sample indices [g * batch_size, (g + 1) * batch_size).
        """
        first = self.epoch * self.batches_per_epoch
        stride = workers * self.world_size
        return range(first + self.rank * workers + worker, first + self.batches_per_epoch, stride)

    def __iter__(self) -> Iterator[SampleBatch]:
        info = _torch.utils.data.get_worker_info()
        worker, workers = (info.id, info.num_workers) if info is not None else (0, 1)
        for g in self.batch_indices(worker, workers):
            first = g * self.batch_size
            if first + self.batch_size > 1 << 32:
                raise RuntimeError(f"SampleStream: batch {g} passes the last sample index 4294967295; use another seed")
            rows = _native.sample(self.sdf, self.pattern, self.batch_size, seed=self.seed, time=self.time,
                                  gradient_step=self.gradient_step, entry=self.entry, params=self.params, first_index=first)
            yield {
                "position": _torch.from_numpy(rows["position"]),
                "distance": _torch.from_numpy(rows["distance"]),
                "gradient": _torch.from_numpy(rows["gradient"]),
                "first_index": first,
            }


def loader(stream: SampleStream, num_workers: int = 2, **kwargs: Any) -> _torch.utils.data.DataLoader[SampleBatch]:
    """A DataLoader over `stream` whose workers are started by 'spawn' (a forked worker cannot use the GPU
    its parent already used). batch_size=None: the stream's batches pass through as they are.

    Args:
        stream (SampleStream): the dataset.
        num_workers (int): >= 0, worker processes (0: batches are made in the calling process). Default 2.
        kwargs: further DataLoader arguments (e.g. pin_memory=True, prefetch_factor=4); multiprocessing_context
            defaults to 'spawn' when there are workers.

    Returns:
        torch.utils.data.DataLoader: yields the stream's SampleBatch dicts.
    """
    if num_workers > 0:
        kwargs.setdefault("multiprocessing_context", "spawn")
    return _torch.utils.data.DataLoader(stream, batch_size=None, num_workers=num_workers, **kwargs)
