#!/usr/bin/env python3
"""Error against run time: sdfwb's mesher beside the meshers users already have, in one run (#33 point 3).

    flock /tmp/sdfwb-build.lock env -u DISPLAY PYTHONPATH=build/python /usr/bin/python3 bench/bench_mesh_peers.py
        [--repeats 3] [--resolutions 32,48,64,96,128,192,256] [--peer-resolutions 64,128,256] [--only NAME,...]
        [--markdown docs/meshing-peers.md] [--plot docs/images/mesh_peers_error_vs_time.png]

Ours: `sdfwb.mesh(sdf, resolution=R)`, the whole call timed (GL context, the bound estimated at the block centres, GPU field, dual contouring,
projection onto the surface), and `sdfwb.mesh(sdf, resolution=R, refine=K)` for the --refined R:K pairs (each triangle
cut into four K times, the new vertices put on the surface), whose rows count for the equal-error comparison.

Peers, each given the same field on the same (R+1)^3 lattice over [-1,1]^3, written for the peer (never sdfwb's):
- scikit-image `measure.marching_cubes` (Lewiner; single-threaded, its kernel holds the GIL);
- VTK `vtkFlyingEdges3D` (threaded through vtkSMPTools; every thread count from 1 to nproc is tried and the
  fastest kept), normals, gradients and scalars off;
- OpenVDB `volumeToMesh` through pyopenvdb's `FloatGrid.convertToPolygons(isovalue=0, adaptivity=0)` (threaded
  by TBB), the grid filled by `copyFromArray`, whose time counts; and the same on a narrow band (3 voxels a side
  active, the rest inactive tiles), as OpenVDB keeps level sets;
- VTK `vtkFlyingEdges3D` from C++ (bench/device/flying_edges_peer.cpp, built strict and with -ffast-math by
  bench/device/build_peer.sh, -march=native; the faster build kept, both printed): the field inline C++ over
  z-slabs, every thread count tried for the field and for Flying Edges, the fastest of each kept; and the same
  given sdfwb's post-processing (two Newton steps onto the surface; refinement at --peer-refined R:K).
The Python peers' field: bench/peer_fields.py (NumPy float32, checked against sdfwb by bench/check_peer_fields.py),
the fastest of the whole lattice and z-slabs over a ThreadPool of 1..nproc threads; its time counts for the peer.
Every time is the median of --repeats runs after a warm-up. Every mesh is graded by `sdfwb.evaluate_mesh` against
the exact field (100,000 points each way, tau as printed), with the edge measures (points near creases). One goal per
table is fixed in GOALS before the run. Nothing is typed by hand into the generated Markdown.
"""
import atexit
import concurrent.futures
import datetime
import json
import subprocess
import os
import platform
import resource
import shutil
import socket
import statistics
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import meshio
import numpy as np
import pyopenvdb
import skimage
import vtk
from skimage import measure
from vtk.util import numpy_support

import sdfwb

import peer_fields  # bench/peer_fields.py: the peers' own fields
from machine import cpu_model  # bench/machine.py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
args = sys.argv[1:]


def option(name, default):
    return args[args.index(name) + 1] if name in args else default


REPEATS = int(option("--repeats", "3"))
OURS_R = [int(r) for r in option("--resolutions", "16,24,32,48,64,96,128,192,256").split(",")]
# sdfwb.mesh(sdf, resolution=R, refine=K): the coarse grid's triangles cut into four K times, each new vertex put on the
# surface; R:K pairs.
REFINED = [tuple(int(v) for v in pair.split(":")) for pair in
           option("--refined", "16:2,16:3,24:2,24:3,32:2,32:3,48:1,48:2,64:1,64:2,96:1,128:1").split(",") if pair]
REFINED_TOOL = "sdfwb, refined"
PEER_R = [int(r) for r in option("--peer-resolutions", "64,128,256").split(",")]
ONLY = set(option("--only", "").split(",")) - {""}
# --scale: each tool once at 512 (and sdfwb and Flying Edges at 1024) in a process of its own, for its time and peak
# memory (VmHWM); SCALE_SHAPES names the shapes.
SCALE = "--scale" in args
SCALE_SHAPES = ["Sphere", "Rotated box", "Anvil"]
# --scale also grades every 512^3 mesh, and runs sdfwb at these (R, refine) in processes of their own, graded, for the
# equal-error comparison at 512^3.
SCALE_CANDIDATES = [(128, 0), (256, 0), (64, 3), (128, 2), (256, 1)]
MARKDOWN = option("--markdown", None)
PLOT = option("--plot", None)
TAU = 0.002
CPUS = os.cpu_count()
THREADS = list(range(1, CPUS + 1))
TOP = max(PEER_R)
FE_CPP = "VTK Flying Edges, C++ field"
# The same mesher given sdfwb's post-processing: two Newton steps onto the surface with the exact field (C++), and
# refinement (each triangle cut into four K times, the new vertices projected) at PEER_REFINED.
FE_PROJECTED = "Flying Edges C++ + projection"
NEWTON_STEPS = 2  # sdfwb's projection: two Newton steps along the gradient (meshing/src/DualContouring.cpp)
FE_REFINED = "Flying Edges C++ + projection, refined"
PEER_REFINED = [tuple(int(v) for v in pair.split(":")) for pair in
                option("--peer-refined", "32:2,64:1,64:2,128:1").split(",") if pair]
VDB_BAND = "OpenVDB volumeToMesh, narrow band"
CPP_PEER = option("--cpp-peer", os.path.join(ROOT, "build", "bench", "flying_edges_peer"))
# The C++ peer built strict (IEEE) and with -ffast-math, both -march=native: the faster is kept, both printed.
CPP_BUILDS = {"strict": CPP_PEER, "fast-math": CPP_PEER + "-fast"}

# One goal per table, fixed before the run (the generated page prints each and whether this run met it).
GOALS = {
    "equal error": "in every class the median equal-error ratio is at least 1: sdfwb reaches the best peer's "
                   "256^3 error no slower than the fastest peer run that reaches it, post-processed peers included",
    "equal resolution": "in every class sdfwb's median 256^3 whole call takes at most Flying Edges' time (ratio <= 1)",
    "scale": "at 512^3 and 1024^3 sdfwb's whole call is faster than every peer's, warm on both sides",
    "scale equal error": "at 512^3 sdfwb reaches the best peer's error faster than the fastest peer, on every shape",
}


# (label, class, the peers' name for it: bench/peer_fields.py's field and the C++ peer's SHAPE)
SHAPE_LIST = [
    ("Sphere", "smooth", "sphere"),
    ("Torus", "smooth", "torus"),
    ("Capsule", "smooth", "capsule"),
    ("Box", "box-like", "box"),
    ("Rotated box", "box-like", "rotated-box"),
    ("Hexagonal prism", "box-like", "hexagonalprism"),
    ("Rotated cylinder", "creased", "rotated-cylinder"),
    ("Anvil", "creased", "anvil"),
    ("hg_sdf arcade with chamfers (foreign)", "creased", "hg-arcade"),
    ("IQ primitives (foreign)", "creased", "iq-primitives"),
    ("jw CSG (foreign)", "creased", "jw-csg"),
    ("Open shell with a 0.03 wall", "thin-walled", "shell"),
    ("Mug", "thin-walled", "mug"),
    ("Menger sponge", "fractal", "mengersponge"),
    ("Sierpinski tetrahedron", "fractal", "sierpinskitetrahedron"),
]
# (label, class, sdf as sdfwb takes it, the peers' NumPy field)
SHAPES = [(label, cls, peer_fields.SDFWB_SOURCES[name], peer_fields.FIELDS[name]) for label, cls, name in SHAPE_LIST]
# The C++ peer's SHAPE for each label (bench/device/flying_edges_peer.cpp has every shape).
CPP_FIELDS = {label: name for label, _, name in SHAPE_LIST}
ROTATED_BOX, ROTATED_CYLINDER = peer_fields.ROTATED_BOX, peer_fields.ROTATED_CYLINDER
if "--write-glsl" in args:  # the tilted shapes as files, for bench/device/bundle.sh
    for name, text in (("rotated_box", ROTATED_BOX), ("rotated_cylinder", ROTATED_CYLINDER)):
        with open(os.path.join(option("--write-glsl", "."), name + ".glsl"), "w") as file:
            file.write(text + "\n")
    sys.exit(0)
if ONLY:
    SHAPES = [s for s in SHAPES if s[0] in ONLY]


def grid_of(row):
    """R, or R + K for a grid of R cells refined K times."""
    return f"{row['R']} + {row['refine']}" if row.get("refine") else str(row["R"])


def timed(function):
    started = time.perf_counter()
    result = function()
    return time.perf_counter() - started, result


def median_time(function, repeats=REPEATS):
    function()  # warm-up
    times, result = [], None
    for _ in range(repeats):
        t, result = timed(function)
        times.append(t)
    return statistics.median(times), result


# The peers' field on the (R+1)^3 lattice, [z][y][x] (x fastest), float32.
def lattice_numpy(field, R, pool=None, slab=32):
    axis = np.linspace(-1.0, 1.0, R + 1, dtype=np.float32)
    x, y, z = axis[None, None, :], axis[None, :, None], axis[:, None, None]
    if pool is None:
        values = field(x, y, z)
        return values if values.shape == (R + 1,) * 3 else np.broadcast_to(values, (R + 1,) * 3).copy()
    values = np.empty((R + 1,) * 3, np.float32)

    def work(z0):
        values[z0:z0 + slab] = field(x, y, z[z0:z0 + slab])

    list(pool.map(work, range(0, R + 1, slab)))
    return values


def field_forms(field, R, pools):
    """The peer's own field (bench/peer_fields.py, NumPy float32): the whole lattice on one thread, and z-slabs over a
    ThreadPool of every thread count. No peer's field comes from sdfwb."""
    forms = [("NumPy whole lattice, 1 thread", lambda: lattice_numpy(field, R))]
    for k in THREADS[1:]:
        forms.append((f"NumPy z-slabs, ThreadPool of {k}", lambda k=k: lattice_numpy(field, R, pools[k])))
    return forms


def skimage_mc(values, R):
    vertices, faces, _, _ = measure.marching_cubes(values, 0.0, spacing=(2.0 / R,) * 3)
    return np.ascontiguousarray(vertices[:, ::-1] - 1.0, dtype=np.float32), faces


def flying_edges(values, R):
    image = vtk.vtkImageData()
    image.SetDimensions(R + 1, R + 1, R + 1)
    image.SetSpacing(2.0 / R, 2.0 / R, 2.0 / R)
    image.SetOrigin(-1.0, -1.0, -1.0)
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(values.ravel(), deep=0, array_type=vtk.VTK_FLOAT))
    mesher = vtk.vtkFlyingEdges3D()
    mesher.SetInputData(image)
    mesher.SetValue(0, 0.0)
    mesher.ComputeNormalsOff()
    mesher.ComputeGradientsOff()
    mesher.ComputeScalarsOff()
    mesher.InterpolateAttributesOff()
    mesher.Update()
    out = mesher.GetOutput()
    if out.GetNumberOfPoints() == 0:
        return np.zeros((0, 3), np.float32), np.zeros((0, 3), np.int64)
    points = numpy_support.vtk_to_numpy(out.GetPoints().GetData()).astype(np.float32)
    faces = numpy_support.vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return points, faces


def openvdb_mesh(values, R):
    h = 2.0 / R
    grid = pyopenvdb.FloatGrid(background=float(3.0 * h))
    grid.copyFromArray(np.ascontiguousarray(values.transpose(2, 1, 0)), ijk=(0, 0, 0), tolerance=0.0)  # [x][y][z]
    grid.transform = pyopenvdb.createLinearTransform(voxelSize=h)
    points, triangles, quads = grid.convertToPolygons(isovalue=0.0, adaptivity=0.0)
    faces = np.concatenate([triangles.reshape(-1, 3), quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]]) if len(quads) else triangles
    return (points - 1.0).astype(np.float32), faces


def openvdb_band_mesh(values, R):
    """OpenVDB as its users keep a level set: a narrow band of 3 voxels active, the rest inactive tiles (outside the
    background, inside its negative by signedFloodFill), so volumeToMesh visits the band only. The lattice is still
    filled densely by the peer's field."""
    h = 2.0 / R
    band = np.float32(3.0 * h)
    banded = np.where(np.abs(values) < band, values, band)
    grid = pyopenvdb.FloatGrid(background=float(band))
    grid.copyFromArray(np.ascontiguousarray(banded.transpose(2, 1, 0)), ijk=(0, 0, 0), tolerance=0.0)
    grid.signedFloodFill()
    grid.transform = pyopenvdb.createLinearTransform(voxelSize=h)
    points, triangles, quads = grid.convertToPolygons(isovalue=0.0, adaptivity=0.0)
    faces = np.concatenate([triangles.reshape(-1, 3), quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]]) if len(quads) else triangles
    return (points - 1.0).astype(np.float32), faces


PEERS = {"scikit-image MC": skimage_mc, "VTK Flying Edges": flying_edges, "OpenVDB volumeToMesh": openvdb_mesh,
         VDB_BAND: openvdb_band_mesh}


def cpp_flying_edges(label, R, mesh_path, threads=None, binary=CPP_PEER, project=0, refine=0):
    """One run of the C++ peer (its field and Flying Edges each the fastest over the thread counts; `project` Newton
    steps and `refine` levels after it): its report, and its peak resident memory in MB."""
    extra = (["--project", str(project)] if project else []) + (["--refine", str(refine)] if refine else [])
    process = subprocess.Popen([binary, CPP_FIELDS[label], str(R), ",".join(map(str, threads or THREADS)), mesh_path]
                               + extra, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    out, err = process.communicate()
    if process.returncode != 0:
        raise RuntimeError(f"{binary} {CPP_FIELDS[label]} {R}: exit {process.returncode}: {err.strip()[-300:]}")
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0  # the largest child so far
    return json.loads(out), peak


def grade(vertices, faces, sdf, folder):
    if len(faces) == 0:
        return None
    path = os.path.join(folder, "m.ply")
    meshio.write(path, meshio.Mesh(np.asarray(vertices, np.float32), [("triangle", np.asarray(faces, np.int32))]),
                 binary=True)
    return sdfwb.evaluate_mesh(path, sdf, tau=TAU, occupancy_resolution=0)


def gl_renderer():
    with tempfile.TemporaryDirectory() as folder:
        report = sdfwb.run({"kind": "sample", "sdf": "sphere", "pattern": "rand", "n": 256,
                            "output": os.path.join(folder, "renderer.bin")})
    return report.get("gl_renderer") or "unknown"


def child_run(tool, label, R, refine=0, graded=False):
    """One tool on one shape at R in this (fresh) process: its whole call's time and this process's peak memory, and
    (graded) the mesh's Hausdorff and Chamfer-L1, measured after both."""
    sdf, field = next((s[2], s[3]) for s in SHAPES if s[0] == label)
    started = time.perf_counter()
    folder = tempfile.mkdtemp(prefix="sdfwb-scale-")
    atexit.register(shutil.rmtree, folder, True)

    def errors(vertices, faces):
        e = grade(vertices, faces, sdf, folder) if graded else None
        return dict(hausdorff=e["hausdorff"], chamfer_l1=e["chamfer_l1"]) if e else {}

    if tool == FE_CPP:
        path = os.path.join(folder, "m.ply")
        binary = CPP_BUILDS[option("--child-build", "strict")]
        cpp_flying_edges(label, 32, path, binary=binary)  # warm: the program and its libraries in the page cache
        report, peak = cpp_flying_edges(label, R, path, binary=binary)
        e = sdfwb.evaluate_mesh(path, sdf, tau=TAU, occupancy_resolution=0) if graded else None
        print("CHILD " + json.dumps(dict(seconds=report["seconds"], field_seconds=report["field_seconds"],
                                         triangles=report["triangles"], peak_mb=peak,
                                         **(dict(hausdorff=e["hausdorff"], chamfer_l1=e["chamfer_l1"]) if e else {}))))
        return
    if tool == "sdfwb":
        sdfwb.mesh(sdf, resolution=32, refine=refine)  # shaders compiled, GL context made: what a warm process has
        started = time.perf_counter()
        mesh = sdfwb.mesh(sdf, resolution=R, refine=refine)
        vertices, faces = mesh["vertices"], mesh["faces"]
        field_seconds = None
    else:
        # Warm, as sdfwb is: the pool made, the field and the mesher run once at 32^3.
        pool = concurrent.futures.ThreadPoolExecutor(CPUS)
        if tool == "VTK Flying Edges":
            vtk.vtkSMPTools.Initialize(CPUS)
        PEERS[tool](lattice_numpy(field, 32, pool), 32)
        started = time.perf_counter()
        values = lattice_numpy(field, R, pool)
        field_seconds = time.perf_counter() - started
        vertices, faces = PEERS[tool](values, R)
    seconds = time.perf_counter() - started
    # VmHWM: this process's own peak (ru_maxrss would carry the parent's over fork and exec).
    with open("/proc/self/status") as status:
        peak = next(int(line.split()[1]) for line in status if line.startswith("VmHWM:")) / 1024.0
    print("CHILD " + json.dumps(dict(seconds=seconds, field_seconds=field_seconds, triangles=len(faces), peak_mb=peak,
                                     **errors(vertices, faces))))


if "--child" in args:
    at = args.index("--child")
    child_run(args[at + 1], args[at + 2], int(args[at + 3]), int(option("--child-refine", "0")), "--graded" in args)
    sys.exit(0)

CPP_SOURCE = os.path.join(ROOT, "bench", "device", "flying_edges_peer.cpp")
if any(not os.path.exists(b) or os.path.getmtime(b) < os.path.getmtime(CPP_SOURCE) for b in CPP_BUILDS.values()):
    subprocess.run(["bash", os.path.join(ROOT, "bench", "device", "build_peer.sh"), CPP_PEER, "native"], check=True)
renderer = gl_renderer()
started = datetime.datetime.now(datetime.timezone.utc)
config = [
    f"Machine: {socket.gethostname()}, nproc {CPUS} ({cpu_model()}), {platform.system()} {platform.release()}; "
    f"started {started.strftime('%Y-%m-%d %H:%M')} UTC; GL renderer `{renderer}`"
    + (" (Mesa's CPU rasteriser, no GPU)" if "llvmpipe" in renderer else "") + ".",
    f"sdfwb {sdfwb.__version__}: `sdfwb.mesh(sdf, resolution=R)` at R = {', '.join(map(str, OURS_R))}, the whole "
    "call timed (GL context, the bound estimated at the block centres, GPU field, dual contouring, projection onto the surface); "
    f"and `sdfwb.mesh(sdf, resolution=R, refine=K)` ({REFINED_TOOL}: each triangle cut into four K times, every new vertex "
    f"stepped onto the exact surface) at R:K = {', '.join(f'{r}:{k}' for r, k in REFINED)}.",
    f"scikit-image {skimage.__version__} `measure.marching_cubes` (Lewiner), 1 thread (its kernel holds the GIL).",
    f"VTK {vtk.vtkVersion.GetVTKVersion()} `vtkFlyingEdges3D`, SMP backend {vtk.vtkSMPTools.GetBackend()}, "
    f"thread counts {', '.join(map(str, THREADS))} tried at each size, the fastest kept; normals, gradients, "
    "scalars off.",
    f"{FE_CPP}: VTK 9.1 `vtkFlyingEdges3D` called from C++ (`bench/device/flying_edges_peer.cpp`, g++ -O3 "
    "-march=native, Debian's libvtk9.1), the field written inline in C++ and filled in z-slabs; thread counts "
    f"{', '.join(map(str, THREADS))} tried for the field and for Flying Edges, the fastest of each kept; built strict "
    "(IEEE) and with -ffast-math, the faster kept for each run (both in \"The C++ peer's builds\"); every shape. Its time "
    f"is the median of {REPEATS} runs of the program. {FE_PROJECTED}: the same, then {NEWTON_STEPS} Newton steps onto "
    f"the surface with its C++ field (sdfwb's projection); {FE_REFINED}: then each triangle cut into four K times, the "
    f"new vertices projected (sdfwb's refinement) at R:K = {', '.join(f'{r}:{k}' for r, k in PEER_REFINED)}.",
    f"OpenVDB {'.'.join(map(str, pyopenvdb.LIBRARY_VERSION))} `volumeToMesh` (pyopenvdb "
    "`FloatGrid.convertToPolygons(isovalue=0, adaptivity=0)`, TBB threads), the dense lattice copied in by "
    f"`copyFromArray` (timed with it); quads split into two triangles. {VDB_BAND}: the same with only a band of 3 "
    "voxels each side of the surface active (the rest inactive tiles, signs by `signedFloodFill`), as OpenVDB keeps "
    "a level set.",
    f"The peers' field: written for the peer in NumPy {np.__version__} float32 (bench/peer_fields.py; checked against "
    "sdfwb's by bench/check_peer_fields.py), the fastest of the whole lattice on 1 thread and z-slabs over a ThreadPool "
    f"of {', '.join(map(str, THREADS[1:]))} threads, timed and added to each peer's time: the whole call, as a user "
    "would run it. No peer's field comes from sdfwb.",
    f"Peers at R = {', '.join(map(str, PEER_R))}. Every time is the median of {REPEATS} runs after a warm-up. "
    f"Errors: `sdfwb.evaluate_mesh(mesh, sdf, tau={TAU})`, 100,000 points each way against the exact field; edge "
    "measures over the points within 0.02 of a crease (the field's normal turning by over 30 degrees).",
]
print("\n".join(config), flush=True)

pools = {k: concurrent.futures.ThreadPoolExecutor(k) for k in THREADS}
results = []  # dict(label, cls, tool, R, seconds, field_seconds, triangles, eval)
field_choice = {}
cpp_choice = {}  # (label, tool, R, refine): (the build kept, {build: median seconds})


def cpp_row(label, cls, sdf, tool, R, folder, project=0, refine=0):
    """The C++ peer, strict and fast-math builds each REPEATS times; the faster build's median run kept (its mesh
    written again for grading), both builds' times recorded."""
    path = os.path.join(folder, "cpp.ply")
    medians = {}
    for build, binary in CPP_BUILDS.items():
        reports = [cpp_flying_edges(label, R, path, binary=binary, project=project, refine=refine)[0]
                   for _ in range(REPEATS)]
        medians[build] = sorted(reports, key=lambda r: r["seconds"])[len(reports) // 2]
    build = min(medians, key=lambda b: medians[b]["seconds"])
    report = medians[build]
    cpp_flying_edges(label, R, path, binary=CPP_BUILDS[build], project=project, refine=refine)  # its mesh, untimed
    cpp_choice[(label, tool, R, refine)] = (build, {b: r["seconds"] for b, r in medians.items()})
    e = sdfwb.evaluate_mesh(path, sdf, tau=TAU, occupancy_resolution=0)
    results.append(dict(label=label, cls=cls, tool=tool, R=R, refine=refine, seconds=report["seconds"],
                        mesh_seconds=report["mesh_seconds"], field_seconds=report["field_seconds"],
                        threads=report["mesh_threads"], triangles=report["triangles"], eval=e, build=build))
    post = f"; projection {report.get('project_seconds', 0):.3f}, refinement {report.get('refine_seconds', 0):.3f}" \
        if project or refine else ""
    print(f"{label:36s} {tool:20s} R={R:4d}{f' refine {refine}' if refine else ''} {report['seconds']:8.3f} s ({build}; "
          f"strict {medians['strict']['seconds']:.3f}, fast-math {medians['fast-math']['seconds']:.3f}; field "
          f"{report['field_seconds']:.3f}, {report['field_threads']} threads; mesher {report['mesh_seconds']:.3f}, "
          f"{report['mesh_threads']} threads{post})  Hausdorff {e['hausdorff']:.3g} Chamfer-L1 {e['chamfer_l1']:.3g}",
          flush=True)

wall_start = time.perf_counter()
with tempfile.TemporaryDirectory() as folder:
    for label, cls, sdf, field in SHAPES:
        print(f"{label}: starting at {time.perf_counter() - wall_start:.0f} s into the run", flush=True)
        for R in OURS_R:
            seconds, mesh = median_time(lambda: sdfwb.mesh(sdf, resolution=R))
            e = grade(mesh["vertices"], mesh["faces"], sdf, folder)
            results.append(dict(label=label, cls=cls, tool="sdfwb", R=R, seconds=seconds, field_seconds=None,
                                triangles=len(mesh["faces"]), eval=e,
                                watertight=mesh["report"].get("topology", {}).get("watertight")))
            print(f"{label:36s} sdfwb R={R:4d} {seconds:8.3f} s  Hausdorff {e['hausdorff']:.3g} "
                  f"Chamfer-L1 {e['chamfer_l1']:.3g}", flush=True)
        for R, K in REFINED:
            seconds, mesh = median_time(lambda: sdfwb.mesh(sdf, resolution=R, refine=K))
            e = grade(mesh["vertices"], mesh["faces"], sdf, folder)
            results.append(dict(label=label, cls=cls, tool=REFINED_TOOL, R=R, refine=K, seconds=seconds, field_seconds=None,
                                triangles=len(mesh["faces"]), eval=e))
            print(f"{label:36s} sdfwb R={R:4d} refine {K} {seconds:8.3f} s  Hausdorff {e['hausdorff']:.3g} "
                  f"Chamfer-L1 {e['chamfer_l1']:.3g}", flush=True)
        for R in PEER_R:
            forms = []
            for name, function in field_forms(field, R, pools):
                t, values = median_time(function)
                forms.append((t, name, values))
            field_seconds, field_name, values = min(forms, key=lambda f: f[0])
            field_choice[(label, R)] = (field_name, field_seconds, [(n, t) for t, n, _ in forms])
            for tool, mesher in PEERS.items():
                if tool == "VTK Flying Edges":
                    best = None
                    for k in THREADS:
                        vtk.vtkSMPTools.Initialize(k)
                        t, out = median_time(lambda: mesher(values, R))
                        if best is None or t < best[0]:
                            best = (t, out, k)
                    t, (vertices, faces), k = best
                    tool_name = f"{tool}"
                    threads = k
                else:
                    t, (vertices, faces) = median_time(lambda: mesher(values, R))
                    threads = None
                e = grade(vertices, faces, sdf, folder)
                results.append(dict(label=label, cls=cls, tool=tool_name if tool == "VTK Flying Edges" else tool, R=R,
                                    seconds=field_seconds + t, mesh_seconds=t, field_seconds=field_seconds,
                                    threads=threads, triangles=len(faces), eval=e))
                print(f"{label:36s} {tool:20s} R={R:4d} {field_seconds + t:8.3f} s (field {field_seconds:.3f} by "
                      f"{field_name}, mesher {t:.3f}{f', {threads} threads' if threads else ''})  Hausdorff "
                      f"{e['hausdorff'] if e else float('nan'):.3g} Chamfer-L1 {e['chamfer_l1'] if e else float('nan'):.3g}",
                      flush=True)
            if label in CPP_FIELDS:
                for tool, project in ((FE_CPP, 0), (FE_PROJECTED, NEWTON_STEPS)):
                    cpp_row(label, cls, sdf, tool, R, folder, project=project)
        if label in CPP_FIELDS:
            for R, K in PEER_REFINED:
                cpp_row(label, cls, sdf, FE_REFINED, R, folder, project=NEWTON_STEPS, refine=K)
wall = time.perf_counter() - wall_start
for pool in pools.values():
    pool.shutdown()
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
config.append(f"The run took {wall:.0f} s; peak memory of this process {peak:.0f} MB; load average at the end "
              f"{os.getloadavg()[0]:.2f}.")


scale_rows = []
if SCALE:
    for label in SCALE_SHAPES:
        cpp = [FE_CPP] if label in CPP_FIELDS else []
        # (tool, R, refine, graded, a candidate for the equal-error table rather than a row of the scale table)
        runs = [(tool, 512, 0, True, False) for tool in ["sdfwb", *PEERS, *cpp]]
        runs += [("sdfwb" if k == 0 else REFINED_TOOL, r, k, True, True) for r, k in SCALE_CANDIDATES]
        runs += [(tool, 1024, 0, False, False) for tool in ["sdfwb", "VTK Flying Edges", *cpp]]
        for tool, R, K, graded, candidate in runs:
            build = cpp_choice.get((label, FE_CPP, TOP, 0), ("strict",))[0]  # the faster build at TOP^3
            command = [sys.executable, os.path.abspath(__file__), "--child", "sdfwb" if tool == REFINED_TOOL else tool,
                       label, str(R), "--child-refine", str(K), "--child-build", build] + (["--graded"] if graded else [])
            run = subprocess.run(command, capture_output=True, text=True)
            line = next((l for l in run.stdout.splitlines() if l.startswith("CHILD ")), None)
            row = dict(label=label, tool=tool, R=R, refine=K, candidate=candidate)
            if run.returncode != 0 or line is None:
                row.update(failed=f"exit {run.returncode}: {run.stderr.strip()[-160:]}")
            else:
                row.update(failed=None, **json.loads(line[6:]))
            scale_rows.append(row)
            r = scale_rows[-1]
            print(f"scale {label:14s} {tool:22s} R={grid_of(r):>7s} " + (r["failed"] if r["failed"] else
                  f"{r['seconds']:7.2f} s, peak {r['peak_mb']:7.0f} MB, {r['triangles']} triangles"
                  + (f", Hausdorff {r['hausdorff']:.3g}, Chamfer-L1 {r['chamfer_l1']:.3g}" if "hausdorff" in r else "")),
                  flush=True)


def rows_of(label, tool):
    return sorted((r for r in results if r["label"] == label and r["tool"] == tool and r["eval"]), key=lambda r: r["R"])


def equal_error(label):
    """Our fastest call that reaches the best peer's error at the top peer resolution (both Hausdorff and
    Chamfer-L1, each the lowest of the peers there, post-processed peers included), against the fastest peer run of
    any size that reaches it too (else the fastest peer at the top resolution); None when no resolution of ours
    reaches it."""
    peer_rows = [r for r in results if r["label"] == label and r["tool"] not in ("sdfwb", REFINED_TOOL) and r["eval"]]
    tops = [r for r in peer_rows if r["R"] == TOP and not r.get("refine")]
    if not tops:
        return None
    best_h = min(r["eval"]["hausdorff"] for r in tops)
    best_c = min(r["eval"]["chamfer_l1"] for r in tops)
    reaching = [r for r in peer_rows if r["eval"]["hausdorff"] <= best_h and r["eval"]["chamfer_l1"] <= best_c]
    peer = min(reaching or tops, key=lambda r: r["seconds"])
    fastest_peer = peer["seconds"]
    ours = [r for r in rows_of(label, "sdfwb") + rows_of(label, REFINED_TOOL)
            if r["eval"]["hausdorff"] <= best_h and r["eval"]["chamfer_l1"] <= best_c]
    if not ours:
        return dict(best_h=best_h, best_c=best_c, peer_seconds=fastest_peer, peer=peer, ours=None)
    first = min(ours, key=lambda r: r["seconds"])
    return dict(best_h=best_h, best_c=best_c, peer_seconds=fastest_peer, peer=peer, ours=first,
                ratio=fastest_peer / first["seconds"])


def fmt(v, spec=".3g"):
    return "n/a" if v is None else format(v, spec)


verdicts = []
classes = []
for label, cls, _, _ in SHAPES:
    if cls not in classes:
        classes.append(cls)
summary_rows = []
for label, cls, _, _ in SHAPES:
    eq = equal_error(label)
    ours_top = next((r for r in rows_of(label, "sdfwb") if r["R"] == TOP), None)
    fe_top = min((r for tool in ("VTK Flying Edges", FE_CPP) for r in rows_of(label, tool) if r["R"] == TOP),
                 key=lambda r: r["seconds"], default=None)  # the faster of Python's and C++'s
    peers_top = [r for r in results if r["label"] == label and r["tool"] not in ("sdfwb", REFINED_TOOL) and r["R"] == TOP
                 and not r.get("refine") and r["eval"]]
    summary_rows.append(dict(label=label, cls=cls, eq=eq, ours=ours_top, fe=fe_top, peers=peers_top))

def goal_line(name, met):
    return f"- **Goal** (fixed before the run): {GOALS[name]}. **{'Met' if met else 'Not met'}** in this run.\n"


SPARSE = ("What is compared: sdfwb evaluates its field sparsely (blocks its Lipschitz bound rules out are skipped); every "
          "peer here fills the dense (R+1)^3 lattice with its own field. The OpenVDB narrow-band row meshes a sparse "
          "grid (3 voxels a side of the surface active) but its field is still filled densely: no peer in this bench "
          "evaluates its field sparsely.\n")
lines = []
lines.append("## Equal error: the time sdfwb needs to reach the best peer's error at "
             f"{TOP}^3\n")
lines.append(f"The best peer's Hausdorff and Chamfer-L1 at R = {TOP} (each the lowest of the peers, {FE_PROJECTED} "
             "included: the same two Newton steps sdfwb takes), the fastest peer run of any size that reaches both "
             f"({FE_REFINED} included: the same refinement sdfwb's refined rows get; else the fastest peer at R = "
             f"{TOP}), and sdfwb's fastest call whose mesh is at least as good on both, refined or not (R + K: a grid "
             "of R cells, refined K times). Ratio = peer time / sdfwb time (above 1: sdfwb is faster).\n")
lines.append(SPARSE)
equal_error_ratios = {}
for cls in classes:
    ratios = [s["eq"]["ratio"] if s["eq"] and s["eq"]["ours"] else 0.0 for s in summary_rows if s["cls"] == cls]
    if ratios:
        equal_error_ratios[cls] = (statistics.median(ratios), len(ratios))
lines.append(goal_line("equal error", all(m >= 1.0 for m, _ in equal_error_ratios.values())))
lines.append("| shape | class | best peer Hausdorff | best peer Chamfer-L1 | fastest peer reaching it | s | sdfwb R | "
             "sdfwb s | ratio |\n|---|---|---|---|---|---|---|---|---|")
for s in summary_rows:
    eq = s["eq"]
    if eq is None:
        lines.append(f"| {s['label']} | {s['cls']} | n/a | n/a | n/a | n/a | n/a | n/a | n/a |")
        continue
    peer = f"{eq['peer']['tool']}, {grid_of(eq['peer'])}"
    if eq["ours"] is None:
        lines.append(f"| {s['label']} | {s['cls']} | {eq['best_h']:.3g} | {eq['best_c']:.3g} | {peer} | "
                     f"{eq['peer_seconds']:.3f} | not reached by R = {max(OURS_R)} | | **slower** |")
    else:
        lines.append(f"| {s['label']} | {s['cls']} | {eq['best_h']:.3g} | {eq['best_c']:.3g} | {peer} | "
                     f"{eq['peer_seconds']:.3f} | {grid_of(eq['ours'])} | {eq['ours']['seconds']:.3f} | "
                     f"{eq['ratio']:.2f}x |")
lines.append("")
for cls, (median, count) in equal_error_ratios.items():
    lines.append(f"- {cls}: median equal-error ratio {median:.2f}x over {count} shapes "
                 "(a shape whose error sdfwb does not reach counts as 0).")
lines.append("")
lines.append(f"## Equal resolution {TOP}^3\n")
lines.append("Time ratio = sdfwb's whole call / Flying Edges' whole call (field + mesher, from C++ or from Python, "
             "whichever is faster; below 1: sdfwb is faster). Error ratios = sdfwb's / the peer's (below 1: sdfwb is more "
             f"accurate); FE+P is {FE_PROJECTED}.\n")
lines.append(SPARSE)
resolution_ratios = {}
for cls in classes:
    group = [s for s in summary_rows if s["cls"] == cls and s["ours"] and s["fe"]]
    if group:
        resolution_ratios[cls] = statistics.median(s["ours"]["seconds"] / s["fe"]["seconds"] for s in group)
lines.append(goal_line("equal resolution", all(r <= 1.0 for r in resolution_ratios.values())))
lines.append("| shape | class | sdfwb s | Flying Edges s | time ratio | Hausdorff sdfwb | Hausdorff / MC, FE, VDB, FE+P | "
             "Chamfer-L1 sdfwb | Chamfer-L1 / MC, FE, VDB, FE+P | edge F sdfwb | edge F MC, FE, VDB, FE+P |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|")
for s in summary_rows:
    o, fe = s["ours"], s["fe"]
    if not o or not fe:
        continue
    peers = {r["tool"]: r for r in s["peers"]}
    order = ["scikit-image MC", "VTK Flying Edges", "OpenVDB volumeToMesh", FE_PROJECTED]

    def ratio(key):
        return ", ".join(fmt(o["eval"][key] / peers[t]["eval"][key], ".2f") if t in peers and peers[t]["eval"][key] > 0
                         else "n/a" for t in order)

    def edge_f(r):
        return r["eval"]["edges"]["fscore"] if r["eval"].get("edges") else None

    lines.append(f"| {s['label']} | {s['cls']} | {o['seconds']:.3f} | {fe['seconds']:.3f} | "
                 f"{o['seconds'] / fe['seconds']:.2f} | {o['eval']['hausdorff']:.3g} | {ratio('hausdorff')} | "
                 f"{o['eval']['chamfer_l1']:.3g} | {ratio('chamfer_l1')} | {fmt(edge_f(o))} | "
                 f"{', '.join(fmt(edge_f(peers[t])) if t in peers else 'n/a' for t in order)} |")
lines.append("")
for cls in classes:
    group = [s for s in summary_rows if s["cls"] == cls and s["ours"] and s["fe"]]
    if not group:
        continue
    time_ratio = statistics.median(s["ours"]["seconds"] / s["fe"]["seconds"] for s in group)
    h_ratio = statistics.median(max(s["ours"]["eval"]["hausdorff"] / p["eval"]["hausdorff"] for p in s["peers"])
                                for s in group)
    c_ratio = statistics.median(max(s["ours"]["eval"]["chamfer_l1"] / p["eval"]["chamfer_l1"] for p in s["peers"])
                                for s in group)
    lines.append(f"- {cls} ({len(group)} shapes), medians: sdfwb takes {time_ratio:.2f}x Flying Edges' time; its "
                 f"Hausdorff is {h_ratio:.2f}x and its Chamfer-L1 {c_ratio:.2f}x the most accurate peer's "
                 "(the largest of its ratios to the peers per shape).")
lines.append("")
if scale_rows:
    lines.append("## Scale: 512^3 and 1024^3\n")
    lines.append("Each tool once, in a process of its own (`--scale`), warm on both sides: each process first runs the "
                 "same tool at 32^3 (sdfwb compiles its shaders and makes its GL context; a peer makes its thread pool "
                 "and runs its field and mesher; the C++ peer runs once, its faster build at 256^3), then is timed: the "
                 f"whole call (the peers' field by NumPy z-slabs on {CPUS} threads; {FE_CPP}'s by C++ threads) and the "
                 "process's peak resident memory (VmHWM, Python and the libraries included). Ratio = the tool's time / "
                 "sdfwb's at the same size.\n")
    lines.append(SPARSE)
    slower = [r for r in scale_rows if not r["failed"] and not r["candidate"] and r["tool"] != "sdfwb" and any(
        o["label"] == r["label"] and o["R"] == r["R"] and o["tool"] == "sdfwb" and not o["failed"] and not o["candidate"]
        and o["seconds"] >= r["seconds"] for o in scale_rows)]
    lines.append(goal_line("scale", not slower and not any(r["failed"] for r in scale_rows)))
    lines.append("| shape | R | tool | whole call s | of which field s | peak memory MB | triangles | time / sdfwb's |\n"
                 "|---|---|---|---|---|---|---|---|")
    for r in scale_rows:
        if r["candidate"]:
            continue
        ours = next((o for o in scale_rows if o["label"] == r["label"] and o["R"] == r["R"] and o["tool"] == "sdfwb"
                     and not o["failed"] and not o["candidate"]), None)
        if r["failed"]:
            lines.append(f"| {r['label']} | {r['R']} | {r['tool']} | failed: {r['failed']} | | | | |")
            continue
        lines.append(f"| {r['label']} | {r['R']} | {r['tool']} | {r['seconds']:.2f} | {fmt(r['field_seconds'], '.2f')} | "
                     f"{r['peak_mb']:.0f} | {r['triangles']} | "
                     f"{(r['seconds'] / ours['seconds']) if ours else float('nan'):.2f}x |")
    lines.append("")
    lines.append("### Equal error at 512^3\n")
    lines.append("The same processes graded (after their time and memory were taken): the best peer's Hausdorff and "
                 "Chamfer-L1 at 512^3 (each the lowest of the peers), the fastest peer's whole call at 512^3, and "
                 "sdfwb's fastest call whose mesh is at least as good on both, among 512 and the candidates "
                 f"{', '.join(f'{r} + {k}' if k else str(r) for r, k in SCALE_CANDIDATES)} (R + K: refined K times), each "
                 "in a process of its own. Ratio = peer time / sdfwb time.\n")
    scale_met = True
    for label in SCALE_SHAPES:
        graded = [r for r in scale_rows if r["label"] == label and not r["failed"] and "hausdorff" in r]
        peers = [r for r in graded if r["tool"] not in ("sdfwb", REFINED_TOOL)]
        if peers:
            best_h = min(r["hausdorff"] for r in peers)
            best_c = min(r["chamfer_l1"] for r in peers)
            fastest = min(r["seconds"] for r in peers)
            scale_met = scale_met and any(r["tool"] in ("sdfwb", REFINED_TOOL) and r["hausdorff"] <= best_h
                                          and r["chamfer_l1"] <= best_c and r["seconds"] <= fastest for r in graded)
    lines.append(goal_line("scale equal error", scale_met))
    lines.append("| shape | best peer Hausdorff | best peer Chamfer-L1 | fastest peer | s | sdfwb R | sdfwb s | "
                 "sdfwb peak MB | ratio |\n|---|---|---|---|---|---|---|---|---|")
    for label in SCALE_SHAPES:
        graded = [r for r in scale_rows if r["label"] == label and not r["failed"] and "hausdorff" in r]
        peers = [r for r in graded if r["tool"] not in ("sdfwb", REFINED_TOOL)]
        if not peers:
            continue
        best_h = min(r["hausdorff"] for r in peers)
        best_c = min(r["chamfer_l1"] for r in peers)
        fastest = min(peers, key=lambda r: r["seconds"])
        ours = [r for r in graded if r["tool"] in ("sdfwb", REFINED_TOOL) and r["hausdorff"] <= best_h
                and r["chamfer_l1"] <= best_c]
        if not ours:
            lines.append(f"| {label} | {best_h:.3g} | {best_c:.3g} | {fastest['tool']} | {fastest['seconds']:.2f} | "
                         "not reached | | | **slower** |")
            continue
        first = min(ours, key=lambda r: r["seconds"])
        lines.append(f"| {label} | {best_h:.3g} | {best_c:.3g} | {fastest['tool']} | {fastest['seconds']:.2f} | "
                     f"{grid_of(first)} | {first['seconds']:.3f} | {first['peak_mb']:.0f} | "
                     f"{fastest['seconds'] / first['seconds']:.2f}x |")
    lines.append("")
    lines.append("| shape | tool | R | whole call s | peak memory MB | triangles | Hausdorff | Chamfer-L1 |\n"
                 "|---|---|---|---|---|---|---|---|")
    for r in scale_rows:
        if not r["failed"] and "hausdorff" in r:
            lines.append(f"| {r['label']} | {r['tool']} | {grid_of(r)} | {r['seconds']:.3f} | {r['peak_mb']:.0f} | "
                         f"{r['triangles']} | {r['hausdorff']:.3g} | {r['chamfer_l1']:.3g} |")
    lines.append("")
# Where a peer wins, from the tables above: said plainly, one line each.
wins = []
for s in summary_rows:
    eq = s["eq"]
    if eq and eq["ours"] is None:
        wins.append(f"equal error, {s['label']} ({s['cls']}): no sdfwb call reaches the best peer's {TOP}^3 error.")
    elif eq and eq["ratio"] < 1.0:
        wins.append(f"equal error, {s['label']} ({s['cls']}): the fastest peer reaches its {TOP}^3 error in "
                    f"{eq['peer_seconds']:.3f} s, sdfwb in {eq['ours']['seconds']:.3f} s ({grid_of(eq['ours'])}): "
                    f"the peer is {1.0 / eq['ratio']:.2f}x faster.")
for s in summary_rows:
    o, fe = s["ours"], s["fe"]
    if o and fe and o["seconds"] > fe["seconds"]:
        wins.append(f"equal resolution {TOP}^3, {s['label']} ({s['cls']}): {fe['tool']} takes {fe['seconds']:.3f} s, "
                    f"sdfwb {o['seconds']:.3f} s ({o['seconds'] / fe['seconds']:.2f}x).")
    for p in s["peers"]:
        for key, name in (("hausdorff", "Hausdorff"), ("chamfer_l1", "Chamfer-L1")):
            if o and p["eval"][key] < o["eval"][key]:
                wins.append(f"equal resolution {TOP}^3, {s['label']}: {p['tool']}'s {name} {p['eval'][key]:.3g} is below "
                            f"sdfwb's {o['eval'][key]:.3g}.")
for r in scale_rows:
    if r["failed"] or r["candidate"] or r["tool"] == "sdfwb":
        continue
    ours = next((o for o in scale_rows if o["label"] == r["label"] and o["R"] == r["R"] and o["tool"] == "sdfwb"
                 and not o["failed"] and not o["candidate"]), None)
    if ours and r["seconds"] < ours["seconds"]:
        wins.append(f"scale {r['R']}^3, {r['label']}: {r['tool']} takes {r['seconds']:.2f} s, sdfwb {ours['seconds']:.2f} s "
                    f"({ours['seconds'] / r['seconds']:.2f}x slower), at {r['peak_mb']:.0f} MB against sdfwb's "
                    f"{ours['peak_mb']:.0f} MB.")
# The lent GPU machine's run (docs/meshing-gpu.md, raw rows in docs/data/meshing-gpu.jsonl): where Flying Edges from
# C++ beat sdfwb there, quoted with that run's machine line.
gpu_rows_path = os.path.join(ROOT, "docs", "data", "meshing-gpu.jsonl")
if os.path.exists(gpu_rows_path):
    with open(gpu_rows_path) as rows_file:
        gpu_rows = [json.loads(line) for line in rows_file if line.strip()]
    machine = next((r for r in gpu_rows if r.get("kind") == "machine"), {})
    for fe in (r for r in gpu_rows if r.get("kind") == "flying_edges"):
        ours = next((r for r in gpu_rows if r.get("kind") == "ours" and r["label"] == fe["label"] and r["R"] == fe["R"]),
                    None)
        if ours and fe["R"] >= 512 and fe["seconds"] < ours["seconds"]:
            wins.append(f"GPU run (docs/meshing-gpu.md, {machine.get('gpu', '?')}, nproc {machine.get('nproc', '?')}, "
                        f"{machine.get('started', '?')}), {fe['R']}^3, {fe['label']}: Flying Edges from C++ takes "
                        f"{fe['seconds']:.3f} s, sdfwb {ours['seconds']:.3f} s ({ours['seconds'] / fe['seconds']:.1f}x "
                        "slower); not re-run since (no GPU lent).")
lines.append("## Where a peer wins\n")
lines.append("\n".join(f"- {w}" for w in wins) if wins else "- Nowhere in this run.")
lines.append("")
lines.append("## Every run\n")
lines.append("| shape | tool | R | whole call s | of which field s (form) | triangles | Hausdorff | Chamfer-L1 | "
             "normal consistency | F-score | edge Chamfer-L1 | edge F-score | closed |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in results:
    e = r["eval"]
    form = ("" if r["tool"] in ("sdfwb", REFINED_TOOL) else f"C++ inline, {r['build']} build" if r.get("build") else
            field_choice.get((r["label"], r["R"]), ("", 0, []))[0])
    edges = e.get("edges") if e else None
    threads = f" ({r['threads']} threads)" if r.get("threads") else ""
    lines.append(f"| {r['label']} | {r['tool']}{threads} | {grid_of(r)} | {r['seconds']:.3f} | "
                 f"{fmt(r['field_seconds'], '.3f')}{f' ({form})' if form else ''} | {r['triangles']} | "
                 f"{fmt(e['hausdorff'] if e else None)} | {fmt(e['chamfer_l1'] if e else None)} | "
                 f"{fmt(e['normal_consistency'] if e else None, '.4f')} | {fmt(e['fscore'] if e else None, '.4f')} | "
                 f"{fmt(edges['chamfer_l1'] if edges else None)} | {fmt(edges['fscore'] if edges else None, '.4f')} | "
                 f"{'yes' if e and e['closed'] else 'no'} |")
lines.append("")
lines.append("## Every field form tried for the peers\n")
lines.append("| shape | R | form | s |\n|---|---|---|---|")
for (label, R), (_, _, forms) in field_choice.items():
    for name, t in forms:
        lines.append(f"| {label} | {R} | {name} | {t:.3f} |")
lines.append("")
lines.append("## The C++ peer's builds\n")
lines.append("Each C++ run in both builds (g++ -O3 -march=native, strict IEEE and -ffast-math), the median of "
             f"{REPEATS} runs each; the faster is the row above.\n")
lines.append("| shape | tool | R | strict s | fast-math s | kept |\n|---|---|---|---|---|---|")
for (label, tool, R, refine), (build, times) in cpp_choice.items():
    lines.append(f"| {label} | {tool} | {f'{R} + {refine}' if refine else R} | {times['strict']:.3f} | "
                 f"{times['fast-math']:.3f} | {build} |")
print("\n".join(lines))

if PLOT:
    columns = min(3, len(classes))
    rows_count = (len(classes) + columns - 1) // columns
    figure, axes = plt.subplots(rows_count, columns, figsize=(5.5 * columns, 4.5 * rows_count), squeeze=False)
    for ax in axes.flat[len(classes):]:
        ax.axis("off")
    colours = {"sdfwb": "C3", REFINED_TOOL: "C6", "scikit-image MC": "C0", "VTK Flying Edges": "C2",
               "OpenVDB volumeToMesh": "C1", VDB_BAND: "C8", FE_CPP: "C4", FE_PROJECTED: "C5", FE_REFINED: "C9"}
    for ax, cls in zip(axes.flat, classes):
        for label, c, _, _ in SHAPES:
            if c != cls:
                continue
            for tool, colour in colours.items():
                rows = sorted(rows_of(label, tool), key=lambda r: r["seconds"])
                if tool == REFINED_TOOL:  # the lower envelope: each row better than every faster one
                    rows = [r for i, r in enumerate(rows) if all(r["eval"]["chamfer_l1"] < q["eval"]["chamfer_l1"]
                                                                 for q in rows[:i])]
                if rows:
                    ax.loglog([r["seconds"] for r in rows], [r["eval"]["chamfer_l1"] for r in rows], "o-", color=colour,
                              alpha=0.6, markersize=3, label=tool if label == next(
                                  s[0] for s in SHAPES if s[1] == cls) else None)
        ax.set_title(f"{cls}")
        ax.set_xlabel("whole call, s")
        ax.set_ylabel("Chamfer-L1")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    figure.suptitle(f"Chamfer-L1 against time, one line per shape and tool ({started.strftime('%Y-%m-%d')}, "
                    f"{socket.gethostname()}, nproc {CPUS})", fontsize=9)
    figure.tight_layout()
    figure.savefig(PLOT, dpi=110)
    print(f"wrote {PLOT}")

if MARKDOWN:
    command = " ".join(["env -u DISPLAY PYTHONPATH=build/python", sys.executable, "bench/bench_mesh_peers.py"] + args)
    with open(MARKDOWN, "w") as out:
        out.write("# Meshes: sdfwb against scikit-image, VTK Flying Edges (from Python and from C++) and OpenVDB\n\n")
        out.write(f"Generated by `{command}` (bench/bench_mesh_peers.py; nothing below is typed by hand).\n\n")
        out.write("".join(f"- {line}\n" for line in config) + "\n")
        if PLOT:
            out.write(f"![Chamfer-L1 against time]({os.path.relpath(PLOT, os.path.dirname(MARKDOWN))})\n\n")
        out.write("\n".join(lines) + "\n")
    print(f"wrote {MARKDOWN}")
