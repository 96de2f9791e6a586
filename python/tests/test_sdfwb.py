"""The Python module as a training pipeline uses it: headless, no Qt, no copies, same bits as the CLI."""
import gc
import json
import os
import resource
import subprocess
import tempfile
import threading
import time

import numpy as np
import pytest

import sdfwb

BINARY = os.environ["SDFWB_BINARY"]
MODULE = os.environ["SDFWB_MODULE"]


def cli_sample(sdf, pattern, n, seed, path):
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    subprocess.run([BINARY, "--batch", "sample", "--sdf", sdf, "--pattern", pattern, "-n", str(n), "--seed", str(seed),
                    "--output", path, "--quiet"], check=True, env=env)


def test_runs_without_a_display():
    assert "DISPLAY" not in os.environ
    result = sdfwb.sample("sphere", "rand", 10)
    assert result["position"].shape == (10, 3)


def test_module_links_no_qt():
    libraries = subprocess.run(["ldd", MODULE], capture_output=True, text=True, check=True).stdout
    assert "Qt" not in libraries and "qscintilla" not in libraries.lower(), libraries


def test_arrays_have_the_documented_shapes_and_own_their_memory():
    result = sdfwb.sample("torus", "near", 5000, seed=3)
    assert result["position"].shape == (5000, 3) and result["position"].dtype == np.float32
    assert result["distance"].shape == (5000,) and result["gradient"].shape == (5000, 3)
    for key in ("position", "distance", "gradient"):
        assert result[key].flags.owndata and result[key].flags.c_contiguous, key
    assert result["bad_rows"] == 0
    assert np.all(np.abs(result["distance"]) <= 0.3)


@pytest.mark.parametrize("pattern", ["rand", "near", "metropolis"])
def test_same_seed_gives_the_clis_file_bit_for_bit(pattern):
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "cli.npz")
        cli_sample("torus", pattern, 20000, 11, path)
        expected = np.load(path, allow_pickle=False)
        result = sdfwb.sample("torus", pattern, 20000, seed=11)
        for key in ("position", "distance", "gradient"):
            assert np.array_equal(result[key], expected[key], equal_nan=True), key


def test_sdf_can_be_a_name_a_path_or_source():
    by_name = sdfwb.sample("Sphere", "rand", 100, seed=2)
    path = next(e["path"] for e in sdfwb.list_sdfs() if e["name"] == "Sphere")
    by_path = sdfwb.sample(path, "rand", 100, seed=2)
    source = open(path).read()
    by_source = sdfwb.sample(source, "rand", 100, seed=2)
    assert np.array_equal(by_name["distance"], by_path["distance"])
    assert np.array_equal(by_name["distance"], by_source["distance"])


def test_errors_are_python_exceptions_with_clear_messages():
    with pytest.raises(ValueError, match="'spiral'"):
        sdfwb.sample("torus", "spiral", 10)
    with pytest.raises(ValueError, match="'no such shape'"):
        sdfwb.sample("no such shape", "rand", 10)
    with pytest.raises(ValueError, match=r"<source>:1:\d+: error: .*radius"):
        sdfwb.sample("float sdf(vec3 p) { return length(p) - radius; }", "rand", 10)
    # A failure names the keyword argument at fault, as it is written in the call.
    with pytest.raises(ValueError, match="^n=: the sample count must be at least 1"):
        sdfwb.sample("torus", "rand", 0)
    with pytest.raises(ValueError, match="^near_truncate=: needs near_widths=$"):
        sdfwb.sample("sphere", "near", 10, near_truncate=2.0)
    with pytest.raises(ValueError, match="^bounds=: expected finite MINX,MINY,MINZ,MAXX,MAXY,MAXZ"):
        sdfwb.mesh("sphere", resolution=8, bounds=(1, 1, 1, 0, 0, 0))


def test_the_gil_is_released_while_sampling():
    ticks = []
    done = threading.Event()

    def worker():
        sdfwb.sample("torus", "metropolis", 400000, seed=5)
        done.set()

    thread = threading.Thread(target=worker)
    thread.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.005)
    thread.join()
    assert len(ticks) > 10, "the main thread could not run while sampling"


def test_a_training_loop_keeps_memory_flat():
    def resident_mib():
        with open("/proc/self/status") as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024.0
        return 0.0

    for _ in range(3):
        sdfwb.sample("torus", "rand", 500000, seed=0)
    gc.collect()
    before = resident_mib()
    for step in range(20):
        batch = sdfwb.sample("torus", "rand", 500000, seed=step)
        loss = float(np.mean(batch["distance"] ** 2))  # stands in for a training step
        del batch
    gc.collect()
    assert loss > 0
    assert resident_mib() - before < 40.0, f"{resident_mib() - before:.1f} MiB more after 20 batches of 500k"


@pytest.mark.parametrize("extension", ["bin", "npz", "ply"])
def test_load_and_save_round_trip(extension):
    result = sdfwb.sample("box", "surface", 3000, seed=8)
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "samples." + extension)
        sdfwb.save(path, result["position"], result["distance"], result["gradient"], sdf="box", pattern="surface", seed=8)
        back = sdfwb.load(path)
        for key in ("position", "distance", "gradient"):
            assert np.array_equal(back[key], result[key]), key
        if extension != "bin":
            assert back["metadata"]["sdf"] == "box" and back["metadata"]["seed"] == 8
    with pytest.raises(ValueError, match=r"\(N, 3\)"):
        sdfwb.save("/tmp/x.npz", np.zeros((4, 2)), np.zeros(4), np.zeros((4, 3)))


def test_load_rejects_corrupt_files_cleanly():
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "broken.npz")
        with open(path, "wb") as f:
            f.write(b"PK\x03\x04 this is not a zip file")
        with pytest.raises(ValueError, match="broken.npz"):
            sdfwb.load(path)


def test_audit_and_list():
    report = sdfwb.audit("sphere", samples=5000)
    assert report["verdict"] == "exact"
    assert abs(report["lipschitz"] - 1.0) < 0.01
    assert report["truncation_distance"] is None
    entries = sdfwb.list_sdfs()
    assert any(e["name"] == "Torus" for e in entries)
    assert {"name", "category", "declared_type", "animated", "path"} <= set(entries[0])


def test_surface_tolerance_bounds_the_surface_samples_error():
    # Sphere of radius 0.8 (dataset "sphere"): the exact distance of a surface sample is | |p| - 0.8 |.
    # (What the tolerance costs in time is a benchmark's figure, docs/benchmarks.md, not a test's.)
    errors = {}
    for tolerance in (1e-2, 1e-5):
        rows = sdfwb.sample("sphere", "surface", 4096, seed=3, surface_tolerance=tolerance)
        assert rows["bad_rows"] == 0
        error = np.abs(np.linalg.norm(rows["position"].astype(np.float64), axis=1) - 0.8)
        assert error.max() <= tolerance * 1.01 + 1e-6, (tolerance, error.max())
        errors[tolerance] = np.median(error)
    assert errors[1e-5] < errors[1e-2] / 100
    with pytest.raises(ValueError, match="^surface_tolerance=: must be positive"):
        sdfwb.sample("sphere", "surface", 16, surface_tolerance=0.0)


SHADERTOY = """
#define EPS 0.001
vec2 map(vec3 p) { return vec2(length(p) - 0.5, 1.0); }
float snake(vec3 p) { return min(1.0, 1.9 * (length(p) - 0.5)); }
vec3 calcNormal(vec3 p) { vec2 e = vec2(EPS, 0.0); return normalize(vec3(map(p + e.xyy).x - map(p - e.xyy).x, 0.0, 0.0)); }
"""


def test_foreign_code_entry_points_and_audit_flags():
    found = sdfwb.sample(SHADERTOY, "rand", 1000, seed=3)  # map() by convention: its .x
    expected = np.linalg.norm(found["position"], axis=1) - 0.5
    assert np.allclose(found["distance"], expected, atol=1e-6)
    snake = sdfwb.sample(SHADERTOY, "rand", 1000, seed=3, entry="snake")
    assert np.allclose(snake["distance"], np.minimum(1.0, 1.9 * expected), atol=1e-5)
    report = sdfwb.audit(SHADERTOY, samples=5000, entry="snake")
    assert report["entry"] == "snake"
    flags = {f["flag"]: f for f in report["flags"]}
    assert set(flags) == {"non-conservative", "truncated"}
    assert report["verdict"] == "truncated"
    assert abs(flags["truncated"]["value"] - 1.0) < 1e-3
    assert abs(flags["non-conservative"]["lipschitz"] - 1.9) < 0.02
    assert 0 < len(flags["truncated"]["examples"]) <= 16
    with pytest.raises(ValueError, match="entry point 'nothere' not found"):
        sdfwb.audit(SHADERTOY, entry="nothere")
    with pytest.raises(ValueError, match="truncation.reach"):
        sdfwb.audit(SHADERTOY, entry="snake", truncation_reach=0.0)
    with pytest.raises(ValueError, match="truncation.reach"):  # its old name, still accepted
        sdfwb.audit(SHADERTOY, entry="snake", probe_distance=0.0)


def cli_json(*arguments):
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    result = subprocess.run([BINARY, "--batch", *arguments], capture_output=True, text=True, env=env)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def without_timings(report):
    return {k: v for k, v in report.items() if k not in ("seconds", "setup_seconds", "frame_ms", "render_seconds", "samples_per_second", "kernel_seconds")}


def test_requests_are_the_clis_json_and_reports_match_it():
    # The request the CLI's options make, run from Python as a dict: the same report, figure for figure.
    request = cli_json("audit", "--sdf", "Sphere", "--plane", "0,0,1,0.25", "--resolution", "48", "--print-request")
    assert request["kind"] == "audit" and request["plane"] == [0.0, 0.0, 1.0, 0.25]
    ours = sdfwb.run(request)
    theirs = cli_json("audit", "--sdf", "Sphere", "--plane", "0,0,1,0.25", "--resolution", "48", "--json")
    assert without_timings(ours) == without_timings(theirs)
    assert abs(ours["minimum"] + 0.55) < 0.02 and ours["points"] > 0
    # audit() keywords build the same request; its report has the CLI's keys.
    report = sdfwb.audit("Sphere", samples=2000, seed=4)
    cli = cli_json("audit", "--sdf", "Sphere", "--samples", "2000", "--seed", "4", "--json")
    assert set(cli) <= set(report)
    assert report["verdict"] == cli["verdict"] and report["lipschitz"] == cli["lipschitz"]


def test_run_renders_from_a_json_string_and_names_bad_keys():
    with tempfile.TemporaryDirectory() as folder:
        output = os.path.join(folder, "box.png")
        source = "float map(vec3 p) { vec3 q = abs(p) - 0.5; return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }"
        report = sdfwb.run(json.dumps({"kind": "render", "source": source, "output": output, "width": 64, "height": 48,
                                       "shading": {"mode": "steps"}}))
        assert report["entry"] == "map" and report["width"] == 64 and os.path.getsize(output) > 0
    with pytest.raises(ValueError, match="'shading.mod': unknown key"):
        sdfwb.run({"kind": "render", "sdf": "Sphere", "output": "x.png", "shading": {"mod": "steps"}})
    with pytest.raises(ValueError, match="'fps': must be"):  # the request's key, as written here (the CLI says --fps)
        sdfwb.run({"kind": "animate", "sdf": "Sphere", "output": "x.mp4", "fps": 0})
    listing = sdfwb.run({"kind": "list"})
    assert any(item["name"] == "Torus" for item in listing["sdfs"])


def test_params_lists_annotated_uniforms_and_names_mistakes():
    source = ("uniform float radius = 0.5; // @range 0.1 1.0 @label \"Radius\"\n"
              "uniform vec3 tint = vec3(1, 0.5, 0); // @color\n"
              "float sdf(vec3 p) { return length(p) - radius; }\n")
    report = sdfwb.params(source)
    assert [p["name"] for p in report["parameters"]] == ["radius", "tint"]
    radius = report["parameters"][0]
    assert radius["default"] == [0.5] and radius["minimum"] == pytest.approx(0.1) and radius["label"] == "Radius"
    assert report["parameters"][1]["color"] and report["parameters"][1]["default"] == [1.0, 0.5, 0.0]
    assert sdfwb.run({"kind": "params", "source": source}) == report
    with pytest.raises(ValueError, match=r"<source>:1:\d+: error: parameter 'radius': @range 1 0 is empty"):
        sdfwb.params("uniform float radius = 0.5; // @range 1 0\nfloat sdf(vec3 p) { return length(p) - radius; }\n")


PARAMS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "params")


def test_params_give_the_clis_bits_and_travel_in_the_metadata():
    columns = os.path.join(PARAMS, "hg_polar_columns.glsl")
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "cli.npz")
        env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        subprocess.run([BINARY, "--batch", "sample", "--sdf", columns, "--pattern", "near", "-n", "4000", "--seed", "3",
                        "--param", "columns=9", "--param", "ringRadius=0.4", "--output", path, "--quiet"], check=True, env=env)
        expected = np.load(path, allow_pickle=False)
        result = sdfwb.sample(columns, "near", 4000, seed=3, params={"columns": 9, "ringRadius": 0.4})
        for key in ("position", "distance", "gradient"):
            assert np.array_equal(result[key], expected[key], equal_nan=True), key
        assert result["parameters"] == {"columns": 9, "ringRadius": pytest.approx(0.4), "columnRadius": pytest.approx(0.1)}
        assert json.loads(str(expected["parameters"])) == {"columns": 9, "ringRadius": 0.4, "columnRadius": 0.1}
        assert sdfwb.load(path)["metadata"]["parameters"] == {"columns": 9, "ringRadius": 0.4, "columnRadius": 0.1}
    default = sdfwb.sample(columns, "near", 4000, seed=3)
    assert not np.array_equal(default["position"], result["position"])
    # vectors as sequences, bools as bools; mistakes are ValueErrors naming the parameter
    torus = os.path.join(PARAMS, "iq_torus_map.glsl")
    moved = sdfwb.sample(torus, "surface", 2000, seed=1, params={"offset": (0.0, 0.15, 0.0), "capped": True})
    assert moved["parameters"]["capped"] is True and moved["parameters"]["offset"] == pytest.approx((0.0, 0.15, 0.0))
    finite = moved["distance"][np.isfinite(moved["distance"])]
    assert finite.size > 1000 and np.all(moved["position"][np.isfinite(moved["distance"]), 0] <= 1e-3)  # capped at x <= 0
    with pytest.raises(ValueError, match=r"parameter 'radius' is not declared \(declared: majorRadius"):
        sdfwb.sample(torus, "rand", 10, params={"radius": 0.3})
    with pytest.raises(ValueError, match=r"'offset' is a vec3: give 1 or 3 numbers, not 2"):
        sdfwb.sample(torus, "rand", 10, params={"offset": [1, 2]})
    with pytest.raises(TypeError, match=r"params\['majorRadius'\]"):
        sdfwb.sample(torus, "rand", 10, params={"majorRadius": "big"})


def test_audit_with_params_sees_the_instance():
    blend = os.path.join(PARAMS, "st_blend_itime.glsl")
    safe = sdfwb.audit(blend, samples=4000, params={"stretch": 0.8})
    steep = sdfwb.audit(blend, samples=4000, params={"stretch": 2.0})
    assert safe["verdict"] in ("exact", "conservative")
    assert steep["verdict"] == "non-conservative" and steep["lipschitz"] == pytest.approx(2.0, abs=0.1)
    assert steep["parameters"] == {"blend": pytest.approx(0.1), "stretch": 2.0}


@pytest.mark.parametrize("extension", ["ply", "obj", "stl", "glb"])
def test_meshes_open_in_meshio_and_open3d_watertight(extension):
    import open3d  # python3-open3d, installed by scripts/bootstrap: a missing one fails, never skips
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "torus." + extension)
        env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        out = subprocess.run([BINARY, "--batch", "mesh", "--sdf", os.path.join(PARAMS, "iq_torus_map.glsl"), "--param",
                              "minorRadius=0.15", "--resolution", "48", "--output", path, "--json", "--quiet"],
                             check=True, env=env, capture_output=True, text=True).stdout
        report = json.loads(out)
        assert report["watertight"] and report["boundary_edges"] == 0 and report["non_manifold_edges"] == 0
        assert report["hausdorff"] < 0.01 and report["error_points"] > 100000
        assert report["parameters"]["minorRadius"] == pytest.approx(0.15)
        mesh = open3d.io.read_triangle_mesh(path)
        if extension == "stl":  # STL keeps each triangle's corners apart
            mesh = mesh.merge_close_vertices(1e-7)
        assert len(mesh.triangles) == report["triangles"]
        assert len(mesh.vertices) == report["vertices"]
        assert mesh.is_edge_manifold() and mesh.is_watertight() and mesh.is_orientable()
        if extension != "glb":  # meshio has no glTF reader
            import meshio
            m = meshio.read(path)
            assert len(m.cells_dict["triangle"]) == report["triangles"]
            # the minor radius is the tube's: every vertex lies on the surface of that torus
            p = m.points
            q = np.stack([np.hypot(p[:, 0], p[:, 2]) - 0.6, p[:, 1]], axis=1)
            assert np.max(np.abs(np.linalg.norm(q, axis=1) - 0.15)) < 1e-4  # vertices are projected onto it


def test_evaluate_mesh_gives_the_clis_figures():
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "torus.obj")
        env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        subprocess.run([BINARY, "--batch", "mesh", "--sdf", "torus", "--resolution", "40", "--error-samples", "0", "--output", path,
                        "--quiet"], check=True, env=env)
        cli = json.loads(subprocess.run([BINARY, "--batch", "eval", "--mesh", path, "--sdf", "torus", "--points", "20000",
                                         "--json", "--quiet"], check=True, env=env, capture_output=True, text=True).stdout)
        result = sdfwb.evaluate_mesh(path, "torus", points=20000)
        for key in ("chamfer_l1", "chamfer_l2", "fscore", "precision", "recall", "normal_consistency", "hausdorff", "iou",
                    "mesh_points", "surface_points", "triangles", "closed"):
            assert result[key] == cli[key], key
        assert result["fscore"] > 0.99 and result["iou"] > 0.97 and "not squared" in result["conventions"]
        with pytest.raises(ValueError, match="no such file"):
            sdfwb.evaluate_mesh(os.path.join(folder, "missing.ply"), "torus")


def test_the_edge_measures_tell_sharp_edges_from_cut_ones():
    """#33 point 2: the same box through sdfwb's dual contouring and scikit-image's marching cubes (the tool ML
    code uses), at the same resolution, graded near the creases. Marching cubes cuts every edge and corner by
    up to a cell; dual contouring keeps them, so its edge F-score is near 1 and marching cubes' far below, while
    over the whole surface both are close (the creases' share is small). The CLI and Python agree, and a
    smooth shape has no edge measures."""
    import meshio
    from skimage import measure
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    R = 64
    axis = np.linspace(-1.0, 1.0, R + 1, dtype=np.float32)
    z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")
    q = np.stack([np.abs(x) - 0.8, np.abs(y) - 0.5, np.abs(z) - 0.6])  # the dataset's Box
    field = np.linalg.norm(np.maximum(q, 0), axis=0) + np.minimum(q.max(axis=0), 0)
    vertices, faces, _, _ = measure.marching_cubes(field, 0.0, spacing=(2.0 / R,) * 3)
    with tempfile.TemporaryDirectory() as folder:
        mc = os.path.join(folder, "mc.ply")
        meshio.write(mc, meshio.Mesh(vertices[:, ::-1] - 1.0, [("triangle", faces)]), binary=True)
        dc = os.path.join(folder, "dc.ply")
        ours = sdfwb.mesh("box", resolution=R)
        meshio.write(dc, meshio.Mesh(ours["vertices"], [("triangle", ours["faces"].astype(np.int64))]), binary=True)
        graded = {name: sdfwb.evaluate_mesh(path, "box", tau=0.002, points=50000) for name, path in (("dc", dc), ("mc", mc))}
        for name, e in graded.items():
            assert e["edge_radius"] == pytest.approx(0.02) and e["edge_angle"] == pytest.approx(30.0), name
            assert e["edges"]["surface_points"] > 1000 and e["edges"]["mesh_points"] > 1000, name
        assert graded["dc"]["edges"]["fscore"] > 0.99
        assert graded["mc"]["edges"]["fscore"] < 0.7
        assert graded["mc"]["fscore"] > 0.9, "over the whole surface marching cubes looks fine"
        assert graded["mc"]["edges"]["chamfer_l1"] > 10 * graded["dc"]["edges"]["chamfer_l1"]
        cli = json.loads(subprocess.run([BINARY, "--batch", "eval", "--mesh", mc, "--sdf", "box", "--points", "50000",
                                         "--tau", "0.002", "--json", "--quiet"], check=True, env=env, capture_output=True,
                                        text=True).stdout)
        assert cli["edges"] == graded["mc"]["edges"]
        assert sdfwb.evaluate_mesh(dc, "box", edge_radius=0.0)["edges"] is None
        assert sdfwb.evaluate_mesh(dc, "sphere", points=20000)["edges"] is None, "a sphere has no crease"
        with pytest.raises(ValueError, match="^edge_angle=: must be between"):
            sdfwb.evaluate_mesh(dc, "box", edge_angle=200.0)
        bad = subprocess.run([BINARY, "--batch", "eval", "--mesh", dc, "--sdf", "box", "--edge-radius", "-1"], env=env,
                             capture_output=True, text=True)
        assert bad.returncode == 2 and "--edge-radius" in bad.stderr, bad.stderr


def test_mesh_and_eval_name_bad_arguments():
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    with tempfile.TemporaryDirectory() as folder:
        cases = [
            (["mesh", "--sdf", "torus", "--output", os.path.join(folder, "t.xyz")], "unsupported mesh type"),
            (["mesh", "--sdf", "torus", "--output", os.path.join(folder, "t.ply"), "--bounds", "1,1,1,0,0,0"], "--bounds"),
            (["mesh", "--sdf", "torus", "--output", os.path.join(folder, "t.ply"), "--resolution", "1"], "--resolution"),
            (["mesh", "--sdf", "torus", "--output", os.path.join(folder, "t.ply"), "--refine", "5"], "--refine"),
            (["mesh", "--sdf", "torus", "--output", os.path.join(folder, "no", "t.ply")], "does not exist"),
            (["eval", "--sdf", "torus", "--mesh", os.path.join(folder, "missing.ply")], "no such file"),
        ]
        for arguments, expected in cases:
            result = subprocess.run([BINARY, "--batch", *arguments], env=env, capture_output=True, text=True)
            assert result.returncode == 2, (arguments, result.stderr)
            assert expected in result.stderr, (arguments, result.stderr)
        assert os.listdir(folder) == []
        with pytest.raises(ValueError, match="^refine=: must be 0..4"):
            sdfwb.mesh("torus", resolution=16, refine=-1)
        # a file that is not a mesh: named, exit 1, nothing written
        bad = os.path.join(folder, "bad.ply")
        with open(bad, "w") as f:
            f.write("ply\nthis is not a mesh\n")
        result = subprocess.run([BINARY, "--batch", "eval", "--sdf", "torus", "--mesh", bad], env=env, capture_output=True, text=True)
        assert result.returncode == 1 and "bad.ply" in result.stderr, result.stderr


def test_mesh_returns_arrays_over_its_own_memory_and_the_clis_mesh():
    result = sdfwb.mesh("box", resolution=48, error_samples=20000)
    v, f = result["vertices"], result["faces"]
    assert v.dtype == np.float32 and v.shape[1] == 3 and f.dtype == np.uint32 and f.shape[1] == 3
    assert not v.flags.owndata and v.base is not None and v.flags.c_contiguous  # a view of the extraction's buffer
    assert not f.flags.owndata and f.base is not None
    report = result["report"]
    assert report["vertices"] == len(v) and report["triangles"] == len(f) and report["watertight"]
    assert report["hausdorff"] < 1e-3
    # the dataset box's corners (0.8, 0.5, 0.6) are vertices
    for corner in np.array(np.meshgrid([-0.8, 0.8], [-0.5, 0.5], [-0.6, 0.6])).T.reshape(-1, 3):
        assert np.min(np.linalg.norm(v - corner, axis=1)) < 1e-3, corner
    # the same mesh as the CLI writes
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "box.ply")
        env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        subprocess.run([BINARY, "--batch", "mesh", "--sdf", "box", "--resolution", "48", "--error-samples", "0", "--output", path,
                        "--quiet"], check=True, env=env)
        import meshio
        written = meshio.read(path)
        assert np.array_equal(written.points.astype(np.float32), v)
        assert np.array_equal(written.cells_dict["triangle"], f)
    # The upper half: the bounds cut the sphere, and the mesh is closed by a flat cap half a cell
    # (1/64) below z = 0.
    half = sdfwb.mesh("sphere", resolution=32, bounds=(-1, -1, 0, 1, 1, 1))
    z = half["vertices"][:, 2]
    assert np.all(z >= -1 / 64 - 1e-6) and half["report"]["boundary_edges"] == 0 and half["report"]["watertight"]
    assert half["report"]["bounds_cut_points"] > 0
    assert np.count_nonzero(np.abs(z + 1 / 64) < 1e-6) > 50, "the cap is flat, on the cut"
    with pytest.raises(ValueError, match="^resolution=: must be 2..2048"):
        sdfwb.mesh("sphere", resolution=1)
