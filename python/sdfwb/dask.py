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

import json
import os
import shutil
import subprocess
import time


def _binary(binary=None):
    here = os.path.dirname(os.path.abspath(__file__))
    build_tree = os.path.join(os.path.dirname(os.path.dirname(here)), "app", "sdfwb")  # build/python/sdfwb -> build/app
    for candidate in (binary, os.environ.get("SDFWB_BINARY"), shutil.which("sdfwb"), build_tree):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
    raise RuntimeError("sdfwb.dask: cannot find the sdfwb binary: pass binary=, set SDFWB_BINARY, or put sdfwb on PATH")


def _command(binary, manifest, *options):
    done = subprocess.run([binary, "--batch", "run", manifest, "--json", *options], capture_output=True, text=True)
    if done.returncode not in (0, 1) or not done.stdout.strip():
        raise RuntimeError(done.stderr.strip() or f"sdfwb --batch run exited with {done.returncode}")
    return json.loads(done.stdout)


def items(manifest, status=None, binary=None):
    """The manifest's items as `sdfwb --batch run MANIFEST --list --json` lists them: index, line, kind, sdf, output
    and the state the status file records (pending, done, failed, timeout)."""
    options = ["--list"] + (["--status", os.path.abspath(status)] if status else [])
    return _command(_binary(binary), os.path.abspath(manifest), *options)["results"]


def _run_items(binary, manifest, indices, status, item_timeout):
    options = ["--item", ",".join(map(str, indices)), "--status", status, "--item-timeout", repr(float(item_timeout))]
    return _command(binary, manifest, *options)["results"]


def run_manifest(manifest, client, status=None, item_timeout=0.0, binary=None, items_per_task=4):
    """Runs every item of `manifest` as a task on `client`'s workers. Returns a summary dict like the CLI's --json
    report: items, done, skipped (done before), failed, seconds, shapes_per_hour, bytes_written and results (one
    dict per item, in manifest order). status: the status file (default MANIFEST.status.jsonl, the CLI's).
    items_per_task: items a task runs in one sdfwb process (items i, i + T, i + 2T, ... with T tasks, so slow and
    fast stretches of the manifest spread over the tasks)."""
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
    results = sorted((r for group in client.gather(futures) for r in group), key=lambda r: r["index"])
    seconds = time.perf_counter() - start
    done = [r for r in results if r["status"] == "done"]
    return {
        "manifest": manifest, "status": status, "items": len(results), "done": len(done),
        "skipped": sum(r["status"] == "skipped" for r in results),
        "failed": sum(r["status"] in ("failed", "timeout") for r in results),
        "seconds": seconds, "shapes_per_hour": len(done) * 3600.0 / seconds if seconds > 0 else 0.0,
        "bytes_written": sum(r["bytes"] for r in done), "results": results,
    }
