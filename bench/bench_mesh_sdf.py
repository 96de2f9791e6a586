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
Speed: the same M points through sdfwb.evaluate (gradient off: one field evaluation per point) and
Open3D's compute_signed_distance on 1 and on all cores, each timed after a warm-up call, best of 3.
Scale: the bunny and a 1.1 M-triangle mesh made from it (two rounds of midpoint subdivision) at
--big-points (10 M) points, one timed call each after a warm-up. The same shape as GLSL: a torus mesh
against sdfwb's own GLSL torus at the same points.
"""
import datetime
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

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def option(name, default):
    return type(default)(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default


POINTS = option("--points", 200000)
SPEED_POINTS = option("--speed-points", 1000000)
BIG_POINTS = option("--big-points", 10000000)
MESHES = option("--meshes", os.path.normpath(os.path.join(ROOT, "..", "shared", "data", "meshes")))
OUT = os.path.join(ROOT, "docs", "mesh-sdf.md")
SDFWB = os.path.join(ROOT, "build", "app", "sdfwb")
METHODS = ["winding", "pseudonormal", "parity"]
work = tempfile.mkdtemp(prefix="sdfwb-mesh-sdf-")


def read_obj(path):
    # OBJ's v and f lines (polygons as fans, v/vt/vn and negative indices), the way assimp reads them
    # for sdfwb: Open3D 0.16's reader returns no vertices for suzanne.obj.
    vertices, faces = [], []
    with open(path) as obj:
        for line in obj:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                vertices.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                index = [int(token.split("/")[0]) for token in parts[1:]]
                index = [i - 1 if i > 0 else len(vertices) + i for i in index]
                faces += [[index[0], index[k], index[k + 1]] for k in range(1, len(index) - 1)]
    return np.asarray(vertices, np.float64), np.asarray(faces, np.int64)


def write_obj(path, vertices, faces):
    with open(path, "w") as out:
        out.write("".join("v %.9g %.9g %.9g\n" % tuple(v) for v in vertices))
        out.write("".join("f %d %d %d\n" % tuple(f + 1) for f in faces))
    return path


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


def subdivide(vertices, faces):
    # Every triangle into four at its edges' midpoints (shared edges share their midpoint).
    edges = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    unique, inverse = np.unique(edges, axis=0, return_inverse=True)
    mids = len(vertices) + inverse.reshape(3, -1).T  # per face: midpoints of ab, bc, ca
    vertices = np.concatenate([vertices, (vertices[unique[:, 0]] + vertices[unique[:, 1]]) / 2])
    a, b, c = faces.T
    ab, bc, ca = mids.T
    faces = np.concatenate([np.stack(t, axis=1) for t in ((a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca))])
    return vertices, faces


def write_ply(path, vertices, faces):
    with open(path, "wb") as out:
        out.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\nproperty float x\n"
                  f"property float y\nproperty float z\nelement face {len(faces)}\n"
                  "property list uchar int vertex_indices\nend_header\n".encode())
        out.write(vertices.astype("<f4").tobytes())
        rows = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", 3)])
        rows["n"], rows["i"] = 3, faces
        out.write(rows.tobytes())


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


files = [("spot.obj", True), ("cow.obj", True), ("fandisk.obj", True), ("teapot.obj", False), ("suzanne.obj", False),
         ("stanford-bunny.obj", False)]
sign_rows = []
speed_rows = []
for name, closed in files:
    path = os.path.join(MESHES, name)
    if not os.path.exists(path):
        print(f"skipping {name}: not in {MESHES}", file=sys.stderr)
        continue
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

    speed = np.random.default_rng(2).uniform(-1.1, 1.1, (SPEED_POINTS, 3)).astype(np.float32)
    entry = {"mesh": name, "triangles": len(faces)}
    for m in METHODS:
        entry[m] = best_of(lambda: sdfwb.evaluate(path, speed, gradient=False, sign=m, normalize="unit-cube"))
    # Near on the mesh's own field: points drawn on the triangles (see docs below).
    marched = sdfwb.sample(path, "near", 20000, normalize="unit-cube")
    entry["near_bad"] = marched["bad_rows"] / 20000
    tensor = o3d.core.Tensor(speed)
    for threads in sorted({1, os.cpu_count() or 1}):
        scene = open3d_scene(unit_cube(vertices), faces, threads)
        entry[f"open3d_{threads}"] = best_of(lambda: scene.compute_signed_distance(tensor))
    speed_rows.append(entry)
    print(entry, flush=True)

# Scale: the bunny and a million triangles made from it, at BIG_POINTS points.
big_rows = []
bunny = os.path.join(MESHES, "stanford-bunny.obj")
if os.path.exists(bunny) and BIG_POINTS > 0:
    bv, bf = read_obj(bunny)
    sv, sf = subdivide(*subdivide(bv, bf))
    million = os.path.join(work, "bunny-subdivided.ply")
    write_ply(million, sv, sf)
    big = np.random.default_rng(4).uniform(-1.1, 1.1, (BIG_POINTS, 3)).astype(np.float32)
    for name, path, vertices, faces in (("stanford-bunny.obj", bunny, bv, bf), ("bunny, subdivided twice", million, sv, sf)):
        entry = {"mesh": name, "triangles": len(faces), "hierarchy": hierarchy_line(path)}
        sdfwb.evaluate(path, big[:1000], gradient=False, normalize="unit-cube")  # compiles, builds the hierarchy
        entry["sdfwb"], ours = timed(lambda: sdfwb.evaluate(path, big, gradient=False, normalize="unit-cube"))
        entry["bad"] = int(ours["bad_rows"])
        tensor = o3d.core.Tensor(big)
        for threads in sorted({1, os.cpu_count() or 1}):
            scene = open3d_scene(unit_cube(vertices), faces, threads)
            scene.compute_distance(o3d.core.Tensor(big[:1000]))  # builds its acceleration structure
            entry[f"open3d_{threads}"], theirs = timed(lambda: scene.compute_signed_distance(tensor).numpy())
        # Unsigned distances agree (Open3D's closest-point query works here; its sign does not, see above).
        entry["max_abs_difference"] = float(np.max(np.abs(np.abs(ours["distance"]) - np.abs(theirs))))
        big_rows.append(entry)
        print(entry, flush=True)

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
    out.write(f"\n## Speed\n\n{SPEED_POINTS} uniform points, seconds (best of 3 after a warm-up call) and millions "
              "of points per second. sdfwb: `sdfwb.evaluate(path, points, gradient=False, sign=...)`, the whole call "
              "(upload, GPU, read-back). Open3D: `RaycastingScene(nthreads=N).compute_signed_distance` (Embree on "
              "the CPU), its scene built before timing; its sign is ray parity.\n\n")
    cols = ["winding", "pseudonormal", "parity"] + [k for k in speed_rows[0] if k.startswith("open3d_")] if speed_rows else []
    out.write("| mesh | triangles | " + " | ".join(("sdfwb " + c) if not c.startswith("open3d") else
                                                   f"Open3D, {c.split('_')[1]} thread(s)" for c in cols) + " |\n")
    out.write("|---|---|" + "---|" * len(cols) + "\n")
    for r in speed_rows:
        out.write(f"| {r['mesh']} | {r['triangles']} | " +
                  " | ".join(f"{r[c]:.3f} s ({SPEED_POINTS / r[c] / 1e6:.2f} M/s)" for c in cols) + " |\n")
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
              "beside them, drawing lines along the tracer's proxy box. Bad rows of the near sampler "
              "on each mesh's own field (20000 rows, gradient on):\n\n"
              "| mesh | triangles | near: bad rows |\n|---|---|---|\n")
    for r in speed_rows:
        out.write(f"| {r['mesh']} | {r['triangles']} | {100 * r['near_bad']:.1f} % |\n")
    out.write("\nA GPU driver has no such limit (docs/gpu.md has a run on an NVIDIA H200).\n")
    if speed_rows:
        best_o3d = [min(r[c] for c in cols if c.startswith("open3d")) for r in speed_rows]
        ratios = [r["winding"] / b for r, b in zip(speed_rows, best_o3d)]
        out.write(f"\nsdfwb with winding numbers takes {min(ratios):.1f}x to {max(ratios):.1f}x the time of Open3D at "
                  "its best thread count on this machine (above 1: sdfwb is slower). On llvmpipe the GPU field runs "
                  "on the CPU's cores through Mesa's JIT, against Embree's hand-vectorised traversal; Open3D's "
                  "parity sign is also cheaper than a winding number.\n")
    if big_rows:
        out.write(f"\n## A million triangles, {BIG_POINTS:,} points\n\n{BIG_POINTS:,} uniform points in [-1.1, 1.1]^3 "
                  "through the Stanford bunny and the bunny subdivided twice (every triangle into four at its edges' "
                  "midpoints: the same surface, 16 times the triangles), one timed call each after a warm-up call "
                  "that compiles the shader and builds the hierarchy (sdfwb) or the BVH (Open3D). sdfwb: winding "
                  "numbers. The hierarchy's size and build time are sdfwb's own log line when it opens the mesh. "
                  "\"|d| differs\": the largest difference between sdfwb's and Open3D's unsigned distances.\n\n"
                  "| mesh | triangles | hierarchy: nodes, depth, build, GPU memory | sdfwb | " +
                  " | ".join(f"Open3D, {k.split('_')[1]} thread(s)" for k in big_rows[0] if k.startswith("open3d_")) +
                  " | sdfwb / best Open3D | \\|d\\| differs | bad rows |\n|---|---|---|---|" +
                  "---|" * len([k for k in big_rows[0] if k.startswith("open3d_")]) + "---|---|---|\n")
        for r in big_rows:
            h = r["hierarchy"]
            hierarchy = f"{h[0]:,} nodes, depth {h[1]}, {h[2]:.2f} s, {h[3]:.1f} MB" if h else "not logged"
            o3d_keys = [k for k in r if k.startswith("open3d_")]
            best = min(r[k] for k in o3d_keys)
            out.write(f"| {r['mesh']} | {r['triangles']:,} | {hierarchy} | {r['sdfwb']:.1f} s "
                      f"({BIG_POINTS / r['sdfwb'] / 1e6:.3f} M/s) | " +
                      " | ".join(f"{r[k]:.1f} s ({BIG_POINTS / r[k] / 1e6:.3f} M/s)" for k in o3d_keys) +
                      f" | {r['sdfwb'] / best:.1f}x | {r['max_abs_difference']:.2g} | {r['bad']} |\n")
        growth = big_rows[-1]["sdfwb"] / big_rows[0]["sdfwb"]
        o3d_growth = (min(big_rows[-1][k] for k in big_rows[-1] if k.startswith("open3d_")) /
                      min(big_rows[0][k] for k in big_rows[0] if k.startswith("open3d_")))
        out.write(f"\n16 times the triangles costs sdfwb {growth:.2f}x the time and Open3D {o3d_growth:.2f}x. "
                  "Above 1 in the ratio column, sdfwb is slower.\n")
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
