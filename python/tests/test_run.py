"""Many shapes per run: `sdfwb --batch run MANIFEST` on SDF files in public styles (IQ, Shadertoy, hg_sdf, G3D),
killed midway and resumed, with broken and hanging items, sliced by rank (the Slurm example, task by task), and
the same manifest on a Dask LocalCluster with 2 workers. Outputs are compared byte for byte."""
import filecmp
import json
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

BINARY = os.environ["SDFWB_BINARY"]
REPO = Path(__file__).resolve().parents[2]
FOREIGN = REPO / "tests" / "foreign"

BROKEN = "float sdf(vec3 p) {\n    return length(p) - 0.5  // a missing semicolon\n}\n"
# A field that takes minutes per million points on llvmpipe: the stand-in for a shader that never ends.
SLOW = """float sdf(vec3 p) {
    float d = length(p) - 0.5;
    for (int i = 0; i < 60000; ++i) d += 1e-9 * sin(d + float(i));
    return d;
}
"""


def run(*arguments, check=None, **options):
    done = subprocess.run([BINARY, "--batch", *arguments], capture_output=True, text=True, **options)
    if check is not None:
        assert done.returncode == check, done.stderr + done.stdout
    return done


def items(folder):
    """Six items: four public-style SDF files (one with a parameter), a dataset name and a DeepSDF recipe."""
    return [
        {"sdf": str(FOREIGN / "01_iq_primitives.glsl"), "pattern": "near", "n": 30000, "seed": 1, "output": "out/iq.npz"},
        {"sdf": str(FOREIGN / "02_st_bounce_itime.glsl"), "pattern": "rand", "n": 30000, "seed": 2, "time": 0.5,
         "output": "out/bounce.bin"},
        {"sdf": str(FOREIGN / "05_hg_colonnade.glsl"), "pattern": "surface", "n": 20000, "seed": 3, "output": "out/hg.ply"},
        {"sdf": str(FOREIGN / "13_g3d_snake_truncated.glsl"), "pattern": "near", "n": 30000, "seed": 4,
         "near_widths": "0.01:0.7,0.05:0.3", "output": "out/snake.npz"},
        {"sdf": "torus", "pattern": "near", "n": 40000, "seed": 5, "output": "out/torus.npz"},
        {"recipe": "deepsdf", "sdf": "Sphere", "n": 20000, "seed": 6, "output": "out/sphere_deepsdf.npz"},
    ]


def write_jsonl(path, rows):
    path.write_text("# sdf, pattern or recipe, n, seed, output\n" + "".join(json.dumps(r) + "\n" for r in rows))
    return path


def status_records(path):
    return [json.loads(line) for line in Path(path).read_text().splitlines() if line.strip()]


def outputs(folder):
    return sorted(p.relative_to(folder).as_posix() for p in (folder / "out").rglob("*") if p.is_file())


def same_files(a, b):
    names = outputs(a)
    assert names == outputs(b)
    for name in names:
        assert filecmp.cmp(a / name, b / name, shallow=False), name
    return names


def test_a_manifest_writes_what_single_commands_write_and_a_second_run_skips_it(tmp_path):
    manifest = write_jsonl(tmp_path / "shapes.jsonl", items(tmp_path))
    done = run("run", str(manifest), "--json", check=0)
    report = json.loads(done.stdout)
    assert (report["items"], report["done"], report["failed"], report["skipped"]) == (6, 6, 0, 0)
    assert report["bytes_written"] == sum((tmp_path / "out" / n).stat().st_size for n in os.listdir(tmp_path / "out"))
    assert report["shapes_per_hour"] > 0
    # Each sample item equals the plain command with the same options, byte for byte.
    run("sample", "--sdf", str(FOREIGN / "02_st_bounce_itime.glsl"), "--pattern", "rand", "-n", "30000", "--seed", "2",
        "--time", "0.5", "--output", str(tmp_path / "single.bin"), "--quiet", check=0)
    assert filecmp.cmp(tmp_path / "single.bin", tmp_path / "out" / "bounce.bin", shallow=False)
    with np.load(tmp_path / "out" / "sphere_deepsdf.npz") as data:
        assert data["pos"].shape[1] == 4 and len(data["pos"]) + len(data["neg"]) == 20000
    # --item picks items; a number past the last is named.
    late = run("run", str(manifest), "--item", "6")
    assert late.returncode == 2 and "--item: 6 is past the manifest's last item (5)" in late.stderr
    picked = json.loads(run("run", str(manifest), "--item", "4,1", "--list", "--json", check=0).stdout)
    assert [r["index"] for r in picked["results"]] == [1, 4]
    # The second run does nothing and says so.
    again = json.loads(run("run", str(manifest), "--json", check=0).stdout)
    assert (again["done"], again["skipped"]) == (0, 6)
    # A changed line (another seed) runs again; the others stay done.
    rows = items(tmp_path)
    rows[4]["seed"] = 50
    write_jsonl(manifest, rows)
    again = json.loads(run("run", str(manifest), "--json", check=0).stdout)
    assert (again["done"], again["skipped"]) == (1, 5)
    assert [r["index"] for r in again["results"] if r["status"] == "done"] == [4]
    # An output deleted by hand is made again.
    (tmp_path / "out" / "iq.npz").unlink()
    again = json.loads(run("run", str(manifest), "--json", check=0).stdout)
    assert (again["done"], again["skipped"]) == (1, 5) and (tmp_path / "out" / "iq.npz").exists()


def test_csv_and_json_lines_manifests_write_the_same_files(tmp_path):
    csv_folder, jsonl_folder = tmp_path / "csv", tmp_path / "jsonl"
    csv_folder.mkdir()
    jsonl_folder.mkdir()
    hg = REPO / "tests" / "params" / "hg_polar_columns.glsl"  # hg_sdf style, with an int and a float parameter
    (csv_folder / "shapes.csv").write_text(
        "sdf,pattern,n,seed,params,output,near_widths\n"
        f"{hg},near,20000,7,columns=9;ringRadius=0.5,hg.npz,\"0.005:0.8,0.05:0.2\"\n"
        "# a comment line\n"
        "\n"
        "Sphere,rand,10000,8,,sphere.ply,\n")
    write_jsonl(jsonl_folder / "shapes.jsonl", [
        {"sdf": str(hg), "pattern": "near", "n": 20000, "seed": 7, "params": {"columns": 9, "ringRadius": 0.5}, "output": "hg.npz",
         "near_widths": "0.005:0.8,0.05:0.2"},
        {"sdf": "Sphere", "pattern": "rand", "n": 10000, "seed": 8, "output": "sphere.ply"}])
    run("run", str(csv_folder / "shapes.csv"), "--quiet", check=0)
    run("run", str(jsonl_folder / "shapes.jsonl"), "--quiet", check=0)
    for output in ("hg.npz", "sphere.ply"):
        assert filecmp.cmp(csv_folder / output, jsonl_folder / output, shallow=False), output
    run("sample", "--sdf", str(hg), "--pattern", "near", "-n", "20000", "--seed", "7", "--param", "columns=9",
        "--param", "ringRadius=0.5", "--near-widths", "0.005:0.8,0.05:0.2", "--output", str(tmp_path / "hg.npz"),
        "--quiet", check=0)
    assert filecmp.cmp(tmp_path / "hg.npz", csv_folder / "hg.npz", shallow=False)
    listed = json.loads(run("run", str(csv_folder / "shapes.csv"), "--list", "--json", check=0).stdout)
    assert [r["line"] for r in listed["results"]] == [2, 5] and all(r["status"] == "done" for r in listed["results"])


def test_a_killed_run_resumes_and_ends_with_the_files_of_an_uninterrupted_run(tmp_path):
    whole, killed = tmp_path / "whole", tmp_path / "killed"
    for folder in (whole, killed):
        folder.mkdir()
        write_jsonl(folder / "shapes.jsonl", items(folder))
    run("run", str(whole / "shapes.jsonl"), "--quiet", check=0)

    runner = subprocess.Popen([BINARY, "--batch", "run", str(killed / "shapes.jsonl"), "--quiet"],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    status = killed / "shapes.jsonl.status.jsonl"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and runner.poll() is None:
        if status.exists() and sum(r["status"] == "done" for r in status_records(status)) >= 2:
            break
        time.sleep(0.02)  # polling the status file for the state we wait on, not a fixed delay
    assert runner.poll() is None, "the run ended before it could be killed"
    runner.send_signal(signal.SIGKILL)
    runner.wait()
    before = status_records(status)
    assert 2 <= len(before) < 6

    resumed = json.loads(run("run", str(killed / "shapes.jsonl"), "--json", check=0).stdout)
    assert resumed["skipped"] == len(before) and resumed["done"] == 6 - len(before)
    assert same_files(whole, killed) == sorted(["out/iq.npz", "out/bounce.bin", "out/hg.ply", "out/snake.npz",
                                                  "out/torus.npz", "out/sphere_deepsdf.npz"])
    assert not [p for p in (killed / "out").iterdir() if ".partial-" in p.name]


def test_a_broken_shader_and_a_hang_fail_alone(tmp_path):
    (tmp_path / "broken.glsl").write_text(BROKEN)
    (tmp_path / "slow.glsl").write_text(SLOW)
    rows = [
        {"sdf": "broken.glsl", "pattern": "rand", "n": 1000, "output": "broken.npz"},
        {"sdf": "slow.glsl", "pattern": "rand", "n": 4000000, "output": "slow.npz"},
        {"sdf": "no_such_shape", "pattern": "rand", "n": 1000, "output": "missing.npz"},
        {"sdf": str(FOREIGN / "04_iq_operators.glsl"), "pattern": "near", "n": 20000, "output": "good.npz"},
    ]
    manifest = write_jsonl(tmp_path / "shapes.jsonl", rows)
    start = time.monotonic()
    done = run("run", str(manifest), "--item-timeout", "4", "--json", check=1)
    seconds = time.monotonic() - start
    report = json.loads(done.stdout)
    by_output = {Path(r["output"]).name: r for r in report["results"]}
    assert by_output["broken.npz"]["status"] == "failed"
    assert re.search(r"broken\.glsl:\d+", by_output["broken.npz"]["error"])  # the file and line of the error
    assert by_output["slow.npz"]["status"] == "timeout" and 4.0 <= by_output["slow.npz"]["seconds"] < 12.0
    assert by_output["missing.npz"]["status"] == "failed" and "no_such_shape" in by_output["missing.npz"]["error"]
    assert by_output["good.npz"]["status"] == "done" and (tmp_path / "good.npz").exists()
    assert (report["done"], report["failed"]) == (1, 3) and seconds < 60
    assert not [p for p in tmp_path.iterdir() if ".partial-" in p.name] and not (tmp_path / "slow.npz").exists()
    # The status file holds the same outcomes; a rerun retries the failures and skips the good item.
    assert [r["status"] for r in status_records(tmp_path / "shapes.jsonl.status.jsonl")] == \
        ["failed", "timeout", "failed", "done"]
    again = json.loads(run("run", str(manifest), "--item-timeout", "2", "--json", check=1).stdout)
    assert (again["skipped"], again["failed"]) == (1, 3)


def test_bad_manifests_are_named_and_run_nothing(tmp_path):
    cases = {
        "unknown.jsonl": ('{"sdf": "Sphere", "pattern": "rand", "n": 10, "output": "a.npz", "colour": 1}\n',
                          "unknown.jsonl:1: sample request: 'colour': unknown key"),
        "missing.jsonl": ('{"sdf": "Sphere", "pattern": "rand", "output": "a.npz"}\n', "missing.jsonl:1: missing \"n\""),
        "json.jsonl": ('{"sdf": "Sphere", "pattern": "rand", "n": 10, "output": "a.npz"}\n{"sdf": \n',
                       "json.jsonl:2: not valid JSON"),
        "twice.jsonl": ('{"sdf": "Sphere", "pattern": "rand", "n": 10, "output": "a.npz"}\n'
                        '{"sdf": "Torus", "pattern": "rand", "n": 10, "output": "./a.npz"}\n',
                        ("twice.jsonl:2: 'output': '", "/a.npz' is also the output of line 1")),
        "recipe.jsonl": ('{"recipe": "shapenet", "sdf": "Sphere", "output": "a.npz"}\n',
                         "recipe.jsonl:1: 'recipe': expected one of deepsdf, occnet"),
        "count.csv": ("sdf,pattern,n,output\nSphere,rand,ten,a.npz\n", "count.csv:2: 'n': expected a non-negative integer"),
        "cells.csv": ("sdf,pattern,n,output\nSphere,rand,10,a.npz,extra\n", "cells.csv:2: 5 cells"),
        "quote.csv": ('sdf,pattern,n,output\n"Sphere,rand,10,a.npz\n', "quote.csv:2: unterminated"),
        "family.jsonl": ('{"sdf": "Sphere", "pattern": "rand", "n": 10, "output": "a.npz", "randomize": 3}\n',
                         "family.jsonl:1: 'randomize': a family writes many files"),
        "empty.csv": ("sdf,pattern,n,output\n", "empty.csv: the manifest has no items"),
    }
    for name, (text, message) in cases.items():
        (tmp_path / name).write_text(text)
        done = run("run", str(tmp_path / name))
        assert done.returncode == 2, name
        for part in (message,) if isinstance(message, str) else message:
            assert part in done.stderr, (name, done.stderr)
    assert run("run", str(tmp_path / "nothing.jsonl")).returncode == 2
    assert run("run", str(tmp_path / "count.csv"), "--rank", "2", "--world-size", "2").returncode == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(cases)  # no outputs, no status files


def test_the_slurm_example_runs_task_by_task_to_the_single_runs_files(tmp_path):
    single, array = tmp_path / "single", tmp_path / "array"
    for folder in (single, array):
        folder.mkdir()
        write_jsonl(folder / "shapes.jsonl", items(folder))
    run("run", str(single / "shapes.jsonl"), "--quiet", check=0)
    script = REPO / "docs" / "examples" / "slurm_manifest.sh"
    for task in range(3):
        env = dict(os.environ, SDFWB=BINARY, MANIFEST=str(array / "shapes.jsonl"), ITEM_TIMEOUT="300",
                   SLURM_ARRAY_TASK_ID=str(task), SLURM_ARRAY_TASK_COUNT="3")
        env.pop("DISPLAY", None)
        done = subprocess.run(["bash", str(script)], env=env, capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        records = status_records(array / f"shapes.jsonl.status-{task}-of-3.jsonl")
        assert sorted(r["index"] for r in records) == [i for i in range(6) if i % 3 == task]
        assert all(r["status"] == "done" for r in records)
    same_files(single, array)


def test_dask_run_on_a_local_cluster_writes_the_cli_runs_files(tmp_path):
    import distributed  # bootstrap installs python3-distributed; sdfwb itself never needs it

    import sdfwb.dask

    cli, dask = tmp_path / "cli", tmp_path / "dask"
    for folder in (cli, dask):
        folder.mkdir()
        write_jsonl(folder / "shapes.jsonl", items(folder))
    run("run", str(cli / "shapes.jsonl"), "--quiet", check=0)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        summary = sdfwb.dask.run_manifest(dask / "shapes.jsonl", client, item_timeout=300, binary=BINARY)
        workers = {r["index"]: r for r in summary["results"]}
        assert (summary["done"], summary["failed"], len(workers)) == (6, 0, 6)
        again = sdfwb.dask.run_manifest(dask / "shapes.jsonl", client, binary=BINARY)
        assert again["skipped"] == 6 and again["done"] == 0
    same_files(cli, dask)
    assert summary["bytes_written"] == sum((dask / n).stat().st_size for n in outputs(dask))
    # The CLI reads the status file the Dask run wrote.
    listed = json.loads(run("run", str(dask / "shapes.jsonl"), "--list", "--json", check=0).stdout)
    assert all(r["status"] == "done" for r in listed["results"])
