#!/usr/bin/env python3
"""Many shapes per run (#18 point 3): the same manifest run several ways in one sitting, with throughput.

    flock /tmp/sdfwb-build.lock env -u DISPLAY PYTHONPATH=build/python SDFWB_BINARY=build/app/sdfwb /usr/bin/python3 \
        bench/bench_run.py [--shapes 40] [--n 100000] [--repeats 3] [--markdown FILE]

The items are the first --shapes dataset SDFs (by name), each sampled with `near` (--n points, seed = its index)
into an .npz. The reference is what users do without a manifest runner: one `sdfwb --batch sample` process per
item, run by a loop that keeps P processes going at once (what `xargs -P P` does), timed at every P from 1 to
os.cpu_count(); the fastest is the reference. Then `sdfwb --batch run MANIFEST` (one worker process for all sample
items) and sdfwb.dask.run_manifest on a LocalCluster with 2 single-threaded workers (started before its timing
starts, closed after). Every way runs --repeats times, interleaved (one round of every way, then the next round),
each time into a fresh folder, after an untimed warm-up (one `sdfwb --batch sample`, one `sdfwb --batch run` over
the whole manifest: page cache and Mesa's on-disk shader cache warm for every SDF); times are median [min, max].
All ways and rounds must write byte-identical files (checked). Prints a configuration line, seconds, shapes per
hour, MB written and the speed against the loops.
"""
import concurrent.futures
import datetime
import filecmp
import json
import os
import platform
import shlex
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time

import distributed

import sdfwb
import sdfwb.dask

from machine import cpu_model  # bench/machine.py




def gl_renderer():
    """The GL renderer sdfwb's headless context runs on, from a tiny sample run's report."""
    with tempfile.TemporaryDirectory() as folder:
        report = sdfwb.run({"kind": "sample", "sdf": "sphere", "pattern": "rand", "n": 256,
                            "output": os.path.join(folder, "renderer.bin")})
    return report.get("gl_renderer") or "unknown"


def launcher():
    """`flock LOCK` when the parent process is flock (the shared lock that keeps other jobs off the machine)."""
    try:
        with open(f"/proc/{os.getppid()}/cmdline", "rb") as cmdline:
            words = [w.decode() for w in cmdline.read().split(b"\0") if w]
    except OSError:
        return ""
    if words and os.path.basename(words[0]) == "flock" and len(words) > 1:
        return f"flock {shlex.quote(words[1])}"
    return ""


def cpu_busy():
    """(busy seconds of the whole machine, CPU seconds of this process and its reaped children) so far."""
    with open("/proc/stat") as stat:
        fields = [int(v) for v in stat.readline().split()[1:]]
    idle = fields[3] + fields[4]
    own = os.times()
    return (sum(fields[:8]) - idle) / os.sysconf("SC_CLK_TCK"), own.user + own.system + own.children_user + own.children_system


def fmt(times, digits=1):
    return f"{statistics.median(times):.{digits}f} [{min(times):.{digits}f}, {max(times):.{digits}f}]"


def main():
    # Dask's workers start by spawn and import __main__: everything runs from here, never at import.
    args = sys.argv[1:]
    SHAPES = int(args[args.index("--shapes") + 1]) if "--shapes" in args else 40
    N = int(args[args.index("--n") + 1]) if "--n" in args else 100_000
    REPEATS = int(args[args.index("--repeats") + 1]) if "--repeats" in args else 3
    MARKDOWN = args[args.index("--markdown") + 1] if "--markdown" in args else None
    BINARY = os.path.abspath(os.environ.get("SDFWB_BINARY", "build/app/sdfwb"))
    CPUS = os.cpu_count()
    PARALLEL = list(range(1, CPUS + 1))

    names = sorted(item["name"] for item in sdfwb.list_sdfs())[:SHAPES]
    work = tempfile.mkdtemp(prefix="sdfwb-bench-run-")
    items = [{"sdf": name, "pattern": "near", "n": N, "seed": k, "output": f"out/{k:03d}.npz"} for k, name in enumerate(names)]
    renderer = gl_renderer()
    started = datetime.datetime.now(datetime.timezone.utc)
    command = " ".join(filter(None, [
        launcher(),
        "env -u DISPLAY" if "DISPLAY" not in os.environ else "",
        f"PYTHONPATH={shlex.quote(os.environ['PYTHONPATH'])}" if os.environ.get("PYTHONPATH") else "",
        f"SDFWB_BINARY={shlex.quote(os.environ['SDFWB_BINARY'])}" if os.environ.get("SDFWB_BINARY") else "",
        f"LP_NUM_THREADS={os.environ['LP_NUM_THREADS']}" if os.environ.get("LP_NUM_THREADS") else "",
        sys.executable, shlex.join(sys.argv)]))

    def folder(way, round_):
        path = os.path.join(work, f"{way}-{round_}")
        os.makedirs(os.path.join(path, "out"))
        with open(os.path.join(path, "shapes.jsonl"), "w") as out:
            out.writelines(json.dumps(item) + "\n" for item in items)
        return path

    def written(path):
        return sum(os.path.getsize(os.path.join(path, "out", f)) for f in os.listdir(os.path.join(path, "out")))

    def sample(item, path):
        subprocess.run([BINARY, "--batch", "sample", "--sdf", item["sdf"], "--pattern", "near", "-n", str(N), "--seed",
                        str(item["seed"]), "--output", os.path.join(path, item["output"]), "--quiet"], check=True)

    def loop(processes, path):
        with concurrent.futures.ThreadPoolExecutor(processes) as pool:
            list(pool.map(lambda item: sample(item, path), items))
        return written(path)

    def cli(path):
        report = json.loads(subprocess.run([BINARY, "--batch", "run", os.path.join(path, "shapes.jsonl"), "--json"],
                                           capture_output=True, text=True, check=True).stdout)
        assert report["done"] == len(items), report
        return report["bytes_written"]

    ways = [(f"one `sdfwb --batch sample` process per item, {p} at a time (reference)", f"loop{p}",
             lambda path, p=p: loop(p, path)) for p in PARALLEL]
    ways.append(("`sdfwb --batch run MANIFEST`", "cli", cli))
    ways.append(("`sdfwb.dask.run_manifest`, LocalCluster of 2 workers", "dask", None))

    warm = folder("warm-up", 0)
    sample(items[0], warm)
    warm_run = folder("warm-up-run", 0)
    cli(warm_run)  # every SDF once, untimed: page cache and Mesa's on-disk shader cache warm for every way
    times = {key: [] for _, key, _ in ways}
    sizes = {}
    wall_start, load_start = time.perf_counter(), os.getloadavg()[0]
    busy_start, own_start = cpu_busy()
    for round_ in range(REPEATS):
        for label, key, run in ways:
            path = folder(key, round_)
            if run is not None:
                start = time.perf_counter()
                size = run(path)
                seconds = time.perf_counter() - start
            else:
                with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                              dashboard_address=None) as cluster, distributed.Client(cluster) as client:
                    start = time.perf_counter()
                    summary = sdfwb.dask.run_manifest(os.path.join(path, "shapes.jsonl"), client, binary=BINARY)
                    seconds = time.perf_counter() - start
                assert summary["done"] == len(items), summary
                size = summary["bytes_written"]
            times[key].append(seconds)
            sizes[key] = size
            print(f"round {round_ + 1}/{REPEATS} {label}: {seconds:.1f} s", flush=True)
            first = os.path.join(work, "loop1-0")
            for item in items:
                assert filecmp.cmp(os.path.join(first, item["output"]), os.path.join(path, item["output"]),
                                   shallow=False), (key, round_, item)
            if path != first:
                shutil.rmtree(path)
    wall = time.perf_counter() - wall_start
    busy_end, own_end = cpu_busy()
    others = max(0.0, (busy_end - busy_start) - (own_end - own_start))
    shutil.rmtree(work)

    median = {key: statistics.median(t) for key, t in times.items()}
    best_p = min(PARALLEL, key=lambda p: median[f"loop{p}"])
    sequential, best = median["loop1"], median[f"loop{best_p}"]
    config = [
        f"Machine: {socket.gethostname()}, nproc {CPUS} ({cpu_model()}), {platform.system()} {platform.release()}; "
        f"started {started.strftime('%Y-%m-%d %H:%M')} UTC; load average {load_start:.2f} at the start, "
        f"{os.getloadavg()[0]:.2f} at the end.",
        f"sdfwb {sdfwb.__version__} (`{os.path.relpath(BINARY)}`), GL renderer `{renderer}`"
        + (" (Mesa's CPU rasteriser, no GPU)" if "llvmpipe" in renderer else "")
        + f"; Dask distributed {distributed.__version__}; Python {platform.python_version()}.",
        f"Reference: what a user does without a manifest runner, one `sdfwb --batch sample` process per item "
        f"(process start, GL context, sampling, write), launched by a loop that keeps P of them running "
        f"(`xargs -P P`), P = {', '.join(map(str, PARALLEL))} tried; the fastest ({best_p} at a time) is the "
        "reference for the last column.",
        f"{REPEATS} rounds, every way once per round, interleaved, each into a fresh folder, after one warm-up "
        f"`sdfwb --batch sample` and one untimed `sdfwb --batch run` over the whole manifest (they fill the page cache and "
        f"Mesa's on-disk shader cache for every SDF, so no way pays a cold compile); times are median [min, max] over "
        f"the rounds; {wall / 60:.1f} minutes of measurements in all.",
        f"Quiet machine check: during the measurements, processes other than this one and its children used "
        f"{others:.1f} CPU-seconds ({100 * others / (wall * CPUS):.1f}% of the {CPUS} CPUs).",
    ]
    lines = ["| way | seconds | shapes/hour | MB written | MB/s | speed vs the 1-at-a-time loop | "
             f"speed vs the fastest loop ({best_p} at a time) |", "|---|---|---|---|---|---|---|"]
    for label, key, _ in ways:
        m = median[key]
        lines.append(f"| {label} | {fmt(times[key])} | {len(items) * 3600 / m:.0f} | {sizes[key] / 1e6:.1f} | "
                     f"{sizes[key] / 1e6 / m:.1f} | {sequential / m:.2f}x | {best / m:.2f}x |")
    table = "\n".join(lines)
    verdicts = []
    for label, key, _ in ways[len(PARALLEL):]:
        ratio = best / median[key]
        verdicts.append(f"{label}: {ratio:.2f}x the fastest loop" + (" (faster)." if ratio >= 1 else
                        f": slower, it takes {1 / ratio:.2f}x as long."))
    print("\n".join(config))
    print(table)
    print("\n".join(verdicts))
    print(f"files byte-identical across every way and round")

    if MARKDOWN:
        with open(MARKDOWN, "w") as out:
            out.write("# Many shapes per run: throughput\n\n")
            out.write(f"Generated by `{command}` (bench/bench_run.py; nothing below is typed by hand).\n\n")
            out.write("".join(f"- {line}\n" for line in config) + "\n")
            out.write(f"{len(items)} dataset SDFs (the first by name: {names[0]} ... {names[-1]}), `near` with {N:,} points "
                      f"each into .npz. Every way and round wrote byte-identical files (the script checks). Shapes/hour, "
                      f"MB/s and speeds are from the median times.\n\n")
            out.write(table + "\n\n")
            out.write("".join(f"- {line}\n" for line in verdicts) + "\n")
            out.write("The loop pays a process start (the binary links Qt, OpenImageIO and FFmpeg) "
                      "and a GL context per item; `--batch run` pays them once, for a worker that takes every sample "
                      "item until one crashes or times out. The Dask tasks each run a few items in one `sdfwb --batch run "
                      "--item I,J,...` process.\n")
        print(f"wrote {MARKDOWN}")


if __name__ == "__main__":
    main()
