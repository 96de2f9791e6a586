"""Many shapes on Dask distributed (Debian's python3-distributed): one task per manifest item.

    from distributed import Client, LocalCluster
    import sdfwb.dask
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        summary = sdfwb.dask.run_manifest("shapes.jsonl", client, item_timeout=600)

Each task runs `sdfwb --batch run MANIFEST --item I,J,...` (items_per_task of them, so a process start and a GL
context serve several) in a subprocess on its worker, so an item runs exactly as in the CLI's own run (same worker
process, same files, byte for byte), a broken shader or a hang fails that item alone, and the status file is
shared with CLI runs: items done by either are skipped by both. Workers need the sdfwb binary
(binary=, $SDFWB_BINARY, or sdfwb on PATH) and the manifest's folder at the same path (a shared filesystem).
Importing this module does not import dask; run_manifest needs a distributed.Client.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import time
from typing import TYPE_CHECKING, Any, TypedDict

if TYPE_CHECKING:
    from distributed import Client

__all__ = ["ManifestSummary", "items", "run_manifest"]


class ManifestSummary(TypedDict):
    """What run_manifest returns: the fields of `sdfwb --batch run --json`'s report."""

    manifest: str  # the manifest's absolute path
    status: str  # the status file's absolute path
    items: int
    done: int
    skipped: int  # done before (by this or a CLI run)
    failed: int  # failed or timed out
    seconds: float
    shapes_per_hour: float
    bytes_written: int
    results: list[dict[str, Any]]  # one dict per item, in manifest order


def _binary(binary: str | None = None) -> str:
    here = os.path.dirname(os.path.abspath(__file__))
    build_tree = os.path.join(os.path.dirname(os.path.dirname(here)), "app", "sdfwb")  # build/python/sdfwb -> build/app
    for candidate in (binary, os.environ.get("SDFWB_BINARY"), shutil.which("sdfwb"), build_tree):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
    raise RuntimeError("sdfwb.dask: cannot find the sdfwb binary: pass binary=, set SDFWB_BINARY, or put sdfwb on PATH")


def _command(binary: str, manifest: str, *options: str) -> dict[str, Any]:
    done = subprocess.run([binary, "--batch", "run", manifest, "--json", *options], capture_output=True, text=True)
    if done.returncode not in (0, 1) or not done.stdout.strip():
        raise RuntimeError(done.stderr.strip() or f"sdfwb --batch run exited with {done.returncode}")
    report: dict[str, Any] = json.loads(done.stdout)
    return report


def items(manifest: str, status: str | None = None, binary: str | None = None) -> list[dict[str, Any]]:
    """The manifest's items as `sdfwb --batch run MANIFEST --list --json` lists them.

    Args:
        manifest (str): a manifest file (the format of `sdfwb --batch run`: JSON lines or CSV).
        status (str | None): the status file. Default None: the CLI's, MANIFEST.status.jsonl.
        binary (str | None): the sdfwb executable. Default None: $SDFWB_BINARY, else sdfwb on PATH, else the
            build tree's app/sdfwb.

    Returns:
        list[dict]: one dict per item: index, line, kind, sdf, output and the state the status file records
        (pending, done, failed, timeout).

    Raises:
        RuntimeError: no sdfwb binary, or sdfwb failed (a bad manifest: its message).
    """
    options = ["--list"] + (["--status", os.path.abspath(status)] if status else [])
    listed: list[dict[str, Any]] = _command(_binary(binary), os.path.abspath(manifest), *options)["results"]
    return listed


def _run_items(binary: str, manifest: str, indices: list[int], status: str,
               item_timeout: float) -> list[dict[str, Any]]:
    options = ["--item", ",".join(map(str, indices)), "--status", status, "--item-timeout", repr(float(item_timeout))]
    results: list[dict[str, Any]] = _command(binary, manifest, *options)["results"]
    return results


def run_manifest(manifest: str, client: Client, status: str | None = None, item_timeout: float = 0.0,
                 binary: str | None = None, items_per_task: int = 4) -> ManifestSummary:
    """Runs every item of `manifest` as a task on `client`'s workers; items the status file records as done are
    skipped. Workers need the sdfwb binary and the manifest's folder at the same path.

    Args:
        manifest (str): a manifest file (the format of `sdfwb --batch run`: JSON lines or CSV).
        client (distributed.Client): the cluster's client.
        status (str | None): the status file, shared with CLI runs. Default None: MANIFEST.status.jsonl, the CLI's.
        item_timeout (float): >= 0, seconds an item may run before it is killed and recorded as timeout
            (0: no limit). Default 0.
        binary (str | None): the sdfwb executable, at the same path on every worker. Default None: $SDFWB_BINARY,
            else sdfwb on PATH, else the build tree's app/sdfwb.
        items_per_task (int): items a task runs in one sdfwb process (items i, i + T, i + 2T, ... with T tasks,
            so slow and fast stretches of the manifest spread over the tasks); values below 1 count as 1.
            Default 4.

    Returns:
        dict: a summary like the CLI's --json report: manifest, status, items, done, skipped (done before),
        failed (failed or timed out), seconds, shapes_per_hour, bytes_written and results (one dict per item, in
        manifest order).

    Raises:
        RuntimeError: no sdfwb binary, or sdfwb failed on the manifest (a bad manifest: its message).
    """
    binary = _binary(binary)
    manifest = os.path.abspath(manifest)
    status = os.path.abspath(status) if status else manifest + ".status.jsonl"
    listed = items(manifest, status, binary)
    start = time.perf_counter()
    indices = [item["index"] for item in listed]
    tasks = max(1, -(-len(indices) // max(1, int(items_per_task))))
    groups = [indices[t::tasks] for t in range(tasks)]
    futures = client.map(_run_items, [binary] * tasks, [manifest] * tasks, groups, [status] * tasks,
                         [item_timeout] * tasks, pure=False)
    gathered: list[list[dict[str, Any]]] = client.gather(futures)
    results = sorted((r for group in gathered for r in group), key=lambda r: int(r["index"]))
    seconds = time.perf_counter() - start
    done = [r for r in results if r["status"] == "done"]
    return {
        "manifest": manifest, "status": status, "items": len(results), "done": len(done),
        "skipped": sum(r["status"] == "skipped" for r in results),
        "failed": sum(r["status"] in ("failed", "timeout") for r in results),
        "seconds": seconds, "shapes_per_hour": len(done) * 3600.0 / seconds if seconds > 0 else 0.0,
        "bytes_written": sum(r["bytes"] for r in done), "results": results,
    }
