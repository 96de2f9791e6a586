"""Recipes: near's mixture of widths (its histogram), truncation, ratios, occupancy, float16, and the
DeepSDF / Occupancy Networks layouts with their metadata."""
import math
import os
import subprocess
import warnings

import numpy as np
import pytest

import sdfwb
from sdfwb import recipes

BINARY = os.environ["SDFWB_BINARY"]


def mixture_cdf(x, components):
    return sum(w * 0.5 * (1.0 + math.erf(x / (s * math.sqrt(2.0)))) for s, w in components)


def test_near_mixture_follows_the_mixture_distribution():
    # On the dataset sphere (an exact field) the distance is the offset itself (to the surface tolerance).
    rows = sdfwb.sample("Sphere", "near", 200000, seed=2, near_widths="0.005:0.8,0.05:0.2")
    d = np.sort(rows["distance"])
    for x in (-0.06, -0.01, -0.003, 0.0, 0.002, 0.008, 0.03, 0.1):
        empirical = np.searchsorted(d, x) / len(d)
        assert abs(empirical - mixture_cdf(x, [(0.005, 0.8), (0.05, 0.2)])) < 0.006, x
    plain = sdfwb.sample("Sphere", "near", 200000, seed=2)["distance"]
    assert abs(np.std(plain) - 0.005) < 1e-4  # the default width is unchanged
    assert abs(np.std(d) - math.sqrt(0.8 * 0.005**2 + 0.2 * 0.05**2)) < 1e-3


def test_near_truncation_redraws_instead_of_clamping():
    d = sdfwb.sample("Sphere", "near", 100000, seed=4, near_widths="0.05", near_truncate=1.0)["distance"]
    assert np.abs(d).max() <= 0.05 + 2e-5
    assert np.mean(np.abs(d) > 0.0495) < 0.01  # no spike at the bounds
    truncated_std = math.sqrt(1.0 - 2.0 * math.exp(-0.5) / math.sqrt(2.0 * math.pi) / math.erf(1.0 / math.sqrt(2.0)))
    assert abs(np.std(d) - 0.05 * truncated_std) < 5e-4


def test_cli_takes_widths_and_names_bad_ones(tmp_path):
    out = tmp_path / "near.npz"
    subprocess.run([BINARY, "--batch", "sample", "--sdf", "Sphere", "-p", "near", "-n", "1000", "-o", str(out),
                    "--near-widths", "0.005:0.8,0.05:0.2", "--quiet"], check=True)
    assert sdfwb.load(str(out))["metadata"]["pattern"] == "near 0.005:0.8,0.05:0.2"
    api = sdfwb.sample("Sphere", "near", 1000, near_widths="0.005:0.8,0.05:0.2")
    assert np.array_equal(sdfwb.load(str(out))["distance"], api["distance"])
    for bad, message in [("0.1:x", "'0.1:x' is not WIDTH"), ("-1", "must be positive"), ("1,1,1,1,1", "at most 4")]:
        run = subprocess.run([BINARY, "--batch", "sample", "--sdf", "Sphere", "-p", "near", "-n", "10", "-o",
                              str(tmp_path / "bad.npz"), "--near-widths", bad], capture_output=True, text=True)
        assert run.returncode == 2 and message in run.stderr, run.stderr
        assert not (tmp_path / "bad.npz").exists()
    with pytest.raises(ValueError, match="only the near pattern"):
        sdfwb.sample("Sphere", "rand", 10, near_widths="0.1")


def test_mix_follows_its_ratios_with_occupancy_and_float16():
    rows = recipes.mix("Torus", {"rand": 1, "near": 4}, 10001, seed=3, occupancy=True, dtype=np.float16)
    assert np.bincount(rows["part"]).tolist() == [2000, 8001]
    assert rows["position"].dtype == np.float16 and rows["distance"].dtype == np.float16
    reference = recipes.mix("Torus", {"rand": 1, "near": 4}, 10001, seed=3)
    assert np.array_equal(rows["occupancy"], reference["distance"] < 0)
    # float16 round trip: relative error at most 2^-11 for normal numbers, absolute 2^-25 below them
    for key in ("position", "distance", "gradient"):
        exact, stored = reference[key], rows[key].astype(np.float32)
        assert np.all(np.abs(stored - exact) <= np.maximum(np.abs(exact) * 2.0**-11, 2.0**-25)), key
    near_rows = reference["position"][reference["part"] == 1]
    assert np.abs(reference["distance"][reference["part"] == 1]).max() < 0.05  # near rows hug the surface
    assert np.abs(reference["position"][reference["part"] == 0]).max() <= 1.0 and len(near_rows) == 8001
    meta = reference["metadata"]
    assert meta["seed"] == 3 and [p["count"] for p in meta["parts"]] == [2000, 8001] and meta["bounds"] == [-1, -1, -1, 1, 1, 1]


def test_a_surface_leaving_the_box_warns():
    big = "float sdf(vec3 p) { return length(p) - 1.2; }"
    with pytest.warns(RuntimeWarning, match="surface leaves the sampling box"):
        recipes.mix(big, {"rand": 1}, 100)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        recipes.mix("Sphere", {"rand": 1}, 100)


def test_deepsdf_layout(tmp_path):
    path = tmp_path / "torus.npz"
    meta = recipes.deepsdf("Torus", str(path), n=50000, seed=1)
    with np.load(path) as data:
        pos, neg = data["pos"], data["neg"]
        assert set(data.files) == {"pos", "neg", "sdfwb_metadata"}
    assert pos.dtype == np.float32 and pos.shape[1] == 4 and neg.shape[1] == 4
    assert len(pos) + len(neg) == 50000 - meta["rows_dropped"] and meta["rows_dropped"] < 50
    assert np.all(pos[:, 3] > 0) and np.all(neg[:, 3] <= 0)
    values = sdfwb.evaluate("Torus", np.ascontiguousarray(pos[:, :3]), gradient=False)["distance"]
    assert np.array_equal(values, pos[:, 3])
    assert recipes.metadata_of(str(path))["recipe"] == "deepsdf" and "Park et al." in meta["description"]
    near = np.abs(np.concatenate([pos, neg])[:, 3])
    assert 0.85 < np.mean(near < 0.2) <= 1.0  # 47/50 near the surface


def test_occnet_layout(tmp_path):
    path = tmp_path / "points.npz"
    meta = recipes.occnet("Torus", str(path), n=20000, seed=1)
    with np.load(path) as data:
        points, bits, loc, scale = data["points"], data["occupancies"], data["loc"], float(data["scale"])
    assert points.dtype == np.float16 and points.shape == (20000, 3) and bits.dtype == np.uint8 and bits.shape == (2500,)
    assert np.abs(points).max() <= 0.55 and np.abs(points).max() > 0.54
    inside = np.unpackbits(bits)[:20000].astype(bool)
    world = points.astype(np.float32) * np.float32(scale) + loc
    assert np.array_equal(inside, sdfwb.evaluate("Torus", world, gradient=False)["distance"] < 0)
    assert meta["normalisation"] == {"loc": [0.0, 0.0, 0.0], "scale": 2.0} and "Mescheder" in meta["description"]
