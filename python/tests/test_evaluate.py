"""Points in, values out: sdfwb.evaluate against the samplers, torch tensors without copies, and the
SampleStream's batches (deterministic, disjoint across workers and epochs) through a real DataLoader."""
import os
import subprocess
import sys

import numpy as np
import pytest
import torch

import sdfwb
from sdfwb.torch import SampleStream, loader

# Shadertoy style (IQ's box and sphere, a `map` returning vec2), not written for sdfwb.
SHADERTOY_MAP = """
float sdBox( vec3 p, vec3 b ) { vec3 q = abs(p) - b; return length(max(q,0.0)) + min(max(q.x,max(q.y,q.z)),0.0); }
vec2 map( in vec3 pos ) {
    float d = sdBox( pos - vec3(0.2,0.0,0.0), vec3(0.3) );
    d = min( d, length(pos + vec3(0.3,0.0,0.0)) - 0.35 );
    return vec2( d, 1.0 );
}
"""


@pytest.mark.parametrize("sdf,pattern,entry", [("Sphere", "rand", ""), ("Mandelbulb", "near", ""),
                                               ("Torus", "surface", ""), (SHADERTOY_MAP, "near", "map")])
def test_evaluate_is_bit_equal_to_the_samplers(sdf, pattern, entry):
    rows = sdfwb.sample(sdf, pattern, 20000, seed=5, entry=entry)
    values = sdfwb.evaluate(sdf, rows["position"], entry=entry)
    assert np.array_equal(values["distance"], rows["distance"], equal_nan=True)
    assert np.array_equal(values["gradient"], rows["gradient"], equal_nan=True)
    field_only = sdfwb.evaluate(sdf, rows["position"], gradient=False, entry=entry)
    assert field_only["gradient"] is None
    assert np.array_equal(field_only["distance"], rows["distance"], equal_nan=True)


# A scene built around its own camera, as pasted from Shadertoy: the ball at z = 5 has no surface
# in [-1, 1]^3 until it is framed.
FAR_BALL = """
float map(vec3 p) { return length(p - vec3(0.0, 0.0, 5.0)) - 1.0; }
void mainImage(out vec4 c, in vec2 u) {
    float t = 0.0;
    for (int i = 0; i < 64; i++) { float d = map(vec3(0.0, 0.0, 1.0) * t); if (d < 0.001) break; t += d; }
    c = vec4(t);
}
"""


def test_a_glsl_field_outside_the_unit_box_is_framed():
    plain = sdfwb.sample(FAR_BALL, "rand", 2000, seed=1)
    assert (plain["distance"] > 0).all()
    framed = sdfwb.sample(FAR_BALL, "rand", 2000, seed=1, normalize="-2,-2,3,2,2,7")
    point = framed["position"].astype(np.float64) * 2.0 + [0.0, 0.0, 5.0]  # centre (0, 0, 5), scale 2
    exact = (np.linalg.norm(point - [0.0, 0.0, 5.0], axis=1) - 1.0) / 2.0
    assert np.abs(framed["distance"] - exact).max() < 1e-5
    assert (framed["distance"] < 0).any()
    # Framed by its surface's box: the unit box's centre is near the ball's.
    found = sdfwb.evaluate(FAR_BALL, np.zeros((1, 3), np.float32), normalize="unit-cube")
    assert found["distance"][0] < -0.5
    with pytest.raises(ValueError, match="normalize"):
        sdfwb.sample(FAR_BALL, "rand", 10, normalize="1,2,3")


# An unsigned field (never negative), as pasted shaders march thin shells and lines.
SHELL = "float sdf(vec3 p) { return abs(length(p) - 0.5); }"


def test_an_unsigned_field_gets_a_surface_with_level():
    points = np.random.default_rng(3).uniform(-1.0, 1.0, (4000, 3)).astype(np.float32)
    shell = np.abs(np.linalg.norm(points.astype(np.float64), axis=1) - 0.5)
    plain = sdfwb.evaluate(SHELL, points, gradient=False)
    assert (plain["distance"] >= 0).all()
    levelled = sdfwb.evaluate(SHELL, points, gradient=False, level=0.1)
    assert np.abs(levelled["distance"] - (shell - 0.1)).max() < 1e-6
    assert (levelled["distance"] < 0).sum() > 250  # inside the shell of half thickness 0.1: 8 % of the box
    rows = sdfwb.sample(SHELL, "surface", 500, level=0.1)
    assert rows["bad_rows"] == 0
    radius = np.linalg.norm(rows["position"].astype(np.float64), axis=1)
    assert np.minimum(np.abs(radius - 0.4), np.abs(radius - 0.6)).max() < 1e-4
    with pytest.raises(ValueError, match="level"):
        sdfwb.evaluate(SHELL, points, level=float("nan"))


def test_evaluate_matches_the_exact_field_in_float64():
    # The Shadertoy map above, evaluated here in float64 NumPy at 100,000 points of the cube: values
    # to float32 rounding, and the gradients against the same central differences (step 1e-3) in
    # float64, so what is left is float32's cancellation in the taps.
    points = np.random.default_rng(7).uniform(-1.0, 1.0, (100000, 3)).astype(np.float32)
    p = points.astype(np.float64)

    def field(q):
        box = np.abs(q - [0.2, 0.0, 0.0]) - 0.3
        outside = np.linalg.norm(np.maximum(box, 0.0), axis=1) + np.minimum(box.max(axis=1), 0.0)
        return np.minimum(outside, np.linalg.norm(q + [0.3, 0.0, 0.0], axis=1) - 0.35)

    got = sdfwb.evaluate(SHADERTOY_MAP, points, entry="map")
    exact = field(p)
    assert np.max(np.abs(got["distance"] - exact)) < 1e-6  # measured 1.4e-7
    h = 1e-3
    gradient = np.stack([(field(p + h * e) - field(p - h * e)) / (2 * h) for e in np.eye(3)], axis=1)
    error = np.linalg.norm(got["gradient"] - gradient, axis=1)
    # measured: median 1.9e-5, 99th percentile 7.5e-5 (float32 differences of the 6 taps)
    assert np.median(error) < 1e-4 and np.quantile(error, 0.99) < 5e-4, (np.median(error), np.quantile(error, 0.99))


def test_evaluate_takes_parameters_and_time():
    points = np.array([[0.0, 0.0, 0.0], [0.5, 0.0, 0.0]], np.float32)
    source = "uniform float radius = 0.25;\nfloat sdf(vec3 p, float t) { return length(p) - radius - 0.1 * t; }"
    got = sdfwb.evaluate(source, points, params={"radius": 0.4}, time=1.0, gradient=False)["distance"]
    np.testing.assert_allclose(got, [-0.5, 0.0], atol=1e-6)


def test_evaluate_reads_strided_and_float64_input_once_converted():
    base = (np.random.default_rng(1).random((1000, 6)) * 2 - 1)
    strided = base[:, ::2]  # float64, not contiguous
    expected = sdfwb.evaluate("Sphere", np.ascontiguousarray(strided, np.float32))["distance"]
    assert np.array_equal(sdfwb.evaluate("Sphere", strided)["distance"], expected)


def test_evaluate_refuses_bad_input_by_name():
    with pytest.raises(ValueError, match=r"points must have shape \(N, 3\), not \(4, 2\)"):
        sdfwb.evaluate("Sphere", np.zeros((4, 2), np.float32))
    with pytest.raises(ValueError, match="error"):
        sdfwb.evaluate("float sdf(vec3 p) { return length(p) - ; }", np.zeros((4, 3), np.float32))
    assert sdfwb.evaluate("Sphere", np.zeros((0, 3), np.float32))["distance"].shape == (0,)


def test_torch_tensors_in_and_out_share_memory():
    points = torch.rand(5000, 3) * 2 - 1
    result = sdfwb.evaluate("Torus", points)
    assert isinstance(result["distance"], torch.Tensor) and isinstance(result["gradient"], torch.Tensor)
    assert result["distance"].shape == (5000,) and result["gradient"].shape == (5000, 3)
    expected = sdfwb.evaluate("Torus", points.numpy())
    assert np.array_equal(result["distance"].numpy(), expected["distance"])
    # from_numpy: the tensor is a view of the native result array, not a copy of it
    view = result["distance"].numpy()
    view[0] = 123.0
    assert result["distance"][0].item() == 123.0
    with pytest.raises(ValueError, match="CPU tensor"):
        sdfwb.evaluate("Torus", points.to("meta"))


def test_import_sdfwb_imports_neither_torch_nor_dask():
    code = "import sys, sdfwb; assert 'torch' not in sys.modules and 'dask' not in sys.modules, sorted(sys.modules)"
    subprocess.run([sys.executable, "-c", code], check=True, env=dict(os.environ))


def stream_rows(stream, epochs, workers):
    out = {}
    for epoch in range(epochs):
        stream.set_epoch(epoch)
        for batch in (loader(stream, num_workers=workers) if workers else stream):
            assert batch["first_index"] not in out
            out[batch["first_index"]] = (epoch, batch["position"].numpy().copy(), batch["distance"].numpy().copy())
    return out


def test_sample_stream_is_deterministic_and_disjoint_across_workers_and_epochs():
    sdfwb.sample("Sphere", "rand", 10)  # this process has used GL before the loader starts its workers
    stream = SampleStream("Sphere", "near", batch_size=512, batches_per_epoch=6, seed=11)
    two_workers = stream_rows(stream, epochs=2, workers=2)
    in_process = stream_rows(stream, epochs=2, workers=0)
    assert sorted(two_workers) == [512 * g for g in range(12)]  # every batch once, epochs after each other
    for first, (epoch, positions, distances) in two_workers.items():
        assert epoch == first // 512 // 6
        assert np.array_equal(positions, in_process[first][1]) and np.array_equal(distances, in_process[first][2])
        expected = sdfwb.sample("Sphere", "near", 512, seed=11, first_index=first)
        assert np.array_equal(positions, expected["position"])
    rows = np.concatenate([p for _, p, _ in two_workers.values()])
    assert len(np.unique(rows, axis=0)) == len(rows)  # no row repeats across workers and epochs
    other_seed = SampleStream("Sphere", "near", batch_size=512, batches_per_epoch=6, seed=12)
    assert not np.array_equal(next(iter(other_seed))["position"].numpy(), two_workers[0][1])


def test_sample_stream_splits_batches_across_ranks():
    ranks = [SampleStream("Sphere", "rand", batch_size=64, batches_per_epoch=8, rank=r, world_size=2) for r in range(2)]
    firsts = [[b["first_index"] for b in r] for r in ranks]
    assert sorted(firsts[0] + firsts[1]) == [64 * g for g in range(8)] and not set(firsts[0]) & set(firsts[1])


def test_a_forked_worker_after_gl_gets_a_clear_error_not_a_hang():
    sdfwb.sample("Sphere", "rand", 10)
    stream = SampleStream("Sphere", "rand", batch_size=64, batches_per_epoch=2)
    fork_loader = torch.utils.data.DataLoader(stream, batch_size=None, num_workers=1, multiprocessing_context="fork",
                                              timeout=60)
    with pytest.raises(RuntimeError, match="spawn"):
        list(fork_loader)


def test_command_line_form_reads_and_writes_npy(tmp_path):
    points = (np.random.default_rng(2).random((3000, 3), dtype=np.float32) * 2 - 1)
    np.save(tmp_path / "points.npy", points)
    run = [sys.executable, "-m", "sdfwb", "evaluate", "--sdf", "Torus", "--points", str(tmp_path / "points.npy")]
    subprocess.run(run + ["--output", str(tmp_path / "out.npz")], check=True, capture_output=True)
    expected = sdfwb.evaluate("Torus", points)
    with np.load(tmp_path / "out.npz") as data:
        assert np.array_equal(data["distance"], expected["distance"]) and np.array_equal(data["gradient"], expected["gradient"])
    subprocess.run(run + ["--output", str(tmp_path / "d.npy")], check=True, capture_output=True)
    assert np.array_equal(np.load(tmp_path / "d.npy"), expected["distance"])
    np.save(tmp_path / "flat.npy", np.zeros((5, 2)))
    bad = subprocess.run(run[:-1] + [str(tmp_path / "flat.npy"), "--output", str(tmp_path / "bad.npz")],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "flat.npy" in bad.stderr and "(N, 3)" in bad.stderr
    broken = subprocess.run([sys.executable, "-m", "sdfwb", "evaluate", "--sdf", "float sdf(vec3 p) { return x; }",
                             "--points", str(tmp_path / "points.npy"), "--output", str(tmp_path / "bad.npz")],
                            capture_output=True, text=True)
    assert broken.returncode == 2 and "1:" in broken.stderr and "undeclared" in broken.stderr
    assert not (tmp_path / "bad.npz").exists() and not list(tmp_path.glob(".*"))
