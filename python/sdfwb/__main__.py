"""Command line for the Python-side tools: `python3 -m sdfwb evaluate --sdf SDF --points IN.npy --output OUT.npz`.

OUT.npz holds distance (N,) and, unless --no-gradient, gradient (N,3) (float32), written atomically; an .npy
output holds the distances alone. Exit codes: 0 done, 2 bad arguments or input, 1 a failure while running.
"""

import argparse
import json
import os
import sys
import tempfile

import numpy as np

from . import evaluate


def _atomic_save(path, write):
    folder = os.path.dirname(os.path.abspath(path))
    handle, temporary = tempfile.mkstemp(prefix=".sdfwb-", suffix=os.path.splitext(path)[1], dir=folder)
    try:
        with os.fdopen(handle, "wb") as stream:
            write(stream)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def _evaluate(options):
    try:
        points = np.load(options.points, allow_pickle=False)
    except (OSError, ValueError) as error:
        raise ValueError(f"--points: '{options.points}': not a readable .npy array ({error})") from None
    if points.ndim != 2 or points.shape[1] != 3 or points.dtype.kind != "f":
        raise ValueError(f"--points: '{options.points}': expected a float array of shape (N, 3), got {points.dtype} "
                         f"{points.shape}")
    if not options.output.endswith((".npz", ".npy")):
        raise ValueError(f"--output: '{options.output}': use .npz (distance and gradient) or .npy (distance)")
    params = json.loads(options.params) if options.params else None
    gradient = not options.no_gradient and options.output.endswith(".npz")
    result = evaluate(options.sdf, points, params=params, time=options.time, gradient=gradient, entry=options.entry)
    if options.output.endswith(".npy"):
        _atomic_save(options.output, lambda stream: np.save(stream, result["distance"]))
    else:
        arrays = {"distance": result["distance"]}
        if gradient:
            arrays["gradient"] = result["gradient"]
        _atomic_save(options.output, lambda stream: np.savez(stream, **arrays))
    print(f"{options.output}: {len(points)} points in {result['seconds']:.3f} s ({result['bad_rows']} non-finite)")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m sdfwb")
    commands = parser.add_subparsers(dest="command", required=True)
    ev = commands.add_parser("evaluate", help="the field at the points of a .npy file")
    ev.add_argument("--sdf", required=True, help="dataset name, path or GLSL source")
    ev.add_argument("--points", required=True, help=".npy array (N, 3)")
    ev.add_argument("--output", required=True, help=".npz (distance, gradient) or .npy (distance)")
    ev.add_argument("--entry", default="", help="the SDF's function when it is not sdf (e.g. map)")
    ev.add_argument("--time", type=float, default=0.0)
    ev.add_argument("--params", default="", help='JSON object of parameter values, e.g. {"radius": 0.3}')
    ev.add_argument("--no-gradient", action="store_true", help="distances only (one evaluation per point)")
    options = parser.parse_args(argv)
    try:
        _evaluate(options)
    except (ValueError, json.JSONDecodeError) as error:
        print(f"sdfwb: {error}", file=sys.stderr)
        return 2
    except RuntimeError as error:
        print(f"sdfwb: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
