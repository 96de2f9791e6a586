#!/usr/bin/env python3
"""sdfwb's mesher against Flying Edges at 256, 512 and 1024 on the lent GPU machine (#33 point 5).

    python3 bench/device/run_device.py OUT_FOLDER [--resolutions 256,512,1024] [--repeats 3] [--skimage-at 512]

Runs from the bundle bench/device/bundle.sh makes (.device/): sdfwb's batch CLI on the GPU through EGL's device
platform, and the C++ Flying Edges peer (bench/device/flying_edges_peer.cpp; its field inline C++ over every
thread count, VTK's vtkFlyingEdges3D over every thread count, the fastest of each kept). Where NumPy and
scikit-image import, scikit-image's marching_cubes on a NumPy field is timed at 512 too. Every mesh is graded by
`sdfwb --batch grade` against the exact field. Writes OUT_FOLDER/results.jsonl (one object per measurement) and
a machine line; bench/device/report.py turns them into docs/meshing-gpu.md. Needs no sdfwb Python module.
"""
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/
from machine import cpu_model  # bench/machine.py

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUNDLE = os.path.join(ROOT, ".device")
SDFWB = os.path.join(BUNDLE, "sdfwb")
PEER = os.path.join(BUNDLE, "flying_edges_peer")
args = sys.argv[1:]
OUT = args[0]


def option(name, default):
    return args[args.index(name) + 1] if name in args else default


RESOLUTIONS = [int(r) for r in option("--resolutions", "256,512,1024").split(",")]
REPEATS = int(option("--repeats", "3"))
SKIMAGE_AT = int(option("--skimage-at", "512"))  # the one resolution scikit-image runs at
CPUS = os.cpu_count() or 1
# (label, class, the sdf as sdfwb takes it, the peer's name for its inline C++ field)
SHAPES = [("Sphere", "smooth", "sphere", "sphere"),
          ("Rotated box", "box-like", os.path.join(BUNDLE, "rotated_box.glsl"), "rotated-box"),
          ("Rotated cylinder", "creased", os.path.join(BUNDLE, "rotated_cylinder.glsl"), "rotated-cylinder")]
results = open(os.path.join(OUT, "results.jsonl"), "w")


def record(**fields):
    results.write(json.dumps(fields) + "\n")
    results.flush()
    print(json.dumps(fields), flush=True)


def run(command, **kw):
    started = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, **kw)
    return time.perf_counter() - started, done


def reports(stdout):
    """The JSON objects a job file's steps print, one after another."""
    decoder, objects, at = json.JSONDecoder(), [], 0
    while True:
        at = stdout.find("{", at)
        if at < 0:
            return objects
        obj, at = decoder.raw_decode(stdout, at)
        objects.append(obj)


def grade(sdf, mesh):
    wall, done = run([SDFWB, "--batch", "grade", "--sdf", sdf, "--mesh", mesh, "--occupancy-resolution", "0",
                      "--json"])
    if done.returncode != 0:
        return {"error": done.stderr[-500:]}
    r = json.loads(done.stdout)
    edges = r.get("edges") or {}
    return {"hausdorff": r["hausdorff"], "chamfer_l1": r["chamfer_l1"], "fscore": r["fscore"],
            "normal_consistency": r.get("normal_consistency"), "edge_chamfer_l1": edges.get("chamfer_l1"),
            "edge_fscore": edges.get("fscore"), "grade_seconds": wall}


def machine():
    def text(command):
        try:
            return subprocess.run(command, capture_output=True, text=True, timeout=30).stdout.strip()
        except (OSError, subprocess.SubprocessError):
            return ""
    cpu = cpu_model()
    with tempfile.TemporaryDirectory() as folder:
        _, done = run([SDFWB, "--batch", "sample", "--sdf", "sphere", "--pattern", "rand", "--count", "256", "-o",
                       os.path.join(folder, "r.bin"), "--json"])
    gl = (reports(done.stdout) or [{}])[0].get("gl_renderer", "unknown: " + done.stderr[-300:])
    record(kind="machine", started=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
           gpu=text(["nvidia-smi", "--query-gpu=name,driver_version,memory.total", "--format=csv,noheader"]),
           cpu=cpu, nproc=CPUS, kernel=platform.release(), gl_renderer=gl,
           sdfwb=text([SDFWB, "--version"]), memory_gb=os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30)


def ours(label, cls, sdf, R, folder):
    mesh = os.path.join(folder, "ours.ply")
    step = f"mesh --sdf {sdf} --resolution {R} -o {mesh} --error-samples 0 --json"
    job = os.path.join(folder, "job.txt")
    with open(job, "w") as file:  # a warm process: shaders compiled and the GL context made at R = 32 first
        file.write(f"mesh --sdf {sdf} --resolution 32 -o {mesh} --error-samples 0 --json\n")
        file.write((step + "\n") * REPEATS)
    _, done = run([SDFWB, "--batch", job])
    steps = reports(done.stdout)[1:]
    if done.returncode != 0 or len(steps) != REPEATS:
        record(kind="ours", label=label, R=R, error=done.stderr[-800:])
        return
    cold, cold_done = run([SDFWB, "--batch"] + step.split())  # one whole process: start, EGL, compile, mesh, write
    record(kind="ours", label=label, cls=cls, R=R, seconds=statistics.median(s["seconds"] for s in steps),
           mesh_seconds=statistics.median(s["mesh_seconds"] for s in steps), process_seconds=cold,
           triangles=steps[-1]["triangles"], manifold=steps[-1]["manifold"], watertight=steps[-1]["watertight"],
           blocks_kept=steps[-1]["blocks_kept"], blocks=steps[-1]["blocks"], cold_exit=cold_done.returncode,
           phases={p["name"]: p["seconds"] for p in steps[-1].get("phase_seconds", [])},
           **grade(sdf, mesh))


def flying_edges(label, cls, sdf, field, R, folder):
    threads = list(range(1, CPUS + 1)) if R <= 512 else sorted({max(1, CPUS // 2), CPUS})
    mesh = os.path.join(folder, "fe.ply")
    wall, done = run([PEER, field, str(R), ",".join(map(str, threads)), mesh])
    if done.returncode != 0:
        record(kind="flying_edges", label=label, R=R, error=done.stderr[-800:])
        return
    peer = json.loads(done.stdout)
    peer.pop("R"), peer.pop("shape")
    record(kind="flying_edges", label=label, cls=cls, R=R, threads_tried=threads, process_seconds=wall, **peer,
           **grade(sdf, mesh))


def scikit_image(label, cls, sdf, field, R, folder):
    try:
        import numpy as np
        from skimage import measure
    except ImportError as error:
        record(kind="scikit_image", label=label, R=R, error=str(error))
        return
    axis = np.linspace(-1.0, 1.0, R + 1, dtype=np.float32)
    x, y, z = axis[None, None, :], axis[None, :, None], axis[:, None, None]
    k = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    T = (np.eye(3) + np.sin(0.3) * K + (1 - np.cos(0.3)) * K @ K).T.astype(np.float32)

    def untilt():
        return (T[0, 0] * x + T[0, 1] * y + T[0, 2] * z, T[1, 0] * x + T[1, 1] * y + T[1, 2] * z,
                T[2, 0] * x + T[2, 1] * y + T[2, 2] * z)

    def values():
        if field == "sphere":
            return np.sqrt(x * x + y * y + z * z) - np.float32(0.8)
        u, v, w = untilt()
        if field == "rotated-box":
            qx, qy, qz = np.abs(u) - np.float32(0.55), np.abs(v) - np.float32(0.4), np.abs(w) - np.float32(0.3)
            return (np.sqrt(np.maximum(qx, 0) ** 2 + np.maximum(qy, 0) ** 2 + np.maximum(qz, 0) ** 2)
                    + np.minimum(np.maximum(qx, np.maximum(qy, qz)), 0))
        dx, dy = np.sqrt(u * u + w * w) - np.float32(0.45), np.abs(v) - np.float32(0.6)
        return np.minimum(np.maximum(dx, dy), 0) + np.sqrt(np.maximum(dx, 0) ** 2 + np.maximum(dy, 0) ** 2)

    started = time.perf_counter()
    lattice = values()
    field_seconds = time.perf_counter() - started
    vertices, faces, _, _ = measure.marching_cubes(lattice, 0.0, spacing=(2.0 / R,) * 3)
    seconds = time.perf_counter() - started
    mesh = os.path.join(folder, "mc.ply")
    vertices = np.ascontiguousarray(vertices[:, ::-1] - 1.0, dtype=np.float32)
    with open(mesh, "wb") as file:
        file.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\nproperty float x\n"
                    f"property float y\nproperty float z\nelement face {len(faces)}\n"
                    "property list uchar int vertex_indices\nend_header\n").encode())
        file.write(vertices.tobytes())
        rows = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", 3)])
        rows["n"], rows["i"] = 3, faces
        file.write(rows.tobytes())
    record(kind="scikit_image", label=label, cls=cls, R=R, seconds=seconds, field_seconds=field_seconds,
           triangles=len(faces), numpy=np.__version__, **grade(sdf, mesh))


machine()
for R in RESOLUTIONS:
    for label, cls, sdf, field in SHAPES:
        with tempfile.TemporaryDirectory() as folder:
            ours(label, cls, sdf, R, folder)
            flying_edges(label, cls, sdf, field, R, folder)
            if R == SKIMAGE_AT:
                scikit_image(label, cls, sdf, field, R, folder)
