"""PyTorch adapter (optional: needs python3-torch; `import sdfwb` never imports torch).

SampleStream is an IterableDataset of fresh samples made on the fly, no disk in between. Batch g of the
whole run holds the sample indices [g * batch_size, (g + 1) * batch_size); epoch e owns the batches
e * batches_per_epoch ... (e + 1) * batches_per_epoch - 1, and DataLoader worker w of W takes every W-th
of them starting at w. So seed, epoch and worker decide the counter range: batches are deterministic, and
no two workers or epochs repeat a row. Call set_epoch(e) at the start of each epoch (as with
DistributedSampler); rank and world_size split the batches across processes in the same way.
"""

import torch as _torch
from torch.utils.data import IterableDataset as _IterableDataset

from . import _native


class SampleStream(_IterableDataset):
    def __init__(self, sdf, pattern="near", batch_size=65536, batches_per_epoch=16, seed=0, params=None, time=0.0,
                 entry="", gradient_step=1e-3, rank=0, world_size=1):
        super().__init__()
        if batch_size < 1 or batches_per_epoch < 1:
            raise ValueError("SampleStream: batch_size and batches_per_epoch must be at least 1")
        if not 0 <= rank < world_size:
            raise ValueError(f"SampleStream: rank {rank} is not in 0..world_size-1 ({world_size})")
        self.sdf, self.pattern, self.batch_size = sdf, pattern, int(batch_size)
        self.batches_per_epoch, self.seed, self.params, self.time = int(batches_per_epoch), int(seed), params, float(time)
        self.entry, self.gradient_step, self.rank, self.world_size = entry, float(gradient_step), int(rank), int(world_size)
        self.epoch = 0

    def set_epoch(self, epoch):
        self.epoch = int(epoch)

    def batch_indices(self, worker=0, workers=1):
        """The global batch numbers this rank's worker yields this epoch, in order."""
        first = self.epoch * self.batches_per_epoch
        stride = workers * self.world_size
        return range(first + self.rank * workers + worker, first + self.batches_per_epoch, stride)

    def __iter__(self):
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


def loader(stream, num_workers=2, **kwargs):
    """A DataLoader over `stream` whose workers are started by 'spawn' (a forked worker cannot use the GPU
    its parent already used). batch_size=None: the stream's batches pass through as they are."""
    if num_workers > 0:
        kwargs.setdefault("multiprocessing_context", "spawn")
    return _torch.utils.data.DataLoader(stream, batch_size=None, num_workers=num_workers, **kwargs)
