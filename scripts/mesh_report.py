#!/usr/bin/env python3
"""Error against run time of `sdfwb --batch mesh`: docs/meshing.md and docs/images/mesh_error_vs_time.png.

    PYTHONPATH=build/python /usr/bin/python3 scripts/mesh_report.py [build/app/sdfwb] [--max-resolution 512]
    /usr/bin/python3 scripts/mesh_report.py --quote-peers   (only the section quoted from docs/meshing-peers.md)

For each shape and each resolution (32, 64, ..., up to --max-resolution) it runs
`sdfwb --batch mesh --json` and tabulates the extraction time, the mesh's size and topology, and
its error against the exact field both ways (with the seconds the measurement took). Then it
meshes the same fields with another tool, scikit-image's marching cubes on a NumPy grid of the
field (sampled by `sdfwb.sample(..., "grid", ...)`, the same lattice), and grades both meshes
with `sdfwb --batch grade` side by side.
"""
import datetime
import glob
import json
import os
import platform
import re
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
args = [a for a in sys.argv[1:] if not a.startswith("--")]
BINARY = args[0] if args else os.path.join(ROOT, "build", "app", "sdfwb")
LARGEST = int(sys.argv[sys.argv.index("--max-resolution") + 1]) if "--max-resolution" in sys.argv else 512
ENV = {k: v for k, v in os.environ.items() if k != "DISPLAY"}


# The peers' run (bench/bench_mesh_peers.py) is too long for this script; its plot and its own generated summary
# lines are quoted from docs/meshing-peers.md, with that run's machine line, so that this page says where a peer wins.
PEERS_TITLE = "## Against scikit-image, VTK Flying Edges and OpenVDB (quoted from meshing-peers.md)"


def quote_peers():
    """Appends the peers' section to docs/meshing.md."""
    peers_path = os.path.join(ROOT, "docs", "meshing-peers.md")
    if os.path.exists(peers_path):
        peers = open(peers_path).read().splitlines()
        machine = next((line[2:] for line in peers if line.startswith("- Machine:")), "machine unknown")

        def section(title):
            at = next((k for k, line in enumerate(peers) if line.startswith(title)), None)
            if at is None:
                return []
            end = next((k for k in range(at + 1, len(peers)) if peers[k].startswith("## ")), len(peers))
            return peers[at + 1:end]

        equal_error = [line for line in section("## Equal error: the time") if line.startswith("- ")]
        equal_resolution = [line for line in section("## Equal resolution") if line.startswith("- ")]
        wins = [line for line in section("## Where a peer wins") if line.startswith("- ")]
        with open(os.path.join(ROOT, "docs", "meshing.md"), "a") as out:
            out.write("\n" + PEERS_TITLE + "\n\n")
            out.write(f"Quoted by this script from [meshing-peers.md](meshing-peers.md), which `bench/bench_mesh_peers.py "
                      f"--scale` generates ({machine}); every table, configuration and scale run is there.\n\n")
            out.write("![Chamfer-L1 against time, every peer and shape class](images/mesh_peers_error_vs_time.png)\n\n")
            out.write("Equal error (sdfwb's time to reach the best peer's 256^3 error; above 1: sdfwb is faster):\n\n" +
                      "\n".join(equal_error) + "\n\nEqual resolution 256^3:\n\n" + "\n".join(equal_resolution) + "\n\n")
            out.write("Where a peer wins:\n\n" + ("\n".join(wins) if wins else "- nowhere in that run") + "\n")


# --quote-peers: only the peers' section at the end of docs/meshing.md, re-quoted from a new
# docs/meshing-peers.md (bench/bench_mesh_peers.py), the rest of the page left as generated.
if "--quote-peers" in sys.argv:
    page_path = os.path.join(ROOT, "docs", "meshing.md")
    page = open(page_path).read()
    at = page.find("\n" + PEERS_TITLE)
    with open(page_path, "w") as page_file:
        page_file.write(page if at < 0 else page[:at])
    quote_peers()
    print("rewrote the peers' section of docs/meshing.md")
    sys.exit(0)
SHAPES = [
    ("Sphere (dataset)", "sphere", []),
    ("Box (dataset, sharp edges)", "box", []),
    ("Torus (dataset)", "torus", []),
    ("hg_sdf polar columns (tests/params)", os.path.join(ROOT, "tests", "params", "hg_polar_columns.glsl"), []),
    ("Coffee Mug (dataset, conservative)", "mug", []),
]
resolutions = [r for r in (32, 64, 128, 256, 512, 1024) if r <= LARGEST]
REFINED = [(32, 2), (64, 1), (64, 2)]  # --resolution R --refine K
work = tempfile.mkdtemp(prefix="sdfwb-mesh-report-")
rows = []
gl = ""
for label, sdf, extra in SHAPES:
    for resolution, refine in [(r, 0) for r in resolutions] + REFINED:
        out = subprocess.run([BINARY, "--batch", "mesh", "--sdf", sdf, "--resolution", str(resolution), "--refine", str(refine),
                              "--output", os.path.join(work, "m.ply"), "--json", "--quiet", *extra], env=ENV,
                             capture_output=True, text=True)
        if out.returncode != 0:
            raise RuntimeError(f"mesh {sdf} at {resolution} (refine {refine}) failed: {out.stderr.strip()}")
        r = json.loads(out.stdout[out.stdout.index("{"):])
        r["label"] = label
        rows.append(r)
        print(f"{label:38s} {resolution:5d} +{refine} {r['triangles']:9d} tris {r['mesh_seconds']:7.2f} s  "
              f"Hausdorff {r['hausdorff']:.3g}  watertight {r['watertight']}", flush=True)


def grid_of(r):
    return f"{r['resolution']} + {r['refine']}" if r.get("refine") else str(r["resolution"])
probe = subprocess.run([BINARY, "--batch", "render", "--sdf", "sphere", "--size", "8x8", "--output", os.path.join(work, "p.png"),
                        "--json", "--quiet"], env=ENV, capture_output=True, text=True).stdout
gl = json.loads(probe[probe.index("{"):]).get("gl_renderer", "") if "{" in probe else ""

fig, axis = plt.subplots(figsize=(7, 4.5))
for index, (label, _, _) in enumerate(SHAPES):
    for refined in (False, True):
        mine = sorted((r for r in rows if r["label"] == label and bool(r.get("refine")) == refined),
                      key=lambda r: r["mesh_seconds"])
        axis.loglog([r["mesh_seconds"] for r in mine], [r["hausdorff"] for r in mine], "s--" if refined else "o-",
                    color=f"C{index}", alpha=0.7 if refined else 1.0, label=f"{label}, refined" if refined else label)
        for r in mine:
            axis.annotate(grid_of(r), (r["mesh_seconds"], r["hausdorff"]), fontsize=6, xytext=(3, 3),
                          textcoords="offset points")
axis.set_xlabel("extraction seconds (dual contouring, GPU field)")
axis.set_ylabel("Hausdorff distance to the exact surface")
axis.set_title("sdfwb --batch mesh: error against run time (labels: resolution + refine levels)", fontsize=9)
axis.grid(True, which="both", alpha=0.3)
axis.legend(fontsize=7)
fig.tight_layout()
os.makedirs(os.path.join(ROOT, "docs", "images"), exist_ok=True)
fig.savefig(os.path.join(ROOT, "docs", "images", "mesh_error_vs_time.png"), dpi=100)

with open(os.path.join(ROOT, "docs", "meshing.md"), "w") as out:
    out.write("# Meshes: error against run time\n\n")
    out.write("Generated by `PYTHONPATH=build/python /usr/bin/python3 scripts/mesh_report.py`; do not edit by hand.\n\n")
    out.write("```sh\n"
              "sdfwb --batch mesh --sdf SDF --output FILE.{ply,obj,stl,glb} [--resolution 128] [--refine 0..4]\n"
              "                   [--bounds X0,Y0,Z0,X1,Y1,Z1] [--time T] [--param NAME=VALUE] [--lipschitz L]\n"
              "                   [--error-samples 100000] [--json]   # Python: sdfwb.mesh(sdf, resolution=, refine=)\n"
              "sdfwb --batch grade --mesh PRED.{ply,obj,stl,glb,off,...} --sdf SDF [--tau 0.01] [--points 100000]\n"
              "                   [--occupancy-resolution 128] [--edge-radius 0.02] [--edge-angle 30] [--json]\n"
              "                   # Python: sdfwb.evaluate_mesh(mesh, sdf, tau=..., edge_radius=..., edge_angle=...)\n"
              "```\n\n"
              "**How.** Dual contouring (Ju et al. 2002), chosen over marching cubes because a vertex per cell placed by a "
              "QEF of the crossings' tangent planes lands on sharp edges and corners, which marching cubes cuts off "
              "(a test checks the 8 corners of a box within 1e-3 and every edge vertex on its edge). Sharp features off the "
              "grid: a cell whose QEF leaves a line of minimisers (an edge) puts its vertex on that line, inside the cell or "
              "up to half a cell beside it when the edge passes just outside; a corner whose tip pokes into a cell with no "
              "vertex of its own is placed there by the neighbour's QEF; the crossings' normals come from differences over "
              "a hundredth of a cell, so a crossing near a crease does not mix the two faces' normals (tests: a box under an "
              "irrational rotation keeps every corner within 1e-3 at 128 cells and every vertex within 1e-4 of the "
              "surface; a rotated cylinder's rims and an hg_sdf chamfered object score edge F-scores of 1.0 and 0.987). "
              "`--batch grade` grades any mesh near creases too: `edges` repeats Chamfer-L1, F-score and Hausdorff over the "
              "points within --edge-radius of a crease of the exact field (its normal turns by over --edge-angle towards "
              "one of 8 points around the point), where a mesher that rounds edges loses; it is null on smooth shapes. "
              "Against scikit-image, VTK Flying Edges and OpenVDB in one run: [meshing-peers.md](meshing-peers.md). On a lent "
              "H100 machine against Flying Edges called from C++ with its field inline in C++ on 16 threads: "
              "[meshing-gpu.md](meshing-gpu.md). The CPU steps (edges, vertices, polygons, the crossings' brackets, the "
              "projection, the topology check) run in chunks on every core ($SDFWB_THREADS caps them) and are joined in "
              "order, so every thread count gives the same bytes (a test); the report's `phase_seconds` says where the "
              "time went. The field is "
              "evaluated on the GPU; blocks of 8^3 cells whose centre has |f| above L times half their diagonal are "
              "skipped, with L the bound the report names (`--lipschitz`; when the error is measured, a quick audit's largest "
              "difference quotient x 1.25, at least 1, and a field the audit finds discontinuous or NaN is evaluated "
              "everywhere; otherwise 1.25 x the steepest |grad f| at the block centres, at least 1). A skipped block that "
              "the surface crosses into from a kept block is evaluated after all, so a bound too low loses no connected "
              "surface (the report counts these blocks as `blocks_grown`). Inside a kept block the same test runs on its "
              "eight octants' centres and then on the centres of the 2^3-cell sub-blocks of the octants kept; only the "
              "grid points of the sub-blocks kept are evaluated (the others take their centre's value, whose sign the bound "
              "proves theirs), and a skipped sub-block whose points then disagree in sign, or whose face point a "
              "neighbouring block's copy contradicts, is evaluated after all: the mesh is the one from every grid point, bit "
              "for bit (a test), from fewer evaluations than the kept blocks' grid points alone (the report's `points_evaluated`). "
              "The grid points are generated on the GPU from their indices and only their values come back (no gradient "
              "taps); crossings are put on the surface by false position with the Illinois rule (at most 8 steps, "
              "stopping once the crossing is known to 1e-4 of its edge, kept 1/1024 of an edge off grid points), vertices are projected onto it by two Newton steps within their "
              "cell (a vertex whose step would leave the cell by one face steps along that face onto the surface, up to "
              "two more times: the top of a dome that barely enters a cell; a clamp left such vertices off the surface by "
              "up to the dome's height, 2.4e-4 on the dataset torus at 64). Edges and cells are found per block through bitsets with running counts (no hash maps). PLY and OBJ are written here, STL and GLB through assimp; meshio and Open3D read all "
              "of them (a test opens each). A cell gets one vertex per patch of surface in it (its crossings joined "
              "along its faces, an ambiguous face split by its bilinear centre), so two sheets in one cell (walls "
              "thinner than a cell) stay apart. Where a tunnel is thinner than a cell (the Menger sponge, the Mandelbox), "
              "the patches on both sides of an ambiguous face can each join its two segments; the edge between their "
              "two vertices would then be shared by four triangles. Each segment of such a face gets a vertex of its own "
              "on the face, between the two cells' vertices, and the polygon around each crossing edge is fanned so that "
              "no edge gains a third triangle (manifold dual contouring's patch vertices, Schaefer, Ju and Warren 2007, "
              "on a uniform grid). A quad is split along its shorter diagonal, except one folded by more than a hundredth "
              "of a cell (across a crease), which takes the diagonal whose middle has the smaller |f|: the one along the "
              "crease, not the one cutting it off (the report's `folded_quads_turned`; a test bounds the rotated box's largest "
              "distance from the surface at 64 cells by 5e-4, where the shorter diagonal always gave 8.7e-4). Vertices at one position are welded only where the collapse keeps every vertex one "
              "fan; a triangle of zero area whose vertices lie in a row (seen on NVIDIA's driver, never on llvmpipe) is "
              "flipped away with the triangle across its long edge (the report's `collinear_flips`); a vertex whose QEF minimiser leaves its cell goes from its crossings' mean towards the minimiser as "
              "far as the cell allows. The grid has a cell of padding on every side and the field is cut by a "
              "box half a cell beyond the bounds: a shape that leaves the bounds is closed there by flat caps with "
              "sharp rims (the report says so and counts the grid points cut). Every dataset shape and every closed "
              "foreign file meshes manifold at 64 and 256 (the table at the end; a test checks all of them at 64).\n\n"
              "**Refinement (`--refine K`).** On a smooth surface the error of any mesh whose vertices lie on the surface "
              "is the sag of its triangles, about (edge length)^2 x curvature / 8: a grid twice as fine quarters it for "
              "eight times the cells. `--refine K` instead cuts every triangle of the dual-contoured mesh into four, K "
              "times, and steps each new vertex (an edge's midpoint) onto the exact surface: one field value per midpoint "
              "and a step along its edge's mean gradient (a second step where that direction may be off, judged from the "
              "angle between the ends' normals); a step longer than a quarter of the edge is not taken (`midpoints_kept`). "
              "Each level quarters a smooth shape's error (a test: Hausdorff falls by over 3x per level on the sphere and "
              "the torus) at a fraction of a finer grid's cost, which is what the equal-error comparison in "
              "[meshing-peers.md](meshing-peers.md) uses on smooth shapes. Creases stay where the coarse grid put them "
              "(a midpoint on a flat face has f = 0 and does not move; a test checks the rotated box's error does not "
              "grow), and features smaller than the coarse grid's cells stay missed: refine where the shape is smooth at "
              "the coarse scale. The topology is exact without a check of the fine mesh: the cut doubles every edge and "
              "adds three in each triangle, so the report's counts come from the coarse mesh's check (`subdividedTopology`, "
              "tested against a full check), and its degenerate triangles are counted on the fine mesh (where two vertices "
              "the coarse weld kept apart share a position, their midpoints do too: those are welded and the fine mesh is "
              "checked in full).\n\n"
              "**In the workbench.** File > Export mesh meshes the editor's text with the Parameters dock's values in a "
              "child process (resolution, progress, Cancel; a cancelled export leaves no file) and then shows the mesh "
              "over the surface, coloured per pixel by the field at the mesh's own point: grey where it lies on the zero "
              "set, red outside, blue inside, full colour at a tenth of the mesh's mean edge. View > Show mesh deviation "
              "does the same for any mesh file (another tool's, a reconstruction). Below, a coarse UV sphere written by a "
              "test over the Sphere: its vertices are on the surface, its flat facets dip inside towards their middles "
              "(`scripts/docs_screenshots` makes the picture from the GUI test).\n\n"
              "![mesh deviation overlay](images/mesh_deviation.png)\n\n")
    out.write(f"Run on {datetime.date.today().isoformat()}, {platform.node()} ({os.cpu_count()} cores, {gl or 'GL unknown'}). "
              "Each row is one `sdfwb --batch mesh --sdf SDF --resolution R --refine K --json` (R + K in the table; "
              "bounds [-1,1]^3, error from 100 000 "
              "points each way). Extraction: the field on the GPU, blocks of 8^3 cells skipped by the Lipschitz bound of a "
              "quick audit, crossings by false position on the field, one QEF vertex per patch of surface in a cell, projected onto the surface. "
              "Error: mesh to surface is |f| at the vertices and at points spread on the faces (a lower bound of the "
              "distance where the field is only conservative, as for the mug); surface to mesh is points of the zero set "
              "(the surface sampler, |f| < 1e-5, which is the floor of this measure) to the nearest triangle. Hausdorff is "
              "the larger maximum.\n\n")
    out.write("![error against run time](images/mesh_error_vs_time.png)\n\n")
    out.write("| SDF | resolution | vertices | triangles | watertight | blocks evaluated | extraction s | mesh->surface mean / max | "
              "surface->mesh mean / max | Hausdorff | error s |\n|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        out.write(f"| {r['label']} | {grid_of(r)} | {r['vertices']} | {r['triangles']} | "
                  f"{'yes' if r['watertight'] else 'no (%d boundary, %d non-manifold)' % (r['boundary_edges'], r['non_manifold_edges'])} | "
                  f"{r['blocks_kept']} of {r['blocks']} | {r['mesh_seconds']:.2f} | "
                  f"{r['mesh_to_surface_mean']:.2g} / {r['mesh_to_surface_max']:.2g} | "
                  f"{r['surface_to_mesh_mean']:.2g} / {r['surface_to_mesh_max']:.2g} | {r['hausdorff']:.2g} | {r['error_seconds']:.2f} |\n")
# Every dataset SDF and every foreign file (tests/foreign: Shadertoy, IQ, hg_sdf, G3D styles) at
# resolutions 64 and 256: watertight, manifold, degenerate triangles, self-crossings.
def topology(path, resolution):
    out = subprocess.run([BINARY, "--batch", "mesh", "--sdf", path, "--resolution", str(resolution), "--error-samples", "0",
                          "--self-intersections", "--output", os.path.join(work, "d.ply"), "--json", "--quiet"], env=ENV,
                         capture_output=True, text=True)
    if out.returncode != 0:
        return None, out.stderr.strip()
    return json.loads(out.stdout[out.stdout.index("{"):]), None


shapes = [dict(name=e["name"], category=e["category"], path=e["path"])
          for e in json.loads(subprocess.run([BINARY, "--batch", "list", "--json"], env=ENV, capture_output=True, text=True,
                                             check=True).stdout)["sdfs"]]
for path in sorted(glob.glob(os.path.join(ROOT, "tests", "foreign", "*.glsl"))):
    expect = re.search(r"// expect:.*", open(path).read())
    nan = bool(expect and re.search(r"flags=\S*nan", expect.group(0)))
    shapes.append(dict(name=os.path.basename(path), category="foreign, NaN over half of space" if nan else "foreign", path=path))
for shape in shapes:
    for resolution in (64, 256):
        shape[resolution], shape[f"failed{resolution}"] = topology(shape["path"], resolution)
    r64, r256 = shape[64], shape[256]
    print(f"{shape['name']:40s} 64: {r64 and r64['manifold']} 256: {r256 and r256['manifold']}", flush=True)


def clean(r):
    return r is not None and r["manifold"] and r["degenerate_triangles"] == 0


def count(group, resolution):
    return sum(1 for d in group if clean(d[resolution]))


dataset = [d for d in shapes if d["category"] != "foreign" and not d["category"].startswith("foreign")]
closed_foreign = [d for d in shapes if d["category"] == "foreign"]
nan_foreign = [d for d in shapes if d["category"].startswith("foreign, NaN")]
with open(os.path.join(ROOT, "docs", "meshing.md"), "a") as out:
    out.write("\n## Every dataset shape and foreign file at resolutions 64 and 256\n\n"
              f"Manifold (watertight, every edge two triangles, every vertex one fan, every edge run once each way) with no "
              f"degenerate triangle (a repeated vertex or zero area): {count(dataset, 64)} of {len(dataset)} dataset SDFs at 64 "
              f"and {count(dataset, 256)} at 256; {count(closed_foreign, 64)} of {len(closed_foreign)} closed foreign files "
              f"(tests/foreign, in the styles of Shadertoy, IQ's articles, hg_sdf and G3D) at 64 and {count(closed_foreign, 256)} "
              f"at 256. The {len(nan_foreign)} foreign files whose field is NaN over half of space (written so on purpose: "
              "sqrt of a coordinate that goes negative) are not closed shapes: their surfaces end where the NaN begins, "
              "which the boundary edges count. Self-crossing pairs are pairs of triangles that share no vertex and cross "
              "(an edge of one passes through the other, or touches it); they are counted, not removed. Split faces are "
              "ambiguous cell faces where a tunnel thinner than a cell passes and each segment got a vertex of its own. "
              "Each cell is one `sdfwb --batch mesh --resolution R --error-samples 0 --self-intersections`.\n\n")
    out.write("| SDF | category | triangles (64) | boundary / non-manifold edges | non-manifold vertices | misoriented edges | "
              "degenerate | self-crossing pairs | split faces | bounds cut | triangles (256) | manifold at 256 | "
              "self-crossing pairs (256) | mesh s (256) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for d in shapes:
        r, q = d[64], d[256]
        if r is None or q is None:
            out.write(f"| {d['name']} | {d['category']} | failed: {(d['failed64'] or d['failed256'])[:80]} |"
                      " | | | | | | | | | | |\n")
            continue
        at256 = "yes" if clean(q) else (f"no ({q['boundary_edges']} boundary, {q['non_manifold_edges']} non-manifold edges, "
                                         f"{q['non_manifold_vertices']} vertices, {q['degenerate_triangles']} degenerate)")
        out.write(f"| {d['name']} | {d['category']} | {r['triangles']} | {r['boundary_edges']} / {r['non_manifold_edges']} | "
                  f"{r['non_manifold_vertices']} | {r['misoriented_edges']} | {r['degenerate_triangles']} | "
                  f"{r['self_intersections']} | {r.get('split_faces', 0)} | {'yes' if r['bounds_cut_points'] else 'no'} | "
                  f"{q['triangles']} | {at256} | {q['self_intersections']} | {q['mesh_seconds']:.2f} |\n")
print(f"dataset: {count(dataset, 64)} of {len(dataset)} manifold at 64, {count(dataset, 256)} at 256; foreign "
      f"{count(closed_foreign, 64)} / {count(closed_foreign, 256)} of {len(closed_foreign)}")

# Another tool on the same field: scikit-image's marching cubes on the lattice of the same resolution.
import time

import meshio
import sdfwb
from skimage import measure

COMPARED = [("Sphere", "sphere"), ("Box (sharp edges)", "box"), ("Torus", "torus"),
            ("hg_sdf polar columns", os.path.join(ROOT, "tests", "params", "hg_polar_columns.glsl"))]
comparison = []
for label, sdf in COMPARED:
    for resolution in [r for r in (64, 128, 256) if r <= LARGEST]:
        ours = os.path.join(work, "ours.ply")
        mesh = json.loads(subprocess.run([BINARY, "--batch", "mesh", "--sdf", sdf, "--resolution", str(resolution), "--output", ours,
                                          "--error-samples", "0", "--json", "--quiet"], env=ENV, capture_output=True,
                                         text=True, check=True).stdout)
        started = time.perf_counter()
        n = resolution + 1
        grid = sdfwb.sample(sdf, "grid", n ** 3)["distance"].reshape(n, n, n)  # [z][y][x]: x varies fastest
        sampled = time.perf_counter() - started
        h = 2.0 / resolution
        mc_started = time.perf_counter()
        vertices, faces, _, _ = measure.marching_cubes(grid, 0.0, spacing=(h, h, h))
        mc_seconds = time.perf_counter() - mc_started
        theirs = os.path.join(work, "skimage.ply")
        meshio.write(theirs, meshio.Mesh(vertices[:, ::-1] - 1.0, [("triangle", faces)]), binary=True)
        for method, path, seconds, triangles in (("sdfwb dual contouring", ours, mesh["mesh_seconds"], mesh["triangles"]),
                                                  ("scikit-image marching cubes", theirs, mc_seconds, len(faces))):
            e = json.loads(subprocess.run([BINARY, "--batch", "grade", "--mesh", path, "--sdf", sdf, "--tau", "0.005", "--json",
                                           "--quiet"], env=ENV, capture_output=True, text=True, check=True).stdout)
            comparison.append(dict(label=label, resolution=resolution, method=method, seconds=seconds, triangles=triangles,
                                   sampled=sampled if "scikit" in method else None, eval=e))
            print(f"{label:24s} {resolution:4d} {method:28s} {seconds:6.2f} s  chamfer {e['chamfer_l1']:.3g}  "
                  f"Hausdorff {e['hausdorff']:.3g}  NC {e['normal_consistency']:.4f}  IoU {e['iou']:.4f}", flush=True)
with open(os.path.join(ROOT, "docs", "meshing.md"), "a") as out:
    out.write("\n## Against another tool, on the same field\n\n")
    out.write("scikit-image's `measure.marching_cubes` on the lattice of the same resolution (the field sampled by "
              "`sdfwb.sample(sdf, 'grid', (R+1)^3)`, which also writes gradients: its seconds are a separate column, not "
              "what a NumPy field would cost), against `sdfwb --batch mesh` (its extraction seconds, its own field "
              "evaluation included). This table compares accuracy on the same field; for speed against the fastest "
              "reference pipeline a user would write (the field in NumPy at its best thread count, then marching cubes), "
              "see [mesh extraction against NumPy + scikit-image](benchmarks/mesh_vs_marching_cubes.md), where sdfwb is "
              "slower. Both graded by `sdfwb --batch grade --tau 0.005` (100 000 points each way, IoU on a 128^3 "
              "grid): Chamfer L1 is the mean of the two mean unsquared distances; normal consistency the mean |cos| between "
              "face normals and the field's gradient.\n\n")
    out.write("| SDF | resolution | method | triangles | seconds | lattice from sdfwb.sample s | Chamfer L1 | Hausdorff | "
              "normal consistency | F-score (0.005) | IoU |\n")
    out.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
    for c in comparison:
        e = c["eval"]
        lattice = f"{c['sampled']:.2f}" if c["sampled"] is not None else ""
        out.write(f"| {c['label']} | {c['resolution']} | {c['method']} | {c['triangles']} | {c['seconds']:.2f} | {lattice} | "
                  f"{e['chamfer_l1']:.2g} | {e['hausdorff']:.2g} | {e['normal_consistency']:.4f} | {e['fscore']:.4f} | "
                  f"{e['iou']:.4f} |\n")
quote_peers()
print("wrote docs/meshing.md and docs/images/mesh_error_vs_time.png")
