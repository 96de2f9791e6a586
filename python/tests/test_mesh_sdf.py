"""Meshes in: a triangle mesh file is an SDF for sample, evaluate, audit and mesh, with the sign method and
normalisation the caller names. The meshes are written here (a cube, whose exact signed distance is known,
and the same cube with one side missing)."""
import warnings

import numpy as np
import pytest

import sdfwb
import sdfwb.recipes

CORNERS = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
# Two triangles a side, counter-clockwise seen from outside (vertex k has bits x y z of k).
SIDES = {"-x": [(0, 1, 3), (0, 3, 2)], "+x": [(4, 6, 7), (4, 7, 5)], "-y": [(0, 4, 5), (0, 5, 1)],
         "+y": [(2, 3, 7), (2, 7, 6)], "-z": [(0, 2, 6), (0, 6, 4)], "+z": [(1, 5, 7), (1, 7, 3)]}


def write_cube(path, skip=()):
    with open(path, "w") as obj:
        for corner in CORNERS:
            obj.write("v %g %g %g\n" % corner)
        for side, triangles in SIDES.items():
            if side in skip:
                continue
            for a, b, c in triangles:
                obj.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    return str(path)


def box_sdf(points, half=0.5):
    q = np.abs(points) - half
    return np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0)


@pytest.mark.parametrize("sign", ["winding", "parity", "pseudonormal"])
def test_a_cube_file_is_its_exact_sdf_with_every_sign(tmp_path, sign):
    cube = write_cube(tmp_path / "cube.obj")
    points = np.random.default_rng(3).uniform(-1.0, 1.0, (20000, 3)).astype(np.float32)
    values = sdfwb.evaluate(cube, points, gradient=False, sign=sign)["distance"]
    exact = box_sdf(points.astype(np.float64))
    assert np.max(np.abs(values - exact)) < 1e-5 * np.sqrt(3.0)


def test_sample_normalizes_and_an_open_cube_keeps_its_inside(tmp_path):
    big = tmp_path / "big.obj"
    write_cube(big)
    text = big.read_text().splitlines()
    # the same cube, 6 units wide and moved: unit-cube brings it back to [-1, 1]^3
    moved = ["v %g %g %g" % tuple(6 * c + o for c, o in zip(map(float, line.split()[1:]), (10, 0, -3)))
             if line.startswith("v ") else line for line in text]
    big.write_text("\n".join(moved) + "\n")
    rows = sdfwb.sample(str(big), "rand", 5000, seed=2, normalize="unit-cube")
    assert np.max(np.abs(rows["distance"] - box_sdf(rows["position"].astype(np.float64), 1.0))) < 2e-5

    open_cube = write_cube(tmp_path / "open.obj", skip=("+z",))
    inside = np.array([[0.0, 0.0, 0.0], [0.2, -0.3, -0.2], [0.0, 0.0, 0.4]], dtype=np.float32)
    assert np.all(sdfwb.evaluate(open_cube, inside, gradient=False)["distance"] < 0)
    # parity counts crossings, which a missing side changes: some ray escapes through the hole
    parity = sdfwb.evaluate(open_cube, inside, gradient=False, sign="parity")["distance"]
    assert np.any(parity > 0)


def test_sample_files_record_the_mesh_provenance(tmp_path):
    cube = write_cube(tmp_path / "cube.obj")
    for extension in ("npz", "ply", "bin"):
        out = str(tmp_path / ("rows." + extension))
        sdfwb.run({"kind": "sample", "sdf": cube, "pattern": "rand", "n": 64, "output": out,
                   "sign": "parity", "normalize": "unit-sphere"})
        if extension == "bin":
            import json
            mesh = json.load(open(out + ".json"))["mesh"]
        else:
            mesh = sdfwb.load(out)["metadata"]["mesh"]
        assert mesh["file"] == "cube.obj" and mesh["triangles"] == 12 and mesh["closed"] is True
        assert mesh["sign"] == "parity" and mesh["normalize"] == "unit-sphere"
        assert mesh["bounds"] == [-0.5, -0.5, -0.5, 0.5, 0.5, 0.5]
        assert np.isclose(mesh["transform"][0], 1 / np.sqrt(0.75)) and mesh["transform"][15] == 1
        report = sdfwb.run({"kind": "sample", "sdf": cube, "pattern": "rand", "n": 64, "output": out,
                            "sign": "parity", "normalize": "unit-sphere"})
        assert report["mesh_source"] == mesh  # the report says what the file says


def test_results_and_reports_name_the_mesh_they_came_from(tmp_path):
    cube = write_cube(tmp_path / "cube.obj")
    points = np.zeros((4, 3), dtype=np.float32)
    for result in (sdfwb.evaluate(cube, points, normalize="unit-cube"),
                   sdfwb.sample(cube, "rand", 16, normalize="unit-cube"),
                   sdfwb.audit(cube, samples=200, normalize="unit-cube"),
                   sdfwb.mesh(cube, resolution=16, lipschitz=1.0, normalize="unit-cube")["report"]):
        source = result["mesh_source"]
        assert source["file"] == "cube.obj" and source["sign"] == "winding" and source["normalize"] == "unit-cube"
        assert np.isclose(source["transform"][0], 2.0) and source["bounds"][3] == 0.5
    assert sdfwb.evaluate("sphere", points)["mesh_source"] is None
    assert sdfwb.sample("sphere", "rand", 16)["mesh_source"] is None


def test_meshing_an_open_cube_gives_a_watertight_mesh(tmp_path):
    open_cube = write_cube(tmp_path / "open.obj", skip=("+z", "-x"))
    meshed = sdfwb.mesh(open_cube, resolution=32)
    report = meshed["report"]
    assert report["watertight"] and report["boundary_edges"] == 0 and report["non_manifold_edges"] == 0
    assert np.allclose(meshed["vertices"].min(axis=0), -0.5, atol=1e-3)
    assert np.allclose(meshed["vertices"].max(axis=0), 0.5, atol=1e-3)


def test_mesh_options_are_checked(tmp_path):
    cube = write_cube(tmp_path / "cube.obj")
    with pytest.raises(ValueError, match="sign=: "):
        sdfwb.evaluate(cube, np.zeros((1, 3), np.float32), sign="inside")
    with pytest.raises(ValueError, match="normalize=: "):
        sdfwb.sample(cube, "rand", 10, normalize="unit")
    with pytest.raises(ValueError, match="mesh files"):
        sdfwb.sample("Sphere", "rand", 10, sign="winding")
    audit = sdfwb.audit(cube, samples=500)
    assert audit["verdict"] in ("exact", "conservative"), audit["reason"]
    assert not any(flag["flag"] == "sign-uncertain" for flag in audit["flags"])
    opened = sdfwb.audit(write_cube(tmp_path / "open.obj", skip=("+z",)), samples=500)
    uncertain = [flag for flag in opened["flags"] if flag["flag"] == "sign-uncertain"]
    assert uncertain and uncertain[0]["count"] > 10 and uncertain[0]["examples"], opened["reason"]


def test_deepsdf_recipe_on_a_mesh_draws_its_near_points_on_the_faces(tmp_path):
    # A 6-unit cube far from the origin, scaled into the box: the recipe's near points lie on the
    # unit cube's faces moved by the two Gaussians (deviations sqrt(0.005) and sqrt(0.0005)), none
    # is dropped, each row's distance is the box's, and the scaled shape raises no "leaves the box".
    big = tmp_path / "far.obj"
    write_cube(big)
    lines = big.read_text().splitlines()
    moved = [("v %g %g %g" % tuple(6.0 * float(x) + 10.0 for x in line.split()[1:])) if line.startswith("v ") else line
             for line in lines]
    big.write_text("\n".join(moved) + "\n")
    out = tmp_path / "deepsdf.npz"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        meta = sdfwb.recipes.deepsdf(str(big), str(out), n=4000, seed=1, normalize="unit-cube")
    assert meta["rows_dropped"] == 0
    data = np.load(out)
    rows = np.concatenate([data["pos"], data["neg"]])
    assert len(rows) == 4000
    assert np.all(data["pos"][:, 3] > 0) and np.all(data["neg"][:, 3] <= 0)
    assert np.max(np.abs(rows[:, 3] - box_sdf(rows[:, :3].astype(np.float64), half=1.0))) < 1e-5
    # 47 of 50 points are near the faces: |distance| mostly within 3 wide deviations (0.21).
    assert np.mean(np.abs(rows[:, 3]) < 0.21) > 0.9


def write_broken_ball(path, remove=0.03, seed=5):
    # An octahedron refined four times onto the sphere of radius 0.7 (2048 triangles), with a share of
    # its faces removed at random: holes everywhere, as in a scanned or ShapeNet-style mesh.
    vertices = [np.array(v, float) for v in [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    for _ in range(4):
        middle, refined = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = vertices[a] + vertices[b]
                vertices.append(m / np.linalg.norm(m))
                middle[key] = len(vertices) - 1
            return middle[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            refined += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = refined
    keep = np.random.default_rng(seed).random(len(faces)) >= remove
    with open(path, "w") as obj:
        for v in vertices:
            obj.write("v %.7f %.7f %.7f\n" % tuple(0.7 * v))
        for (a, b, c), kept in zip(faces, keep):
            if kept:
                obj.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    return str(path), int((~keep).sum())


def test_a_broken_mesh_remeshes_watertight_and_grades_against_its_input(tmp_path):
    broken, removed = write_broken_ball(tmp_path / "broken.obj")
    assert removed > 30
    out = str(tmp_path / "remeshed.ply")
    report = sdfwb.run({"kind": "mesh", "sdf": broken, "output": out, "resolution": 48, "error_samples": 0,
                        "lipschitz": 1.0})  # a distance field: no audit needed for the bound
    assert report["watertight"] and report["boundary_edges"] == 0 and report["non_manifold_edges"] == 0
    assert report["degenerate_triangles"] == 0
    graded = sdfwb.evaluate_mesh(out, broken, points=20000, occupancy_resolution=0)
    # Against the input's own field: the remesh lies on its surface (the holes are filled across,
    # within a cell of the sphere they were cut from; a cell is 2/48).
    assert graded["chamfer_l1"] < 0.01 and graded["hausdorff"] < 2 * 2 / 48
    assert graded["fscore"] > 0.95


def test_evaluate_counts_the_hierarchy_nodes_the_cpu_engine_visits(tmp_path, monkeypatch):
    """Issue 46, point 3: node visits per query, a count that does not depend on the driver. A point
    far from the cube needs few nearest-walk nodes; points on a shell just off its faces need more and
    take their sign from the sign cache or a lattice point (closed cube: no winding walk remains)."""
    monkeypatch.setenv("SDFWB_MESH_ENGINE", "cpu")
    cube = write_cube(tmp_path / "cube.obj")
    rng = np.random.default_rng(5)
    far = rng.normal(size=(4000, 3))
    far = (3.0 * far / np.linalg.norm(far, axis=1, keepdims=True)).astype(np.float32)
    near = rng.uniform(-0.5, 0.5, (4000, 3))
    near[:, 0] = np.where(rng.random(4000) < 0.5, -0.5, 0.5) + rng.normal(scale=1e-3, size=4000)
    near = near.astype(np.float32)
    counts = {}
    for name, points in (("far", far), ("near", near)):
        result = sdfwb.evaluate(cube, points, gradient=True)
        nodes = result["mesh_nodes"]
        assert nodes is not None and nodes["rows"] == len(points), nodes
        assert set(nodes) == {"rows", "nearest", "winding", "segment", "cached_signs", "crossed_signs"}
        assert 1 <= nodes["nearest"] / len(points) < 64, nodes
        assert nodes["cached_signs"] + nodes["crossed_signs"] <= len(points), nodes
        exact = box_sdf(points.astype(np.float64))
        assert np.abs(result["distance"] - exact).max() < 1e-5
        counts[name] = nodes
    assert counts["far"]["cached_signs"] == len(far), counts["far"]
    assert counts["near"]["cached_signs"] + counts["near"]["crossed_signs"] > 0.5 * len(near), counts["near"]
    # GLSL fields and the GPU engine have no CPU walks to count.
    assert sdfwb.evaluate("sphere", far[:10])["mesh_nodes"] is None
    monkeypatch.setenv("SDFWB_MESH_ENGINE", "gpu")
    monkeypatch.delenv("SDFWB_MESH_COUNT", raising=False)
    assert sdfwb.evaluate(cube, far[:10])["mesh_nodes"] is None
    # ... unless asked to count (SDFWB_MESH_COUNT=1): the GLSL field's walks, per evaluation; far
    # from a closed mesh its lattice of winding numbers gives every sign.
    monkeypatch.setenv("SDFWB_MESH_COUNT", "1")
    glsl = sdfwb.evaluate(cube, far)
    nodes = glsl["mesh_nodes"]
    assert nodes is not None and nodes["rows"] == len(far), nodes
    assert 1 <= nodes["nearest"] / len(far) < 64, nodes
    assert nodes["cached_signs"] == len(far), nodes
    assert np.abs(glsl["distance"] - box_sdf(far.astype(np.float64))).max() < 1e-5
