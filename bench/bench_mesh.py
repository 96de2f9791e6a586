#!/usr/bin/env python3
"""Mesh extraction against a fair reference, measured in the same run (#17 point 7).

    flock /tmp/sdfwb-build.lock env -u DISPLAY PYTHONPATH=build/python /usr/bin/python3 bench/bench_mesh.py
        [--resolution 256] [--repeats 5] [--markdown FILE]

Ours: `sdfwb.mesh(sdf, R)`: GPU field (Mesa llvmpipe when there is no GPU; it uses every core unless LP_NUM_THREADS
says otherwise), dual contouring, vertices projected onto the surface by two Newton steps with the exact field.

Reference: the same SDFs written by hand in float32 (broadcast open grids, in-place ops where they help), evaluated on
the same (R+1)^3 lattice over [-1,1]^3, meshed by scikit-image's `measure.marching_cubes` (Lewiner, the tool ML code
uses). The reference gets its best thread use:
- the lattice is evaluated in every form and thread count below and the fastest (by median) is used:
  NumPy on the whole lattice (1 thread: ufuncs do not use threads); NumPy in slabs of z-slices spread over a
  ThreadPool of 1..os.cpu_count() threads (NumPy releases the GIL inside ufuncs); PyTorch (CPU, float32,
  inference_mode) on the whole lattice at intra-op threads 1..os.cpu_count();
- marching cubes itself is single-threaded (its Cython kernel holds the GIL, so threads cannot split it);
- a second reference, "MC + projection", moves the marching-cubes vertices by the same post-pass ours does: two
  Newton steps v -= f(v) grad f(v) / |grad f(v)|^2 with the exact field in NumPy float32 (gradient by central
  differences), the vertices split over a ThreadPool at the fastest of 1..os.cpu_count() threads. Accuracy is then
  compared like for like (dual contouring + projection against marching cubes + projection).
Both sides get one warm-up run at full size before timing; every time is median [min, max] of --repeats runs,
ours and the reference interleaved. All meshes are graded by `sdfwb.evaluate_mesh` against the exact field.
Ratios are reference time / our time (above 1: we are faster); where we are slower or less accurate the output
says so.
"""
import concurrent.futures
import datetime
import os
import platform
import shlex
import socket
import statistics
import sys
import tempfile
import time

import meshio
import numpy as np
import skimage
import torch
from skimage import measure

import sdfwb

from machine import cpu_model  # bench/machine.py

args = sys.argv[1:]
R = int(args[args.index("--resolution") + 1]) if "--resolution" in args else 256
REPEATS = int(args[args.index("--repeats") + 1]) if "--repeats" in args else 5
MARKDOWN = args[args.index("--markdown") + 1] if "--markdown" in args else None
CPUS = os.cpu_count()
THREADS = list(range(1, CPUS + 1))
SLABS = (8, 32)          # z-slices per NumPy work item
NEWTON_STEPS = 2
DIFF_STEP = 1e-4          # central differences for the projection's gradient
try:
    torch.set_num_interop_threads(1)
except RuntimeError:
    pass
TORCH_DEFAULT_THREADS = torch.get_num_threads()


class NP:
    abs, maximum = np.abs, np.maximum
    sqrt_ = staticmethod(lambda a: np.sqrt(a, out=a))
    relu = staticmethod(lambda a: np.maximum(a, 0.0))
    clamp_max_ = staticmethod(lambda a, v: np.minimum(a, v, out=a))


class TORCH:
    abs, maximum = torch.abs, torch.maximum
    sqrt_ = staticmethod(lambda a: a.sqrt_())
    relu = staticmethod(lambda a: a.clamp(min=0.0))
    clamp_max_ = staticmethod(lambda a, v: a.clamp_(max=v))


# The dataset's SDFs, written once for both libraries. Inputs broadcast (x along the last axis); no input is modified.
def sphere(M, x, y, z):
    s = x * x + y * y
    s = s + z * z
    M.sqrt_(s)
    s -= 0.8
    return s


def box(M, x, y, z):
    qx, qy, qz = M.abs(x) - 0.8, M.abs(y) - 0.5, M.abs(z) - 0.6
    outside = M.relu(qx) ** 2 + M.relu(qy) ** 2
    outside = outside + M.relu(qz) ** 2
    M.sqrt_(outside)
    inside = M.maximum(qx, M.maximum(qy, qz))
    M.clamp_max_(inside, 0.0)
    outside += inside
    return outside


def torus(M, x, y, z):  # the dataset's Torus: tilted 30 degrees about x
    c, s = 0.8660254, 0.5
    y, z = c * y + s * z, -s * y + c * z
    q = x * x + z * z
    M.sqrt_(q)
    q -= 0.65
    q *= q
    q += y * y
    M.sqrt_(q)
    q -= 0.25
    return q


SHAPES = [("Sphere", "sphere", sphere), ("Box", "box", box), ("Torus", "torus", torus)]
AXIS = np.linspace(-1.0, 1.0, R + 1, dtype=np.float32)
OPEN = (AXIS[None, None, :], AXIS[None, :, None], AXIS[:, None, None])  # x, y, z of the [z][y][x] lattice
TORCH_OPEN = tuple(torch.from_numpy(np.ascontiguousarray(a)) for a in OPEN)


def lattice_numpy_whole(field):
    return field(NP, *OPEN)


def lattice_numpy_slabs(field, slab, threads, pool):
    values = np.empty((R + 1,) * 3, np.float32)
    x, y, z = OPEN

    def work(z0):
        values[z0:z0 + slab] = field(NP, x, y, z[z0:z0 + slab])

    list(pool.map(work, range(0, R + 1, slab)))
    return values


def lattice_torch(field, threads):
    torch.set_num_threads(threads)
    with torch.inference_mode():
        return field(TORCH, *TORCH_OPEN).numpy()


def lattice_forms(field, pools):
    """(library, form, threads, function) for every way of evaluating the lattice the reference may use."""
    forms = [("NumPy", "whole lattice", 1, lambda: lattice_numpy_whole(field))]
    for slab in SLABS:
        for k in THREADS:
            forms.append(("NumPy", f"slabs of {slab} z-slices, ThreadPool", k,
                          lambda slab=slab, k=k: lattice_numpy_slabs(field, slab, k, pools[k])))
    for k in THREADS:
        forms.append(("PyTorch", "whole lattice", k, lambda k=k: lattice_torch(field, k)))
    return forms


def marching_cubes(values):
    vertices, faces, _, _ = measure.marching_cubes(values, 0.0, spacing=(2.0 / R,) * 3)
    return np.ascontiguousarray(vertices[:, ::-1] - 1.0, dtype=np.float32), faces  # (z,y,x) -> (x,y,z) in [-1,1]


def project(field, vertices, pool, threads):
    """Two Newton steps towards the zero set with the exact field in NumPy float32 (central differences)."""
    out = vertices.copy()
    chunks = np.array_split(np.arange(len(out)), threads)

    def work(index):
        p = [np.ascontiguousarray(out[index, k]) for k in range(3)]
        for _ in range(NEWTON_STEPS):
            f = field(NP, *p)
            gradient = []
            for k in range(3):
                plus, minus = list(p), list(p)
                plus[k], minus[k] = p[k] + np.float32(DIFF_STEP), p[k] - np.float32(DIFF_STEP)
                gradient.append((field(NP, *plus) - field(NP, *minus)) / (plus[k] - minus[k]))
            g2 = gradient[0] ** 2 + gradient[1] ** 2 + gradient[2] ** 2
            scale = np.where(g2 > 1e-12, f / np.maximum(g2, np.float32(1e-12)), np.float32(0))
            p = [p[k] - scale * gradient[k] for k in range(3)]
        out[index] = np.stack(p, axis=1)

    list(pool.map(work, chunks))
    return out


def timed(function):
    started = time.perf_counter()
    result = function()
    return time.perf_counter() - started, result


def spread(times):
    return statistics.median(times), min(times), max(times)


def fmt(times):
    m, lo, hi = spread(times)
    return f"{m:.3f} [{lo:.3f}, {hi:.3f}]"


def grade(vertices, faces, sdf, folder):
    path = os.path.join(folder, "m.ply")
    meshio.write(path, meshio.Mesh(np.asarray(vertices, np.float32), [("triangle", np.asarray(faces, np.int32))]),
                 binary=True)
    return sdfwb.evaluate_mesh(path, sdf, tau=0.001)




def gl_renderer():
    """The GL renderer sdfwb's headless context runs on, from a tiny sample run's report."""
    with tempfile.TemporaryDirectory() as folder:
        report = sdfwb.run({"kind": "sample", "sdf": "sphere", "pattern": "rand", "n": 256,
                            "output": os.path.join(folder, "renderer.bin")})
    return report.get("gl_renderer") or "unknown"


def cpu_busy():
    """(busy seconds of the whole machine, CPU seconds of this process and its threads) so far."""
    with open("/proc/stat") as stat:
        fields = [int(v) for v in stat.readline().split()[1:]]
    idle = fields[3] + fields[4]
    own = os.times()
    return (sum(fields[:8]) - idle) / os.sysconf("SC_CLK_TCK"), own.user + own.system


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


renderer = gl_renderer()
llvmpipe = "llvmpipe" in renderer
lp_threads = os.environ.get("LP_NUM_THREADS")
started = datetime.datetime.now(datetime.timezone.utc)
command = " ".join(filter(None, [
    launcher(),
    "env -u DISPLAY" if "DISPLAY" not in os.environ else "",
    f"PYTHONPATH={shlex.quote(os.environ['PYTHONPATH'])}" if os.environ.get("PYTHONPATH") else "",
    f"LP_NUM_THREADS={lp_threads}" if lp_threads else "",
    sys.executable, shlex.join(sys.argv)]))
config = [
    f"Machine: {socket.gethostname()}, nproc {CPUS} ({cpu_model()}), {platform.system()} {platform.release()}; "
    f"started {started.strftime('%Y-%m-%d %H:%M')} UTC.",
    f"Ours: sdfwb {sdfwb.__version__}, `sdfwb.mesh(sdf, resolution={R})`, GL renderer `{renderer}`"
    + (f" (Mesa's CPU rasteriser, no GPU; it uses {lp_threads if lp_threads else f'all {CPUS}'} "
       f"cores{' (LP_NUM_THREADS)' if lp_threads else ''})" if llvmpipe else "")
    + "; the whole call is timed: GL context, the Lipschitz bound estimated from the block centres, extraction "
      "(dual contouring, two Newton steps onto the surface); the extraction alone in its own column.",
    f"Reference lattice: the same SDFs in float32 on the same (R+1)^3 = {R + 1}^3 lattice; forms tried: NumPy "
    f"{np.__version__} whole lattice (1 thread), NumPy in slabs of {' or '.join(map(str, SLABS))} z-slices over a "
    f"ThreadPool of {', '.join(map(str, THREADS))} threads, PyTorch {torch.__version__} (CPU, inference_mode) "
    f"whole lattice at intra-op threads {', '.join(map(str, THREADS))} (its default here: {TORCH_DEFAULT_THREADS}); "
    "the fastest by median is used (per SDF, named in the table).",
    f"Reference meshing: scikit-image {skimage.__version__} `measure.marching_cubes` (Lewiner), single-threaded: "
    "its Cython kernel holds the GIL, so no thread count can split it.",
    f"Reference projection (MC + projection): {NEWTON_STEPS} Newton steps v -= f grad f / |grad f|^2 with the exact "
    f"field in NumPy float32, gradient by central differences (h = {DIFF_STEP:g}), vertices split over a "
    f"ThreadPool of {', '.join(map(str, THREADS))} threads, the fastest used.",
    f"Python {platform.python_version()}; every time is median [min, max] of {REPEATS} runs after one warm-up run "
    "of the same size on each side, ours and the reference interleaved, all in this one run. Errors by "
    "`sdfwb.evaluate_mesh(mesh, sdf, tau=0.001)` (100,000 points each way) against the exact field.",
]
print("\n".join(config), flush=True)

pools = {k: concurrent.futures.ThreadPoolExecutor(k) for k in THREADS}
rows, forms_table = [], []
busy_start, own_start, wall_start = *cpu_busy(), time.perf_counter()
with tempfile.TemporaryDirectory() as folder:
    for label, name, field in SHAPES:
        sdfwb.mesh(name, resolution=R)  # warm-up of ours at full size (shader cache, GL context)
        # Choose the reference's fastest lattice form (each one warmed up, then timed REPEATS times).
        forms = lattice_forms(field, pools)
        truth = forms[0][3]()
        candidates = []
        for library, form, k, function in forms:
            function()
            times = []
            for _ in range(REPEATS):
                t, values = timed(function)
                times.append(t)
            assert values.shape == truth.shape and np.allclose(values, truth, atol=1e-6), (library, form, k)
            candidates.append((statistics.median(times), library, form, k, times))
            forms_table.append((label, library, form, k, times))
            print(f"{label:8s} lattice {library:7s} {form:40s} {k} thread{'s' if k > 1 else ' '} {fmt(times)} s",
                  flush=True)
        _, library, form, k_lattice, _ = min(candidates, key=lambda c: c[0])
        lattice = next(f for lib, fo, k, f in forms if (lib, fo, k) == (library, form, k_lattice))
        best_lattice = f"{library}, {form}, {k_lattice} thread{'s' if k_lattice > 1 else ''}"
        # Choose the projection's fastest thread count (on this SDF's marching-cubes vertices).
        mc_vertices, mc_faces = marching_cubes(truth)
        projection_candidates = []
        for k in THREADS:
            project(field, mc_vertices, pools[k], k)
            times = [timed(lambda: project(field, mc_vertices, pools[k], k))[0] for _ in range(REPEATS)]
            projection_candidates.append((statistics.median(times), k))
            forms_table.append((label, "NumPy", "projection of the MC vertices, ThreadPool", k, times))
            print(f"{label:8s} projection NumPy {k} thread{'s' if k > 1 else ' '} {fmt(times)} s", flush=True)
        k_projection = min(projection_candidates)[1]

        def reference():
            t0 = time.perf_counter()
            values = lattice()
            t1 = time.perf_counter()
            vertices, faces = marching_cubes(values)
            t2 = time.perf_counter()
            projected = project(field, vertices, pools[k_projection], k_projection)
            t3 = time.perf_counter()
            return (t1 - t0, t2 - t1, t3 - t2), vertices, faces, projected

        reference()  # warm-up of the reference's whole path at full size
        t = {key: [] for key in ("ours", "extraction", "lattice", "mc", "projection", "ref", "ref_projected")}
        for _ in range(REPEATS):
            seconds, ours = timed(lambda: sdfwb.mesh(name, resolution=R))
            t["ours"].append(seconds)
            t["extraction"].append(ours["report"]["mesh_seconds"])
            (lat, mc, proj), vertices, faces, projected = reference()
            t["lattice"].append(lat)
            t["mc"].append(mc)
            t["projection"].append(proj)
            t["ref"].append(lat + mc)
            t["ref_projected"].append(lat + mc + proj)
        errors = {"ours": grade(ours["vertices"], ours["faces"], name, folder),
                  "mc": grade(vertices, faces, name, folder),
                  "mc_projected": grade(projected, faces, name, folder)}
        rows.append(dict(label=label, t=t, errors=errors, lattice=best_lattice, k_projection=k_projection,
                         triangles_ours=len(ours["faces"]), triangles_mc=len(faces)))
        m = {key: statistics.median(v) for key, v in t.items()}
        print(f"{label:8s} R={R}: ours {fmt(t['ours'])} s (extraction {fmt(t['extraction'])}); MC {fmt(t['ref'])} s "
              f"(lattice {fmt(t['lattice'])} by {best_lattice}, marching cubes {fmt(t['mc'])}); MC + projection "
              f"{fmt(t['ref_projected'])} s ({k_projection} thread{'s' if k_projection > 1 else ''}); ratios {m['ref'] / m['ours']:.2f}x, "
              f"{m['ref_projected'] / m['ours']:.2f}x; Hausdorff {errors['ours']['hausdorff']:.2g} / "
              f"{errors['mc']['hausdorff']:.2g} / {errors['mc_projected']['hausdorff']:.2g}, Chamfer L1 "
              f"{errors['ours']['chamfer_l1']:.2g} / {errors['mc']['chamfer_l1']:.2g} / "
              f"{errors['mc_projected']['chamfer_l1']:.2g}", flush=True)
busy_end, own_end, wall = *cpu_busy(), time.perf_counter() - wall_start
for pool in pools.values():
    pool.shutdown()
others = max(0.0, (busy_end - busy_start) - (own_end - own_start))
config.append(f"Quiet machine check: during the {wall:.0f} s of measurements other processes used {others:.1f} "
              f"CPU-seconds ({100 * others / (wall * CPUS):.1f}% of the {CPUS} CPUs); load average at the end "
              f"{os.getloadavg()[0]:.2f}.")
print(config[-1])


def speed_words(ratio, other):
    if ratio >= 1:
        return f"{ratio:.2f}x faster than {other}"
    return f"slower than {other}: {ratio:.2f}x its speed (sdfwb takes {1 / ratio:.2f}x as long)"


def accuracy_words(measure_name, ours, theirs, other):
    if ours > theirs:
        return f"{measure_name} {ours:.2g} against {theirs:.2g}: sdfwb is less accurate ({ours / theirs:.2f}x the error of {other})"
    return f"{measure_name} {ours:.2g} against {theirs:.2g}: sdfwb has {theirs / ours:.2f}x lower error than {other}"


verdicts = []
for row in rows:
    m = {key: statistics.median(v) for key, v in row["t"].items()}
    e = row["errors"]
    verdicts.append(
        f"{row['label']}: sdfwb.mesh is {speed_words(m['ref'] / m['ours'], 'plain marching cubes')} and "
        f"{speed_words(m['ref_projected'] / m['ours'], 'MC + projection')} (medians); like for like, "
        f"{accuracy_words('Hausdorff', e['ours']['hausdorff'], e['mc_projected']['hausdorff'], 'MC + projection')}; "
        f"{accuracy_words('Chamfer L1', e['ours']['chamfer_l1'], e['mc_projected']['chamfer_l1'], 'MC + projection')}.")
print("\n".join(verdicts))

if MARKDOWN:
    with open(MARKDOWN, "w") as out:
        out.write("# Mesh extraction against NumPy/PyTorch + scikit-image marching cubes\n\n")
        out.write(f"Generated by `{command}` (bench/bench_mesh.py; nothing below is typed by hand). "
                  f"Resolution {R}.\n\n")
        out.write("".join(f"- {line}\n" for line in config) + "\n")
        out.write("Times in seconds, median [min, max]. *MC* = lattice + marching cubes; *MC + projection* adds the "
                  "Newton post-pass ours also does. Ratios are reference median / our median (above 1: sdfwb is "
                  "faster).\n\n")
        out.write("| SDF | sdfwb.mesh s | of which extraction s | lattice s | lattice form | marching cubes s "
                  "(1 thread) | projection s | MC s | MC + projection s | MC / ours | MC + projection / ours |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|\n")
        for row in rows:
            t = row["t"]
            m = {key: statistics.median(v) for key, v in t.items()}
            out.write(f"| {row['label']} | {fmt(t['ours'])} | {fmt(t['extraction'])} | {fmt(t['lattice'])} | "
                      f"{row['lattice']} | {fmt(t['mc'])} | {fmt(t['projection'])} ({row['k_projection']} "
                      f"thread{'s' if row['k_projection'] > 1 else ''}) | {fmt(t['ref'])} | {fmt(t['ref_projected'])} "
                      f"| {m['ref'] / m['ours']:.2f}x | {m['ref_projected'] / m['ours']:.2f}x |\n")
        out.write("\n| SDF | Hausdorff sdfwb | Hausdorff MC | Hausdorff MC + projection | Chamfer L1 sdfwb | "
                  "Chamfer L1 MC | Chamfer L1 MC + projection | triangles sdfwb | triangles MC |\n"
                  "|---|---|---|---|---|---|---|---|---|\n")
        for row in rows:
            e = row["errors"]
            out.write(f"| {row['label']} | {e['ours']['hausdorff']:.2g} | {e['mc']['hausdorff']:.2g} | "
                      f"{e['mc_projected']['hausdorff']:.2g} | {e['ours']['chamfer_l1']:.2g} | "
                      f"{e['mc']['chamfer_l1']:.2g} | {e['mc_projected']['chamfer_l1']:.2g} | "
                      f"{row['triangles_ours']} | {row['triangles_mc']} |\n")
        out.write("\n" + "".join(f"- {line}\n" for line in verdicts))
        out.write("\n## Every reference form and thread count tried\n\n"
                  "| SDF | library | form | threads | s, median [min, max] |\n|---|---|---|---|---|\n")
        for label, library, form, k, times in forms_table:
            out.write(f"| {label} | {library} | {form} | {k} | {fmt(times)} |\n")
    print(f"wrote {MARKDOWN}")
