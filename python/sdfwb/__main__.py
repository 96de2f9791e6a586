"""Command line for the Python-side tools.

    python3 -m sdfwb evaluate --sdf SDF --points IN.npy --output OUT.npz
    python3 -m sdfwb recipe deepsdf --sdf SDF --output OUT.npz [--n N --seed S --params JSON ...]
    python3 -m sdfwb recipe - < ITEM.json      (a manifest item: how `sdfwb --batch run` runs recipes)

evaluate: OUT.npz holds distance (N,) and, unless --no-gradient, gradient (N,3) (float32), written atomically; an
.npy output holds the distances alone. recipe: the layouts of sdfwb.recipes; prints a JSON line (output, rows,
bad_rows, seconds). Exit codes: 0 done, 2 bad arguments or input, 1 a failure while running.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable
from typing import Any

import numpy as np

from . import evaluate, recipes
from .recipes import atomic_write as _atomic_save

RECIPE_KEYS = {"recipe", "sdf", "entry", "params", "n", "seed", "time", "output", "padding"}


def _evaluate(options: argparse.Namespace) -> None:
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


def _recipe(options: argparse.Namespace) -> None:
    if options.name == "-":
        text = sys.stdin.read()
        try:
            item = json.loads(text)
        except json.JSONDecodeError as error:
            raise ValueError(f"recipe: the item on stdin is not valid JSON ({error})") from None
        if not isinstance(item, dict):
            raise ValueError("recipe: the item on stdin must be a JSON object")
    else:
        item = {"recipe": options.name, "sdf": options.sdf, "output": options.output, "entry": options.entry,
                "seed": options.seed, "time": options.time}
        if options.n is not None:
            item["n"] = options.n
        if options.params:
            item["params"] = json.loads(options.params)
        if options.padding is not None:
            item["padding"] = options.padding
    unknown = sorted(set(item) - RECIPE_KEYS)
    if unknown:
        raise ValueError(f"recipe: unknown key '{unknown[0]}' (known: {', '.join(sorted(RECIPE_KEYS))})")
    name = item.get("recipe")
    if name not in ("deepsdf", "occnet"):
        raise ValueError(f"recipe: expected deepsdf or occnet, got {name!r}")
    for key in ("sdf", "output"):
        if not isinstance(item.get(key), str) or not item[key]:
            raise ValueError(f"recipe: '{key}' must be a non-empty string")
    if not item["output"].endswith(".npz"):
        raise ValueError(f"recipe: '{item['output']}': a recipe writes .npz")
    arguments = {"seed": int(item.get("seed", 0)), "params": item.get("params"), "time": float(item.get("time", 0.0)),
                 "entry": item.get("entry", "")}
    if "n" in item:
        arguments["n"] = int(item["n"])
    if name == "occnet" and "padding" in item:
        arguments["padding"] = float(item["padding"])
    elif "padding" in item:
        raise ValueError("recipe: 'padding' belongs to occnet")
    run: Callable[..., dict[str, Any]] = recipes.deepsdf
    if name == "occnet":
        run = recipes.occnet
    metadata = run(item["sdf"], item["output"], **arguments)
    rows = metadata["n"] - metadata.get("rows_dropped", 0)
    print(json.dumps({"output": item["output"], "recipe": name, "rows": rows, "bad_rows": metadata.get("rows_dropped", 0),
                      "seconds": metadata["sampling_seconds"]}))


def main(argv: list[str] | None = None) -> int:
    """The command line; returns the exit code (0 done, 2 bad arguments or input, 1 a failure while running).

    Args:
        argv (list[str] | None): the arguments after the program's name. Default None: sys.argv[1:].
    """
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
    rc = commands.add_parser("recipe", help="write a named recipe's .npz (deepsdf, occnet), or run a manifest item (-)")
    rc.add_argument("name", help="deepsdf, occnet, or - to read a manifest item's JSON from stdin")
    rc.add_argument("--sdf", default="", help="dataset name, path or GLSL source")
    rc.add_argument("--output", default="", help="the .npz to write")
    rc.add_argument("--n", type=int, default=None, help="points (default: the recipe's published count)")
    rc.add_argument("--seed", type=int, default=0)
    rc.add_argument("--entry", default="")
    rc.add_argument("--time", type=float, default=0.0)
    rc.add_argument("--params", default="", help='JSON object of parameter values')
    rc.add_argument("--padding", type=float, default=None, help="occnet: the box padding (default 0.1)")
    options = parser.parse_args(argv)
    try:
        (_evaluate if options.command == "evaluate" else _recipe)(options)
    except (ValueError, json.JSONDecodeError) as error:
        print(f"sdfwb: {error}", file=sys.stderr)
        return 2
    except RuntimeError as error:
        print(f"sdfwb: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
