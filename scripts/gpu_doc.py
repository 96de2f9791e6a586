#!/usr/bin/env python3
"""docs/gpu.md from what the lent GPU machine printed, kept as it came back in docs/data/gpu/:
scripts/device_check's report (device-check.md, its log gzipped beside it) and the outputs of the
commands run after it on the same machine (tracer.md, bad-rows.txt, meshes.md, test-meshing.txt),
each under the command that made it; then the issues' goals against those figures. Nothing is
typed by hand: a figure below is a line of those files or computed from them here.

    /usr/bin/python3 scripts/gpu_doc.py && scripts/check_docs --stamp docs/gpu.md
"""
import os
import re

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
DATA = os.path.join(ROOT, "docs", "data", "gpu")
OUT = os.path.join(ROOT, "docs", "gpu.md")
BUNDLE = "/tmp/b"  # where the commands below unpacked .device/bundle.tar.xz

# What came after device_check's run, in the order it ran, with the command that made each file
# (the environment was device_check's: the bundle's libraries, NVIDIA's EGL vendor file,
# SDFWB_EGL_PLATFORM=device, the repository at /work/main).
LATER = [
    ("tracer.md", "Tracer against the reference tracer (bench/bench_tracer.cpp), every dataset SDF",
     f"timeout -k 3 105 {BUNDLE}/bin/bench_tracer > tracer.md", "text"),
    ("bad-rows.txt", "Bad-row counts: the GPU's against the host's recount (scripts/check_bad_rows)",
     f"scripts/check_bad_rows {BUNDLE}/bin/sdfwb {BUNDLE}/bin/count_bad_rows tests/foreign/15_nan_superquadric.glsl 2000000; "
     f"scripts/check_bad_rows ... {BUNDLE}/meshes/stanford-bunny.obj 1000000 rand near surface", "code"),
    ("meshes.md", "The other shared meshes: sampling on the GPU, two passes",
     f"for each mesh: {BUNDLE}/bin/sdfwb --batch sample --sdf MESH --normalize unit-cube -p rand -n 10000000 (and -p near "
     "-n 2000000) -o /tmp/m.npz; columns: mesh, pattern, passes, samples, process seconds, what sdfwb printed", "table"),
    ("test-meshing.txt", "test_meshing, which device_check's 80 s cut (55 s here)",
     f"timeout -k 2 55 {BUNDLE}/bin/test_meshing: the tests that ended, then the one still running", "code"),
]


def read(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        return f.read()


def rates(text, mesh, pattern, passes):
    # "| mesh | pattern | passes | samples | bad rows | seconds | wrote ...: ... (4.87 M samples/s) |"
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) >= 4 and cells[0] == mesh and cells[1] == pattern and cells[2] == passes:
            found = re.search(r"\(([0-9.]+) M samples/s\)", line)
            if found:
                return float(found.group(1))
    return None


def goals(report, tracer):
    lines = ["## Against the issues' goals", ""]
    for line in report.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) >= 8 and cells[7] in ("yes", "**no**"):
            lines.append(f"- Issue 49, sampling into host memory, {cells[0]}: {cells[2].split(' ')[0]} rows/s against a goal "
                         f"of {cells[6]}: {'met' if cells[7] == 'yes' else '**not met**'}.")
    sphere = re.search(r"^\| Sphere \| [^|]+ \| ([0-9.]+);", tracer, re.M)
    if sphere:
        ms = float(sphere.group(1))
        lines.append(f"- Issue 49, the Sphere at 1280x720: {ms:.3f} ms of GPU time a frame against at most 0.1 ms: "
                     f"{'met' if ms <= 0.1 else '**not met**'}.")
    # bench_mesh_gpu's rows (into host memory): | pattern | rows | order | ... | goal | met |
    for line in report.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) >= 14 and cells[0] in ("rand", "near") and cells[13] in ("yes", "**no**"):
            lines.append(f"- Issue 46, the bunny's `{cells[0]}` into host memory ({cells[2]}, bench_mesh_gpu): "
                         f"{cells[4].split(' ')[0]} rows/s against {cells[12]}, distance error {cells[9]}, wrong signs "
                         f"{cells[10]}: {'met' if cells[13] == 'yes' else '**not met**'}.")
    for pattern, goal in (("rand", 50.0), ("near", 20.0)):
        best = max((r for r in (rates(report, "stanford-bunny.obj", pattern, p) for p in ("one", "two", "sorted")) if r), default=None)
        if best is not None:
            lines.append(f"- Issue 46, the bunny's `{pattern}` on the GPU into a file: {best:.2f} M rows/s at best (value, exact gradient "
                         f"and winding sign) against {goal:.0f} M: {'met' if best >= goal else '**not met**'}.")
    for pattern in ("rand", "near"):
        best = max((r for r in (rates(report, "bunny-subdivided-twice.ply", pattern, p) for p in ("one", "two", "sorted")) if r),
                   default=None)
        lines.append(f"- Issue 46, the bunny subdivided twice (1.1 M triangles), `{pattern}`: "
                     + (f"{best:.2f} M rows/s at best." if best is not None else "no figure (the run did not reach it, or it hung)."))
    return lines


def main():
    report = read("device-check.md").rstrip("\n")
    out = [report, ""]
    # A run that device_check finished has no later files: its own report holds every section.
    later = [entry for entry in LATER if os.path.exists(os.path.join(DATA, entry[0]))]
    if later:
        out += ["## After scripts/device_check, on the same machine", "",
                "The device call's 600 s ran out while `scripts/device_check` sampled the bunny subdivided twice (1.1 M "
                "triangles):", "that `sdfwb` process outlived its `timeout` (a SIGTERM, with no kill after it; the script "
                "now sends SIGKILL 5 s", "later and runs that mesh last), so the mesh table above stops before it and the "
                "script's last steps did not run.", "They ran next as separate commands on the same machine, the shader "
                "cache warm from the first run:", ""]
    tracer = read("tracer.md") if os.path.exists(os.path.join(DATA, "tracer.md")) else report
    for name, title, command, kind in later:
        body = read(name).rstrip("\n")
        out += [f"### {title}", "", f"`{command}`", ""]
        if kind == "code":
            out += ["```", body, "```"]
        elif kind == "table":
            out += ["| mesh | pattern | passes | samples | process seconds | what sdfwb printed |", "|---|---|---|---|---|---|", body]
        else:
            out += [line for line in body.splitlines() if not line.startswith("[")]
        out.append("")
    out += goals(report, tracer)
    out.append("")
    with open(OUT, "w", encoding="utf-8") as f:
        f.write("\n".join(out))
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
