#!/usr/bin/env python3
"""Process start-up of the sdfwb binary (#34 point 6): what a command pays before and around its work.

    env -u DISPLAY /usr/bin/python3 bench/bench_startup.py [--binary build/app/sdfwb] [--repeats 30] \
        [--markdown docs/startup.md]

The binary loads OpenImageIO and FFmpeg (libsdfwb_media.so) the first time it reads or writes an image or a video,
and Qt Widgets (libsdfwb_workbench.so) only when it opens the window (core/Plugins.h). The reference, measured in
the same run, is the same binary with both modules preloaded (LD_PRELOAD): the libraries it loaded before they were
modules, when everything was linked into the binary. The floor is `/bin/true`.

Commands: `sdfwb --version`; `sdfwb --batch sample` of 1,000 `rand` points of the dataset's Sphere into an .npz
(GL context, shader from Mesa's warm on-disk cache, sampling, write); `sdfwb --batch render` of a 64x48 PNG (which
needs the media module either way). Every way runs --repeats times, interleaved, after one untimed warm-up round
(page cache and Mesa's shader cache warm); times are median [min, max] wall seconds of the whole process. The
shared-object count is the number of link maps the loader makes (LD_DEBUG=files), dlopen'ed ones included.

The goals: `--version` in at most 50 ms of process overhead (#34 point 6), and the whole 1,000-sample run, the
process a user waits for, in at most 50 ms above the floor (#48 point 2, written before the run); the job's own
time (the report's `setup_seconds` + `seconds`) and the EGL context's creation (sdfwb's `(context in N ms)` log
line) are shown beside it, not subtracted.
"""
import argparse
import datetime
import json
import os
import platform
import re
import shlex
import socket
import statistics
import subprocess
import sys
import tempfile
import time

from machine import cpu_model  # bench/machine.py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))




def run(command, env, cwd):
    start = time.perf_counter()
    done = subprocess.run(command, env=env, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"bench_startup: {shlex.join(command)} failed ({done.returncode}):\n{done.stdout}{done.stderr}")
    return elapsed, done.stdout, done.stderr


def context_seconds(stderr):
    """The EGL context's creation, from the log line `[info] gl: EGL ... (context in N ms)`."""
    found = re.search(r"\(context in ([0-9.]+) ms\)", stderr)
    if not found:
        sys.exit("bench_startup: the sample run logged no '(context in N ms)' line:\n" + stderr)
    return float(found.group(1)) / 1000


def job_seconds(stdout):
    """The job's own time, from the report `--json` prints: its setup (the request checked, the SDF opened, its
    sampler compiled) and its sampling and writing."""
    report = json.loads(stdout)
    return float(report["setup_seconds"]) + float(report["seconds"])


def shared_objects(command, env, cwd):
    traced = dict(env, LD_DEBUG="files")
    done = subprocess.run(command, env=traced, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    return len(set(re.findall(r"file=(\S+) \[\d+\];  generating link map", done.stderr)))


def fmt(times):
    return f"{statistics.median(times) * 1000:.1f} [{min(times) * 1000:.1f}, {max(times) * 1000:.1f}]"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "app", "sdfwb"))
    parser.add_argument("--repeats", type=int, default=30)
    parser.add_argument("--markdown")
    args = parser.parse_args()
    binary = os.path.abspath(args.binary)
    plugins = os.path.join(os.path.dirname(os.path.dirname(binary)), "plugins")
    modules = [os.path.join(plugins, name) for name in ("libsdfwb_media.so", "libsdfwb_workbench.so")]
    missing = [m for m in modules if not os.path.isfile(m)]
    if missing:
        sys.exit(f"bench_startup: {', '.join(missing)} not found (build the default preset first)")

    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "LD_PRELOAD")}
    preloaded = dict(env, LD_PRELOAD=":".join(modules))
    work = tempfile.mkdtemp(prefix="sdfwb-startup-")
    commands = {
        "true": ["/bin/true"],
        "version": [binary, "--version"],
        "sample": [binary, "--batch", "sample", "--sdf", "Sphere", "-p", "rand", "-n", "1000", "-o", "s.npz",
                   "--json"],
        "render": [binary, "--batch", "render", "--sdf", "Sphere", "--size", "64x48", "--output", "r.png"],
    }
    ways = [("`/bin/true` (floor)", "true", env)]
    for key in ("version", "sample", "render"):
        ways.append((f"`sdfwb {' '.join(commands[key][1:])}`", key, env))
        ways.append((f"the same, every library preloaded (before)", key, preloaded))

    started = datetime.datetime.now(datetime.timezone.utc)
    for _, key, way_env in ways:  # warm-up round
        run(commands[key], way_env, work)
    times = {i: [] for i in range(len(ways))}
    overheads = {i: [] for i in range(len(ways))}  # the sample run's whole time less its job's own
    contexts = {i: [] for i in range(len(ways))}  # of which the EGL context (Mesa's driver loading)
    for _ in range(args.repeats):
        for i, (_, key, way_env) in enumerate(ways):
            elapsed, stdout, stderr = run(commands[key], way_env, work)
            times[i].append(elapsed)
            if key == "sample":
                overheads[i].append(elapsed - job_seconds(stdout))
                # --json quiets the log: the context's time comes from the same run without it, untimed.
                contexts[i].append(context_seconds(run(commands[key][:-1], way_env, work)[2]))
    counts = {i: shared_objects(commands[key], way_env, work) for i, (_, key, way_env) in enumerate(ways)}
    for name in ("s.npz", "r.png"):
        os.remove(os.path.join(work, name))
    os.rmdir(work)

    floor = statistics.median(times[0])
    lines = ["| command | ms, median [min, max] | ms above the floor | shared objects loaded |", "|---|---|---|---|"]
    for i, (label, key, _) in enumerate(ways):
        above = (statistics.median(times[i]) - floor) * 1000
        lines.append(f"| {label} | {fmt(times[i])} | {above:.1f} | {counts[i]} |")
    ratios = []
    for i in range(1, len(ways), 2):
        now, before = statistics.median(times[i]), statistics.median(times[i + 1])
        ratios.append(f"`{ways[i][1]}`: {(before - now) * 1000:.1f} ms less than with every library loaded "
                      f"({before / now:.2f}x faster); {(now - floor) * 1000:.1f} ms above `/bin/true`.")
    goal = 0.050
    for i, (label, key, _) in enumerate(ways):
        if key == "version" and ways[i][2] is env:
            over = statistics.median(times[i]) - floor
            ratios.append(f"Goal: `sdfwb --version` in at most {goal * 1000:.0f} ms of process overhead (above the floor): "
                          f"{over * 1000:.1f} ms, {'met' if over <= goal else 'NOT met'}.")
        if key == "sample" and ways[i][2] is env:
            # The goal is on the whole process, what the user waits for; where the time goes is shown
            # beside it, nothing subtracted (issue 48, point 2).
            whole = statistics.median(times[i]) - floor
            job = [t - o for t, o in zip(times[i], overheads[i])]
            rest = [o - c for o, c in zip(overheads[i], contexts[i])]
            ratios.append(f"Goal: the whole 1,000-sample run (the process a user waits for) in at most {goal * 1000:.0f} ms "
                          f"above the floor: {whole * 1000:.1f} ms, {'met' if whole <= goal else 'NOT met'} (before: "
                          f"{(statistics.median(times[i + 1]) - floor) * 1000:.1f} ms). Where it goes (medians, nothing "
                          f"subtracted from the goal): the job itself, {fmt(job)} ms (its `--json` report's `setup_seconds`, "
                          f"the SDF opened and its sampler compiled, plus `seconds`, sampling and writing); creating the EGL "
                          f"context, {fmt(contexts[i])} ms (Mesa's driver with its LLVM loaded and linked: what any OpenGL "
                          f"program pays on this machine, from sdfwb's log line in a second, untimed run without `--json`); "
                          f"the rest (process start, loading, parsing the options, exit), {fmt(rest)} ms.")
    config = [
        f"Machine: {socket.gethostname()}, nproc {os.cpu_count()} ({cpu_model()}), {platform.system()} "
        f"{platform.release()}; started {started.strftime('%Y-%m-%d %H:%M')} UTC.",
        f"Binary `{os.path.relpath(binary, ROOT)}`; modules in `{os.path.relpath(plugins, ROOT)}/`; {args.repeats} rounds, "
        "every way once per round, interleaved, after one untimed warm-up round; no DISPLAY.",
    ]
    print("\n".join(config))
    print("\n".join(lines))
    print("\n".join(ratios))
    if args.markdown:
        command = "env -u DISPLAY /usr/bin/python3 bench/bench_startup.py" + (
            f" --repeats {args.repeats}" if args.repeats != 30 else "") + f" --markdown {args.markdown}"
        with open(args.markdown, "w") as out:
            out.write("# Process start-up\n\n")
            out.write(f"Generated by `{command}` (bench/bench_startup.py; nothing below is typed by hand).\n\n")
            out.write("".join(f"- {line}\n" for line in config) + "\n")
            out.write("sdfwb loads OpenImageIO and the FFmpeg libraries (`libsdfwb_media.so`) the first time a command "
                      "reads or writes an image or a video, and Qt Widgets with QScintilla (`libsdfwb_workbench.so`) "
                      "only when it opens the window. \"Before\" is the same binary with both modules preloaded: the "
                      "libraries it loaded at every start when everything was linked into it, measured in the same "
                      "run. Times are of the whole process, as a shell or a job runner sees them.\n\n")
            out.write("\n".join(lines) + "\n\n")
            out.write("".join(f"- {line}\n" for line in ratios))
        # The tracked doc at its default settings: stamp it with its inputs (scripts/check_docs).
        if os.path.abspath(args.markdown) == os.path.join(ROOT, "docs", "startup.md") and args.repeats == 30:
            subprocess.run([os.path.join(ROOT, "scripts", "check_docs"), "--stamp", args.markdown], check=True)


if __name__ == "__main__":
    main()
