#!/usr/bin/env python3
"""Meshes in, measured: sign errors of each method on every shared mesh and on broken variants of the
closed ones, and points per second against Open3D's RaycastingScene in the same run. Writes
docs/mesh-sdf.md.

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_mesh_sdf.py [--points N] [--speed-points M] [--meshes DIR]

Every mesh is normalised to the unit cube (sdfwb's --normalize unit-cube; the same transform applied
to the file for Open3D). Sign: uniform points in [-1.1, 1.1]^3 farther than 1 % of the bounding box's
diagonal from the surface. On a closed mesh the truth is what sdfwb's winding numbers, sdfwb's
pseudonormals agree on, where both agree (the share where they do not is printed); a broken variant (1 % and 5 % of faces removed, 10 % flipped, a
duplicated shell) is graded against its closed original's truth. Open meshes have no truth: the
table gives how often each method disagrees with winding numbers.
Speed: the same M points and the same normalised mesh file through sdfwb.evaluate (value + exact
gradient; the CPU engine on 1 and all threads, the GLSL field on llvmpipe for scale), the C++
references of bench/mesh_sdf_reference.cpp (Embree and CGAL, each sign method, every compile
variant of bench/build_mesh_sdf_reference.sh, 1 and all threads) and Open3D's unsigned
compute_distance, each timed after a warm-up, best of 3; accuracy beside each against
bench/mesh_sdf_truth.py (float64 brute force, exact winding numbers) on a subset.
Scale: a 1.1 M-triangle mesh made from the bunny (two rounds of midpoint subdivision) at
--big-points (10 M) points against the bunny's fastest reference configuration, one timed call each. The same shape as GLSL: a torus mesh
against sdfwb's own GLSL torus at the same points.
"""
import datetime
import json
import os
import platform
import re
import subprocess
import sys
import tempfile
import time

import numpy as np
import open3d as o3d

import sdfwb

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesh_sdf_truth  # noqa: E402
from mesh_io import read_obj, subdivide, write_obj, write_ply  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def option(name, default):
    return type(default)(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default


POINTS = option("--points", 200000)
SPEED_POINTS = option("--speed-points", 400000)
BIG_POINTS = option("--big-points", 10000000)
BIG_TRUTH_POINTS = option("--big-truth-points", 200)
GLSL_POINTS = option("--glsl-points", 50000)
MESHES = option("--meshes", os.path.normpath(os.path.join(ROOT, "..", "shared", "data", "meshes")))
OUT = os.path.join(ROOT, "docs", "mesh-sdf.md")
SDFWB = os.path.join(ROOT, "build", "app", "sdfwb")
METHODS = ["winding", "pseudonormal", "parity"]
work = tempfile.mkdtemp(prefix="sdfwb-mesh-sdf-")






def unit_cube(vertices):
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    return (vertices - (lo + hi) / 2) * (2.0 / (hi - lo).max())


def damaged(vertices, faces, kind, seed=7):
    rng = np.random.default_rng(seed)
    order = rng.permutation(len(faces))
    if kind == "1% removed":
        return vertices, np.delete(faces, order[: round(0.01 * len(faces))], axis=0)
    if kind == "5% removed":
        return vertices, np.delete(faces, order[: round(0.05 * len(faces))], axis=0)
    if kind == "10% flipped":
        out = faces.copy()
        chosen = order[: round(0.10 * len(faces))]
        out[chosen] = out[chosen][:, ::-1]
        return vertices, out
    if kind == "shell duplicated":
        return np.vstack([vertices, vertices]), np.vstack([faces, faces + len(vertices)])
    raise ValueError(kind)


def sdfwb_signs(path, points, sign):
    return sdfwb.evaluate(path, points, gradient=False, sign=sign, normalize="unit-cube")["distance"] < 0


def open3d_scene(vertices, faces, threads=0):
    scene = o3d.t.geometry.RaycastingScene(nthreads=threads)
    scene.add_triangles(o3d.core.Tensor(vertices.astype(np.float32)), o3d.core.Tensor(faces.astype(np.uint32)))
    return scene






def hierarchy_line(path):
    # The hierarchy's size and build time, as sdfwb logs them when it opens the mesh.
    log = subprocess.run([SDFWB, "--batch", "sample", "--sdf", path, "--normalize",
                          "unit-cube", "--pattern", "rand", "-n", "1000", "--output", os.path.join(work, "h.npz")],
                         capture_output=True, text=True).stderr
    match = re.search(r"hierarchy of (\d+) nodes, depth (\d+), built in ([0-9.]+) s, ([0-9.]+) MB", log)
    return (int(match.group(1)), int(match.group(2)), float(match.group(3)), float(match.group(4))) if match else None


def timed(call):
    call_start = time.perf_counter()
    result = call()
    return time.perf_counter() - call_start, result


def open3d_signs(vertices, faces, points):
    distance = open3d_scene(unit_cube(vertices), faces).compute_signed_distance(o3d.core.Tensor(points)).numpy()
    return distance < 0


def far_points(vertices, faces, count, seed):
    rng = np.random.default_rng(seed)
    points = rng.uniform(-1.1, 1.1, (count, 3)).astype(np.float32)
    scene = open3d_scene(unit_cube(vertices), faces)
    unsigned = scene.compute_distance(o3d.core.Tensor(points)).numpy()
    diagonal = np.linalg.norm(unit_cube(vertices).max(axis=0) - unit_cube(vertices).min(axis=0))
    return points[unsigned > 0.01 * diagonal]


def best_of(call, repeats=3):
    call()  # warm-up: compiles the shader / builds the scene's acceleration structure
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return min(times)


REFERENCE_SOURCE = os.path.join(ROOT, "bench", "mesh_sdf_reference.cpp")
REFERENCE_DIR = os.path.join(work, "reference")
TRUTH_POINTS = option("--truth-points", 1000)
THREADS = sorted({1, os.cpu_count() or 1})
reference_lines = []
reference_notes = {}


def build_references():
    # The C++ references, compiled here in every variant the build script makes (it prints its lines).
    built = subprocess.run(["bash", os.path.join(ROOT, "bench", "build_mesh_sdf_reference.sh"), REFERENCE_DIR],
                           capture_output=True, text=True)
    if built.returncode != 0:
        raise SystemExit("bench_mesh_sdf: building the C++ references failed:\n" + built.stdout + built.stderr)
    reference_lines.extend(line for line in built.stdout.splitlines() if line.strip())
    return sorted(os.path.join(REFERENCE_DIR, f) for f in os.listdir(REFERENCE_DIR)
                  if os.access(os.path.join(REFERENCE_DIR, f), os.X_OK) and not f.endswith(".o"))


def run_reference(binary, engine, sign, mesh_path, points_path, threads, repeat=3):
    values = os.path.join(work, "reference_values.f32")
    gradients = os.path.join(work, "reference_gradients.f32")
    command = [binary, "--engine", engine, "--sign", sign, "--mesh", mesh_path, "--points", points_path, "--out", values,
               "--gradient", gradients, "--threads", str(threads), "--repeat", str(repeat)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        print(f"reference failed: {' '.join(command)}: {done.stderr.strip()}", file=sys.stderr, flush=True)
        return None
    info = json.loads(done.stdout.strip().splitlines()[-1])
    info["binary"] = os.path.basename(binary)
    reference_notes.setdefault(f"{engine}, {sign}", info.get("notes", ""))
    info["values"] = np.fromfile(values, "<f4")
    return info


def accuracy(values, truth_distance, truth_inside, signed=True):
    # Largest |d| error against the float64 brute force and the share of wrong signs against the
    # exact winding numbers, over the truth subset (signs only farther than 1e-4 from the surface).
    k = len(truth_distance)
    error = float(np.max(np.abs(np.abs(values[:k].astype(np.float64)) - truth_distance)))
    if not signed:
        return error, None
    far = truth_distance > 1e-4
    return error, float(np.mean((values[:k] < 0)[far] != truth_inside[far]))


def with_environment(variables, call):
    saved = {k: os.environ.get(k) for k in variables}
    os.environ.update(variables)
    try:
        return call()
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def shared_points(unit, faces, seed, count, truth_count, stem):
    # Uniform points in [-1.1, 1.1]^3 as every program reads them (a float32 file), and the truth on
    # the first truth_count: float64 brute-force distances and exact winding numbers' inside.
    points = np.random.default_rng(seed).uniform(-1.1, 1.1, (count, 3)).astype(np.float32)
    points_path = os.path.join(work, stem + ".f32")
    points.tofile(points_path)
    subset = points[:truth_count]
    truth_distance = mesh_sdf_truth.closest_distances(unit, faces, subset)
    return points, points_path, truth_distance, mesh_sdf_truth.winding_numbers(unit, faces, subset) > 0.5


def speed_row(name, vertices, faces):
    # The same points and the same (normalised) mesh file for sdfwb and every reference.
    unit = unit_cube(vertices)
    mesh_path = write_obj(os.path.join(work, "unit_" + name), unit, faces)
    points, points_path, truth_distance, truth_inside = shared_points(unit, faces, 2, SPEED_POINTS, TRUTH_POINTS, "points")
    row = {"mesh": name, "triangles": len(faces), "entries": []}

    def add(label, configuration, seconds, count, values, signed=True):
        error, wrong = accuracy(values, truth_distance, truth_inside, signed)
        row["entries"].append({"label": label, "configuration": configuration, "rate": count / seconds,
                               "seconds": seconds, "error": error, "wrong": wrong, "signed": signed})
        print(name, row["entries"][-1], flush=True)

    for threads in THREADS:
        env = {"SDFWB_MESH_THREADS": str(threads)}
        seconds = with_environment(env, lambda: best_of(lambda: sdfwb.evaluate(mesh_path, points)))
        values = sdfwb.evaluate(mesh_path, points)["distance"]
        add("sdfwb, value + gradient, winding (default)", f"CPU engine, {threads} thread(s)", seconds, len(points), values)
    for method in ["pseudonormal", "parity"]:
        seconds = best_of(lambda: sdfwb.evaluate(mesh_path, points, sign=method))
        add(f"sdfwb, value + gradient, {method}", f"CPU engine, {THREADS[-1]} thread(s)", seconds, len(points),
            sdfwb.evaluate(mesh_path, points, sign=method)["distance"])
    glsl_points = points[:GLSL_POINTS]
    # The GLSL field (what a GPU runs) with its rows grouped by cell on the GPU (the default) and in
    # the caller's order (SDFWB_MESH_MORTON=0): llvmpipe's eight lanes gain from the grouping too.
    for morton, how in (("1", "rows sorted by cell"), ("0", "rows in the caller's order, SDFWB_MESH_MORTON=0")):
        environment = {"SDFWB_MESH_ENGINE": "gpu", "SDFWB_MESH_MORTON": morton}
        seconds = with_environment(environment, lambda: best_of(lambda: sdfwb.evaluate(mesh_path, glsl_points), 1))
        values = with_environment(environment, lambda: sdfwb.evaluate(mesh_path, glsl_points)["distance"])
        add("sdfwb, value + gradient, winding", f"GLSL field on llvmpipe (SDFWB_MESH_ENGINE=gpu), {how}, "
            f"{len(glsl_points):,} points", seconds, len(glsl_points), values)
    for pattern in ["rand", "near"]:
        seconds = best_of(lambda: sdfwb.sample(mesh_path, pattern, SPEED_POINTS))
        row[pattern] = SPEED_POINTS / seconds
    # Hierarchy nodes a row's walks visit in the CPU engine (a count no driver changes), at the shared
    # uniform points and at the near sampler's points.
    near_points = sdfwb.sample(mesh_path, "near", SPEED_POINTS)["position"]
    for pattern, at in (("rand", points), ("near", near_points)):
        nodes = with_environment({"SDFWB_MESH_ENGINE": "cpu"}, lambda: sdfwb.evaluate(mesh_path, at)["mesh_nodes"])
        row["nodes_" + pattern] = {k: v / nodes["rows"] for k, v in nodes.items() if k != "rows"}
        print(name, pattern, "nodes per row", row["nodes_" + pattern], flush=True)
        # The GLSL field's walks (what a GPU runs in a long run, its 65^3 sign lattice), counted by the shader
        # on the first GLSL_POINTS.
        nodes = with_environment({"SDFWB_MESH_ENGINE": "gpu", "SDFWB_MESH_COUNT": "1", "SDFWB_MESH_SIGN_LEVEL": "6"},
                                 lambda: sdfwb.evaluate(mesh_path, at[:GLSL_POINTS])["mesh_nodes"])
        row["glsl_nodes_" + pattern] = {k: v / nodes["rows"] for k, v in nodes.items() if k != "rows"}
        print(name, pattern, "GLSL nodes per row", row["glsl_nodes_" + pattern], flush=True)
    # Bad rows of the GLSL field's near sampler (the loop budget, below).
    marched = with_environment({"SDFWB_MESH_ENGINE": "gpu"}, lambda: sdfwb.sample(mesh_path, "near", 20000))
    row["near_bad"] = marched["bad_rows"] / 20000
    for binary in REFERENCES:
        for engine, sign in REFERENCE_KINDS:
            for threads in THREADS:
                info = run_reference(binary, engine, sign, mesh_path, points_path, threads)
                if info:
                    add(f"{engine.capitalize() if engine == 'embree' else 'CGAL'}, value + gradient, "
                        f"{sign if sign != 'none' else 'unsigned'}",
                        f"{info['binary']} ({info.get('compiler_flags', '')}), {threads} thread(s)",
                        info["query_seconds"], len(points), info["values"], signed=sign != "none")
    tensor = o3d.core.Tensor(points)
    for threads in THREADS:
        scene = open3d_scene(unit, faces, threads)
        seconds = best_of(lambda: scene.compute_distance(tensor))
        add("Open3D, unsigned distance", f"RaycastingScene(nthreads={threads}).compute_distance", seconds, len(points),
            scene.compute_distance(tensor).numpy(), signed=False)
    return row


def big_row(name, vertices, faces, small):
    unit = unit_cube(vertices)
    mesh_path = os.path.join(work, "big.ply")
    write_ply(mesh_path, unit, faces)
    points, points_path, truth_distance, truth_inside = shared_points(unit, faces, 4, BIG_POINTS, BIG_TRUTH_POINTS,
                                                                      "big_points")
    row = {"mesh": name, "triangles": len(faces), "hierarchy": hierarchy_line(mesh_path), "entries": []}
    sdfwb.evaluate(mesh_path, points[:1000])  # builds the hierarchy and the CPU layout
    seconds, ours = timed(lambda: sdfwb.evaluate(mesh_path, points))
    error, wrong = accuracy(ours["distance"], truth_distance, truth_inside)
    row["entries"].append({"label": "sdfwb, value + gradient, winding (default)", "configuration":
                           f"CPU engine, {THREADS[-1]} thread(s)", "rate": BIG_POINTS / seconds, "seconds": seconds,
                           "error": error, "wrong": wrong, "signed": True})
    print(row["entries"][-1], flush=True)
    signed = [e for e in (small or {"entries": []})["entries"] if e["signed"] and not e["label"].startswith("sdfwb")]
    if signed:
        best = max(signed, key=lambda e: e["rate"])
        binary = os.path.join(REFERENCE_DIR, best["configuration"].split(" ")[0])
        engine = "embree" if best["label"].startswith("Embree") else "cgal"
        sign = best["label"].split(", ")[-1]
        info = run_reference(binary, engine, sign, mesh_path, points_path, THREADS[-1], repeat=1)
        if info:
            error, wrong = accuracy(info["values"], truth_distance, truth_inside)
            row["entries"].append({"label": best["label"], "configuration": f"{info['binary']} "
                                   f"({info.get('compiler_flags', '')}), {THREADS[-1]} thread(s); build "
                                   f"{info['build_seconds']:.2f} s", "rate": BIG_POINTS / info["query_seconds"],
                                   "seconds": info["query_seconds"], "error": error, "wrong": wrong, "signed": True})
            print(row["entries"][-1], flush=True)
    scene = open3d_scene(unit, faces, THREADS[-1])
    scene.compute_distance(o3d.core.Tensor(points[:1000]))  # builds its acceleration structure
    seconds, theirs = timed(lambda: scene.compute_distance(o3d.core.Tensor(points)).numpy())
    error, _ = accuracy(theirs, truth_distance, truth_inside, signed=False)
    row["entries"].append({"label": "Open3D, unsigned distance", "configuration":
                           f"RaycastingScene(nthreads={THREADS[-1]}).compute_distance", "rate": BIG_POINTS / seconds,
                           "seconds": seconds, "error": error, "wrong": None, "signed": False})
    print(row["entries"][-1], flush=True)
    return row


REFERENCES = build_references()
REFERENCE_KINDS = [("embree", "parity"), ("embree", "pseudonormal"), ("embree", "none"), ("cgal", "parity"),
                   ("cgal", "pseudonormal")]

files = [("spot.obj", True), ("cow.obj", True), ("fandisk.obj", True), ("teapot.obj", False), ("suzanne.obj", False),
         ("stanford-bunny.obj", False)]
sign_rows = []
speed_rows = []
for name, closed in files:
    path = os.path.join(MESHES, name)
    if not os.path.exists(path):
        sys.exit(f"bench_mesh_sdf.py: {name} is not in {MESHES}: the doc would silently lose its rows "
                 "(give the shared meshes' folder with --meshes)")
    vertices, faces = read_obj(path)
    points = far_points(vertices, faces, POINTS, seed=1)
    ours = {m: sdfwb_signs(path, points, m) for m in METHODS}
    theirs = open3d_signs(vertices, faces, points)
    if closed:
        agree = ours["winding"] == ours["pseudonormal"]
        truth = ours["winding"]
        row = {"mesh": name, "variant": "closed", "points": int(agree.sum()), "disputed": float(1 - agree.mean())}
        for m in METHODS:
            row[m] = float((ours[m] != truth)[agree].mean())
        row["open3d"] = float((theirs != truth)[agree].mean())
        sign_rows.append(row)
        print(row, flush=True)
        for kind in ["1% removed", "5% removed", "10% flipped", "shell duplicated"]:
            bv, bf = damaged(vertices, faces, kind)
            broken = write_obj(os.path.join(work, f"{kind.replace(' ', '_').replace('%', '')}_{name}"), bv, bf)
            row = {"mesh": name, "variant": kind, "points": int(agree.sum()), "disputed": None}
            for m in METHODS:
                row[m] = float((sdfwb_signs(broken, points, m) != truth)[agree].mean())
            row["open3d"] = float((open3d_signs(bv, bf, points) != truth)[agree].mean())
            sign_rows.append(row)
            print(row, flush=True)
    else:
        row = {"mesh": name, "variant": "open as shipped", "points": len(points), "disputed": None}
        for m in METHODS:
            row[m] = float((ours[m] != ours["winding"]).mean())
        row["open3d"] = float((theirs != ours["winding"]).mean())
        sign_rows.append(row)
        print(row, flush=True)

    speed_rows.append(speed_row(name, vertices, faces))

# Scale: the bunny subdivided twice (1.1 M triangles) at BIG_POINTS points: sdfwb against the fastest
# signed C++ reference configuration of the bunny's own row and Open3D's unsigned distance.
big_rows = []
bunny = os.path.join(MESHES, "stanford-bunny.obj")
if os.path.exists(bunny) and BIG_POINTS > 0:
    bv, bf = read_obj(bunny)
    sv, sf = subdivide(*subdivide(bv, bf))
    big_rows.append(big_row("bunny, subdivided twice", sv, sf, next((r for r in speed_rows if r["mesh"] == "stanford-bunny.obj"), None)))

# The same shape as a mesh and as GLSL: a torus (R 0.6, r 0.3) with 256 x 128 quads (65,536
# triangles, vertices on the torus) against sdfwb's GLSL torus, at the same points.
torus_rows = []
u, v = np.meshgrid(np.arange(256) * 2 * np.pi / 256, np.arange(128) * 2 * np.pi / 128, indexing="ij")
tv = np.stack([(0.6 + 0.3 * np.cos(v)) * np.cos(u), (0.6 + 0.3 * np.cos(v)) * np.sin(u), 0.3 * np.sin(v)], -1).reshape(-1, 3)
at = lambda i, j: (i % 256) * 128 + (j % 128)  # noqa: E731
i, j = np.meshgrid(np.arange(256), np.arange(128), indexing="ij")
i, j = i.ravel(), j.ravel()
tf = np.concatenate([np.stack([at(i, j), at(i + 1, j), at(i + 1, j + 1)], 1), np.stack([at(i, j), at(i + 1, j + 1), at(i, j + 1)], 1)])
torus_path = os.path.join(work, "torus.ply")
write_ply(torus_path, tv, tf)
torus_glsl = "float sdf(vec3 p) { vec2 q = vec2(length(p.xy) - 0.6, p.z); return length(q) - 0.3; }\n"
tpoints = np.random.default_rng(5).uniform(-1.1, 1.1, (SPEED_POINTS, 3)).astype(np.float32)
mesh_seconds = best_of(lambda: sdfwb.evaluate(torus_path, tpoints, gradient=False))
glsl_seconds = best_of(lambda: sdfwb.evaluate(torus_glsl, tpoints, gradient=False))
as_mesh = sdfwb.evaluate(torus_path, tpoints, gradient=False)["distance"]
as_glsl = sdfwb.evaluate(torus_glsl, tpoints, gradient=False)["distance"]
torus_rows.append({"triangles": len(tf), "mesh": mesh_seconds, "glsl": glsl_seconds,
                   "difference": float(np.max(np.abs(as_mesh - as_glsl)))})
print(torus_rows[-1], flush=True)

# Open3D's sign comes from ray casting; check that its rays hit anything on this machine: a ray
# through the unit box from outside, and the occupancy of the box's centre.
box = o3d.t.geometry.TriangleMesh.from_legacy(o3d.geometry.TriangleMesh.create_box())
box_scene = o3d.t.geometry.RaycastingScene()
box_scene.add_triangles(box)
box_hit = float(box_scene.cast_rays(o3d.core.Tensor(np.array([[-1, 0.5, 0.5, 1, 0, 0]], np.float32)))["t_hit"].numpy()[0])
box_occupancy = float(box_scene.compute_occupancy(o3d.core.Tensor(np.array([[0.5, 0.5, 0.5]], np.float32))).numpy()[0])

gl = ""
probe = subprocess.run([os.path.join(ROOT, "build", "app", "sdfwb"), "--batch", "render", "--sdf", "sphere", "--size", "8x8",
                        "--output", os.path.join(work, "p.png"), "--json", "--quiet"], capture_output=True, text=True).stdout
match = re.search(r'"gl_renderer":\s*"([^"]*)"', probe)
gl = match.group(1) if match else "GL unknown"


def pct(x):
    return "" if x is None else f"{100 * x:.2f} %"


with open(OUT, "w") as out:
    out.write("# Meshes in: a triangle mesh as an SDF\n\n")
    out.write(f"Generated by `bench/bench_mesh_sdf.py` on {datetime.date.today().isoformat()}, {platform.node()} "
              f"({os.cpu_count()} cores, {gl}); Open3D {o3d.__version__}. Meshes: `../shared/data/meshes/` "
              "(see its README), each normalised to the unit cube.\n\n")
    out.write("`--sdf model.obj` (or .ply .stl .off .glb ...) opens any triangle mesh as an SDF on every command, in job "
              "files, manifests and Python. `--sign winding` (the default: generalized winding numbers, evaluated "
              "hierarchically), `parity` (the majority of three rays' crossing counts) or `pseudonormal` (the "
              "angle-weighted pseudonormal of the nearest feature); `--normalize none|unit-cube|unit-sphere`. "
              "See meshfield/MeshField.h for the conventions.\n\n")
    rays_work = np.isfinite(box_hit) and box_occupancy == 1.0
    out.write("Open3D's rays on this machine: a ray from (-1, 0.5, 0.5) along +x through the unit box "
              f"`create_box()` hits at t = {box_hit}, and the box's centre has occupancy {box_occupancy:g}. " +
              ("Its ray queries work here.\n\n" if rays_work else
               "**Its ray queries find no hits on this machine** (Debian 12's Open3D 0.16.1 with its Embree), so its "
               "signed distance is positive everywhere: the Open3D column below measures that, not what Open3D does "
               "where its rays work. Its unsigned distance (a closest-point query) is unaffected.\n\n"))
    if os.path.exists(os.path.join(ROOT, "docs", "images", "mesh_bunny_plane.png")):
        out.write("![The Stanford bunny's SDF on the plane z = 0](images/mesh_bunny_plane.png)\n\n"
                  "The Stanford bunny (`scripts/mesh_sdf_pictures`): its SDF on the cutting plane z = 0, inside "
                  "orange, outside a ramp with isocontours; violet hatching marks where the winding number is within "
                  "1/4 of 1/2, below the holes in its base, where inside or outside is a guess (the audit's "
                  "sign-uncertain flag counts the same points). Magenta would mark pixels whose walks of the hierarchy "
                  "ran out of llvmpipe's loop budget (see the last section).\n\n")
    out.write(f"## Wrong signs\n\n{POINTS} uniform points in [-1.1, 1.1]^3, of which those farther than 1 % of the "
              "diagonal from the surface count. Closed meshes: the share of points each method gets wrong, against "
              "the sign sdfwb's winding numbers and pseudonormals agree on (\"disputed\": the share where they "
              "do not, left out). Broken variants are graded against their closed original. Open meshes: "
              "the share where each method differs from winding numbers (no truth exists).\n\n")
    out.write("| mesh | variant | points | disputed | winding | pseudonormal | parity | Open3D |\n|---|---|---|---|---|---|---|---|\n")
    for r in sign_rows:
        out.write(f"| {r['mesh']} | {r['variant']} | {r['points']} | {pct(r['disputed'])} | {pct(r['winding'])} | "
                  f"{pct(r['pseudonormal'])} | {pct(r['parity'])} | {pct(r['open3d'])} |\n")
    out.write("\n## Speed against C++ programs on Embree and CGAL\n\n"
              "**Goal (issue 46, written before the run): sdfwb's value + gradient with its default sign (winding "
              "numbers) at least 1.0x the points per second of the fastest signed C++ reference on every mesh.** "
              f"{SPEED_POINTS:,} uniform points in [-1.1, 1.1]^3 around each mesh normalised to the unit cube; every "
              "program reads the same normalised mesh file and the same points. Times: the query phase, best of 3 "
              "after a warm-up (sdfwb: the whole `sdfwb.evaluate(path, points)` call: its positions through the "
              "samplers' stage, the values and exact gradients on the CPU engine; the references: their query loop, "
              "their scene or tree built before timing). Accuracy beside each: \"|d| error\" is the largest "
              f"difference from a float64 brute-force distance over the first {TRUTH_POINTS:,} points; \"wrong "
              "signs\" the share of those farther than 1e-4 from the surface whose sign differs from the exact "
              "float64 winding number (every triangle's solid angle summed; shares no code with sdfwb), "
              "`bench/mesh_sdf_truth.py`.\n\n"
              "The references (`bench/mesh_sdf_reference.cpp`, compiled by `bench/build_mesh_sdf_reference.sh` in "
              "every variant below): a C++ program on Debian's Embree 3 (closest point by `rtcPointQuery`; sign by "
              "the majority of three rays' crossing parities, or by the angle-weighted pseudonormal of the closest "
              "feature) and on CGAL's AABB tree (`closest_point_and_primitive`; sign by `Side_of_triangle_mesh`, or "
              "pseudonormals), OpenMP over the points, the points visited in Morton order (sorted inside the timed "
              "phase) with each query started from the previous point's closest triangle, the gradient from the "
              "closest point as sdfwb's. sdfwb's CPU engine orders its rows the same way (Morton order, each walk "
              "seeded by the last row's triangle within a block of 1024). Compile lines:\n\n```\n" +
              "\n".join(reference_lines) + "\n```\n\nWhat each reference does, in its own words:\n\n" +
              "".join(f"- {k}: {v}\n" for k, v in sorted(reference_notes.items())) + "\n")
    for r in speed_rows:
        entries = sorted(r["entries"], key=lambda e: -e["rate"])
        out.write(f"### {r['mesh']} ({r['triangles']:,} triangles)\n\n| program | configuration | points/s | "
                  "\\|d\\| error | wrong signs |\n|---|---|---|---|---|\n")
        for e in entries:
            out.write(f"| {e['label']} | {e['configuration']} | {e['rate'] / 1e6:.3f} M | {e['error']:.1e} | "
                      f"{pct(e['wrong']) if e['signed'] else 'unsigned'} |\n")
        ours = max((e for e in r["entries"] if e["label"] == "sdfwb, value + gradient, winding (default)"),
                   key=lambda e: e["rate"])
        refs = [e for e in r["entries"] if e["signed"] and not e["label"].startswith("sdfwb")]
        if refs:
            best = max(refs, key=lambda e: e["rate"])
            ratio = ours["rate"] / best["rate"]
            r["ratio"] = ratio
            out.write(f"\nsdfwb {ours['rate'] / 1e6:.3f} M points/s against the fastest signed reference, "
                      f"{best['label']} ({best['configuration']}), {best['rate'] / 1e6:.3f} M points/s: **{ratio:.2f}x** "
                      f"(goal 1.0x: {'met' if ratio >= 1.0 else 'not met, sdfwb is slower'}). ")
        out.write(f"`sdfwb.sample(path, 'near', {SPEED_POINTS:,})` writes {r['near'] / 1e6:.3f} M rows/s, "
                  f"`'rand'` {r['rand'] / 1e6:.3f} M rows/s: near takes {r['rand'] / r['near']:.2f}x rand's time "
                  "(goal: within 2x).\n\n")
    ratios = [r["ratio"] for r in speed_rows if "ratio" in r]
    if ratios:
        out.write(f"Over the meshes, sdfwb runs at {min(ratios):.2f}x to {max(ratios):.2f}x the fastest signed C++ "
                  "reference (above 1: sdfwb is faster). What sdfwb does: one nearest walk a row over four-wide nodes "
                  "that hold their children's boxes, rows in Morton order with each walk seeded by the last row's "
                  "triangle, the exact gradient from that walk's closest point, and winding numbers shared between "
                  "rows: a lattice point inside the empty ball of radius |d| around a row gives that row's sign "
                  "when the winding number cannot change by enough on the way (a bound from the mesh's open "
                  "boundary: none on closed, oriented meshes); nearer the surface, the nearest point of a 65^3 "
                  "lattice plus the triangles the short segment from it to the row crosses (each crossing changes "
                  "the winding number by exactly one), within the same kind of bound. Only rows whose segment "
                  "passes within rounding of an edge, or that lie too near an open boundary, walk the winding "
                  "hierarchy. ")
        if min(ratios) < 1.0:
            out.write("Where it loses: the references' pseudonormal sign costs nothing once the closest point is "
                      "known, but is wrong behind holes and flipped faces (the wrong-signs column); sdfwb's winding "
                      "sign is right there and costs a lattice lookup, a segment walk or a hierarchy walk a row.")
        out.write("\n\n")
    out.write("### Hierarchy nodes a row visits\n\nThe CPU engine's walks, counted per row "
              "(`sdfwb.evaluate(...)['mesh_nodes']`): a count that does not depend on the driver or the machine's "
              "speed. nearest: nodes the closest-point walk tests; winding: nodes the winding-number walks open "
              "or take as dipoles (the sign cache's lattice included); segment: nodes the walks of segments from a "
              "lattice point test; cached / crossed: the share of rows whose sign came from the sign cache's ball "
              "or from a lattice point and the triangles between. rand: the shared uniform points; near: "
              f"{SPEED_POINTS:,} points of `sdfwb.sample(path, 'near')`.\n\n"
              "The GLSL field (what a GPU runs; `SDFWB_MESH_ENGINE=gpu SDFWB_MESH_COUNT=1`, the shader counts its "
              f"own walks) on the first {GLSL_POINTS:,} of the same points: one nearest walk and one sign a row, "
              "the same ball test and segment walks from a lattice of winding numbers of 65^3 points, as in a "
              "GPU's runs of 4 M rows or more (`SDFWB_MESH_SIGN_LEVEL=6`; otherwise 33^3), and each walk seeded "
              "by its nearest lattice point's nearest triangle.\n\n"
              "| mesh | points | engine | nearest | winding | segment | cached | crossed |\n"
              "|---|---|---|---|---|---|---|---|\n")
    for r in speed_rows:
        for pattern in ("rand", "near"):
            for engine, key in (("CPU", "nodes_"), ("GLSL", "glsl_nodes_")):
                n = r.get(key + pattern)
                if n:
                    out.write(f"| {r['mesh']} | {pattern} | {engine} | {n['nearest']:.1f} | {n['winding']:.1f} | "
                              f"{n['segment']:.1f} | {100 * n['cached_signs']:.0f} % | {100 * n['crossed_signs']:.0f} % |\n")
    out.write("\n## What runs out of budget on llvmpipe\n\nllvmpipe (Mesa's CPU driver, what this machine has) ends "
              "a shader invocation's loops after 65535 iterations in all, counted across every call the invocation "
              "makes. A mesh SDF walks its hierarchy in loops (a nearest-triangle walk and a winding-number walk per "
              "call), so work that evaluates the field many times in one invocation can run out: the tracer's longest "
              "marches, the cutting plane's Lipschitz overlay (7 calls a pixel), and the near and "
              "surface samplers over text that changes a mesh's field (an offset shell), which march rays to its zero "
              "set. A walk that runs out returns NaN, so such rows are bad rows and such pixels magenta, never a wrong "
              "value. On a mesh's own field the near and surface samplers do not march: they draw points uniform by "
              "area on the triangles (as mesh_to_sdf and DeepSDF do) and evaluate there. Point evaluation (`evaluate`, "
              "`--batch grade`), the rand, grid, jitter and image samplers, the audit's point passes and the mesher "
              "evaluate once per invocation (7 times with a gradient) and stay within it. A leaf's triangles cost no "
              "iteration (their loop has a constant bound, which the driver unrolls), and a fragment shader's helper "
              "lanes (pixels outside the primitive, run only for derivatives) walk nothing: llvmpipe drops their "
              "stack writes but not their loop iterations, so their walks spun and spent the budget of the pixels "
              "beside them, drawing lines along the tracer's proxy box. On llvmpipe a mesh's own field is "
              "evaluated by the CPU engine instead (no loop budget there), and the tracer draws it by one ray walk "
              "of the hierarchy a pixel, its cutting plane from a texture the CPU engine fills (docs/viewport.md); "
              "the GLSL field still serves text that changes a mesh's field, the march debugger, and every GPU "
              "driver. Bad rows of the GLSL field's near sampler "
              "(`SDFWB_MESH_ENGINE=gpu`) on each mesh's own field (20000 rows, gradient on):\n\n"
              "| mesh | triangles | near: bad rows |\n|---|---|---|\n")
    for r in speed_rows:
        out.write(f"| {r['mesh']} | {r['triangles']} | {100 * r['near_bad']:.1f} % |\n")
    out.write("\nA GPU driver has no such limit (docs/gpu.md has a run on an NVIDIA H200).\n")
    if big_rows:
        r = big_rows[0]
        h = r["hierarchy"]
        hierarchy = f"{h[0]:,} nodes, depth {h[1]}, built in {h[2]:.2f} s, {h[3]:.1f} MB" if h else "not logged"
        out.write(f"\n## A million triangles, {BIG_POINTS:,} points\n\nThe Stanford bunny subdivided twice (every "
                  "triangle into four at its edges' midpoints: the same surface, 16 times the triangles; "
                  f"{r['triangles']:,} triangles), normalised to the unit cube, at {BIG_POINTS:,} uniform points in "
                  "[-1.1, 1.1]^3, one timed call each after a warm-up call that builds the hierarchy (sdfwb) or "
                  "before which the scene is built (references). The reference is the configuration that was "
                  "fastest on the bunny above. sdfwb's hierarchy: " + hierarchy + f". Accuracy over the first "
                  f"{BIG_TRUTH_POINTS} points against the float64 brute force and exact winding numbers.\n\n"
                  "| program | configuration | points/s | seconds | \\|d\\| error | wrong signs |\n"
                  "|---|---|---|---|---|---|\n")
        for e in r["entries"]:
            out.write(f"| {e['label']} | {e['configuration']} | {e['rate'] / 1e6:.3f} M | {e['seconds']:.1f} | "
                      f"{e['error']:.1e} | {pct(e['wrong']) if e['signed'] else 'unsigned'} |\n")
        signed_refs = [e for e in r["entries"][1:] if e["signed"]]
        if signed_refs:
            ratio = r["entries"][0]["rate"] / signed_refs[0]["rate"]
            out.write(f"\nsdfwb against that reference: **{ratio:.2f}x** (goal 1.0x: "
                      f"{'met' if ratio >= 1.0 else 'not met, sdfwb is slower'}).\n")
    if torus_rows:
        t = torus_rows[0]
        out.write(f"\n## The same shape as GLSL\n\nA torus (R 0.6, r 0.3) as a mesh of {t['triangles']:,} triangles "
                  "(vertices on the torus) and as sdfwb's own GLSL (`length(vec2(length(p.xy) - 0.6, p.z)) - 0.3`), "
                  f"evaluated at the same {SPEED_POINTS:,} uniform points (best of 3): the mesh takes {t['mesh']:.3f} s "
                  f"({SPEED_POINTS / t['mesh'] / 1e6:.3f} M/s), the GLSL {t['glsl']:.3f} s "
                  f"({SPEED_POINTS / t['glsl'] / 1e6:.2f} M/s): the mesh is {t['mesh'] / t['glsl']:.0f}x slower. "
                  f"The largest difference between the two fields is {t['difference']:.2g} (the polygon's chord "
                  "error). Where an SDF can be written in GLSL, it is the faster field by far.\n")
print(f"wrote {OUT}")
