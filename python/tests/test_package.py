"""The package reads like one: __all__, a docstring that help() shows for every argument of every public function,
type stubs for the native module that mypy checks (and that cannot drift from it), and pyproject.toml's metadata."""
import ast
import importlib
import inspect
import os
import pydoc
import re
import subprocess
import sys
import tomllib
import types
import typing

import numpy as np
import pytest

import sdfwb
import sdfwb.dask
import sdfwb.recipes
import sdfwb.torch
from sdfwb import _native

HERE = os.path.dirname(os.path.abspath(__file__))
PYPROJECT = os.path.join(os.path.dirname(HERE), "pyproject.toml")
# The package as built (PYTHONPATH=build/python): the .py files, the stubs and py.typed beside the native module,
# laid out as they are installed.
PACKAGE = os.path.dirname(os.path.abspath(sdfwb.__file__))
STUB = os.path.join(PACKAGE, "_native.pyi")
MODULES = [sdfwb, sdfwb.recipes, sdfwb.torch, sdfwb.dask]


# --- mypy ------------------------------------------------------------------------------------------------------------
# Debian's mypy (python3-mypy, installed by scripts/bootstrap) in the interpreter running these tests: under ctest that
# is CMake's Python_EXECUTABLE, /usr/bin/python3 (CMakeLists.txt prefers it), the interpreter the module is built for
# and the one python3-mypy installs into. mypy analyses with this interpreter's packages (numpy, torch, distributed).
# A missing mypy fails the test: it never skips.
def mypy(*paths):
    # The cache lives in the build tree, beside the package: the first run analyses numpy, torch and distributed
    # (about a minute on 2 cores), later runs reuse it.
    cache = os.path.join(os.path.dirname(PACKAGE), ".mypy_cache")
    command = [sys.executable, "-m", "mypy", "--config-file", PYPROJECT, "--cache-dir", cache, "--no-color-output",
               "--no-error-summary", PACKAGE, *paths]
    # mypy reads the stubs and never loads the native module, so it runs without the sanitizer runtime that
    # scripts/sanitize preloads into the tests (no sdfwb code runs in it).
    env = {key: value for key, value in os.environ.items() if key != "LD_PRELOAD"}
    done = subprocess.run(command, capture_output=True, text=True, timeout=540, env=env)
    assert "No module named mypy" not in done.stderr, \
        f"{sys.executable} has no mypy: install Debian's python3-mypy (scripts/bootstrap does)"
    return done


def test_mypy_accepts_the_stubs_and_every_public_function_typed_as_documented():
    done = mypy(os.path.join(HERE, "typed_usage.py"))
    assert done.returncode == 0, done.stdout + done.stderr


MISTYPED = '''\
import numpy as np
import sdfwb
import sdfwb.recipes
import sdfwb.torch

sdfwb.sample("Torus", "near", "1000")  # arg-type: n is an int
sdfwb.sample("Torus", "near", 10, near_truncation=3.0)  # call-arg: the argument is near_truncate
sdfwb.audit("Torus", params={"radius": "big"})  # dict-item: values are numbers, bools or sequences of numbers
sdfwb.evaluate("Torus", np.zeros((4, 3)), gradient="no")  # call-overload: gradient is a bool
sdfwb.sample("Torus", "near", 10)["positions"]  # typeddict-item: the key is position
faces: str = sdfwb.mesh("Torus")["faces"]  # assignment: faces is an array
sdfwb.evaluate("Torus", np.zeros((4, 3)))["gradient"].shape  # union-attr: gradient may be None
sdfwb.load("rows.npz")["metadata"]["seed"].upper()  # attr-defined: seed is an int
sdfwb.save("rows.npz", np.zeros((4, 3)), np.zeros(4), np.zeros((4, 3)), seed="3")  # arg-type: seed is an int
sdfwb.recipes.mix("Torus", {"rand": "1"}, 100)  # dict-item: ratios are numbers
sdfwb.torch.SampleStream("Torus", batch_size=1.5)  # arg-type: batch_size is an int
'''


def test_mypy_rejects_mistyped_calls(tmp_path):
    path = tmp_path / "mistyped.py"
    path.write_text(MISTYPED)
    expected = {(n, line.split("# ")[1].split(":")[0])
                for n, line in enumerate(MISTYPED.splitlines(), 1) if "# " in line}
    done = mypy(str(path))
    assert done.returncode == 1, done.stdout + done.stderr
    found = set()
    for line in done.stdout.splitlines():
        if ": note: " in line:
            continue
        match = re.match(r".*mistyped\.py:(\d+): error: .*\[([a-z-]+)\]$", line)
        assert match, f"an error outside the mistyped file, or not an error: {line}"
        found.add((int(match[1]), match[2]))
    assert found == expected, done.stdout


# --- __all__ and docstrings ------------------------------------------------------------------------------------------
def public_callables(module):
    """The functions and classes a module defines (or re-exports from sdfwb._native) whose names are public."""
    return {name for name, value in vars(module).items()
            if not name.startswith("_") and callable(value) and not inspect.ismodule(value)
            and getattr(value, "__module__", "").startswith("sdfwb")}


@pytest.mark.parametrize("module", MODULES, ids=lambda m: m.__name__)
def test_all_lists_the_public_api(module):
    assert all(hasattr(module, name) for name in module.__all__), module.__all__
    assert len(set(module.__all__)) == len(module.__all__)
    callables = {name for name in module.__all__ if callable(getattr(module, name))}
    assert callables == public_callables(module)
    if module is sdfwb:
        assert sorted(sdfwb.__all__) == sorted(public_callables(sdfwb))
        native = {name for name, value in vars(_native).items() if not name.startswith("_") and callable(value)}
        assert native <= set(sdfwb.__all__)
        # `from sdfwb import *` gives exactly that
        namespace = {}
        exec("from sdfwb import *", namespace)
        assert sorted(k for k in namespace if k != "__builtins__") == sorted(sdfwb.__all__)


def native_signature(function):
    """The parameters of a pybind11 function, from the signature line its docstring starts with."""
    first = function.__doc__.splitlines()[0]
    assert first.startswith(function.__name__ + "("), first
    tree = ast.parse(f"def {first}: ...")
    return tree.body[0]


def parameters_of(value):
    if inspect.isbuiltin(value):
        return [a.arg for a in native_signature(value).args.args]
    return [p.name for p in inspect.signature(value).parameters.values()]


def documented(value):
    """(name, object) for every public callable of the API and every public method of its classes."""
    yield value.__qualname__, value
    if inspect.isclass(value):
        for name, member in vars(value).items():
            if not name.startswith("_") and inspect.isfunction(member):
                yield f"{value.__qualname__}.{name}", member


@pytest.mark.parametrize("module", MODULES, ids=lambda m: m.__name__)
def test_help_says_what_every_argument_takes(module):
    for public in sorted(public_callables(module)):
        for name, value in documented(getattr(module, public)):
            text = pydoc.render_doc(value, renderer=pydoc.plaintext)
            doc = inspect.getdoc(value) or ""
            assert len(doc) > 40, f"{module.__name__}.{name}: no docstring"
            if typing.is_typeddict(value):
                continue
            for parameter in parameters_of(value):
                if parameter == "self":
                    continue
                # an entry of the Args section: "name (type): what it takes", indented as help() shows it
                assert re.search(rf"^[ |]+{parameter}( \([^\n]*?\))?: \S", text, re.M), \
                    f"help({module.__name__}.{name}) does not say what `{parameter}` takes"


# --- the stubs -------------------------------------------------------------------------------------------------------
def stub_functions():
    tree = ast.parse(open(STUB).read())
    return {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}, tree


def literal(node):
    return ast.literal_eval(node) if node is not None else "<required>"


def test_the_stubs_name_every_native_function_with_its_parameters_defaults_and_simple_types():
    functions, tree = stub_functions()
    native = {name for name, value in vars(_native).items() if inspect.isbuiltin(value)}
    assert set(functions) == native
    for name in sorted(native):
        actual, stub = native_signature(getattr(_native, name)), functions[name]
        assert [a.arg for a in stub.args.args] == [a.arg for a in actual.args.args], name
        assert not stub.args.kwonlyargs and not stub.args.posonlyargs and not stub.args.vararg, name
        padding = [None] * (len(actual.args.args) - len(actual.args.defaults))
        stub_padding = [None] * (len(stub.args.args) - len(stub.args.defaults))
        for arg, default, stub_arg, stub_default in zip(actual.args.args, padding + actual.args.defaults,
                                                        stub.args.args, stub_padding + stub.args.defaults):
            assert literal(stub_default) == literal(default), f"{name}({arg.arg}=): default"
            # pybind11's str, int, float, bool are the stub's exactly; its object, dict, arrays are typed by hand
            if ast.unparse(arg.annotation) in ("str", "int", "float", "bool"):
                assert ast.unparse(stub_arg.annotation) == ast.unparse(arg.annotation), f"{name}({arg.arg}): type"
        if ast.unparse(actual.returns) == "None":
            assert ast.unparse(stub.returns) == "None", name
    exported = next(node for node in tree.body if isinstance(node, ast.Assign) and node.targets[0].id == "__all__")
    assert sorted(ast.literal_eval(exported.value)) == sorted(n for n in native if not n.startswith("_"))


def test_the_package_is_marked_typed_and_ships_its_stubs():
    assert os.path.isfile(os.path.join(PACKAGE, "py.typed"))
    assert os.path.isfile(STUB)
    assert open(STUB).read() == open(os.path.join(os.path.dirname(HERE), "sdfwb", "_native.pyi")).read()


def test_params_take_any_mapping_as_the_stubs_say():
    points = np.zeros((1, 3), np.float32)
    given = sdfwb.evaluate("Torus", points, params=types.MappingProxyType({"majorRadius": 0.5}))
    expected = sdfwb.evaluate("Torus", points, params={"majorRadius": 0.5})
    assert np.array_equal(given["distance"], expected["distance"])
    with pytest.raises(TypeError, match="params: expected a dict"):
        sdfwb.evaluate("Torus", points, params=[("majorRadius", 0.5)])


# --- pyproject.toml --------------------------------------------------------------------------------------------------
def test_pyproject_describes_the_package_built_here():
    with open(PYPROJECT, "rb") as stream:
        project = tomllib.load(stream)["project"]
    assert project["name"] == "sdfwb"
    assert project["version"] == sdfwb.__version__  # the version CMake's project() gives the native module
    assert project["requires-python"] == ">=3.11" and sys.version_info >= (3, 11)
    assert project["dependencies"] == ["numpy"]
    for extra, module in (("torch", "torch"), ("dask", "distributed"), ("open3d", "open3d")):
        assert extra in project["optional-dependencies"]
        importlib.import_module(module)  # bootstrap installs every extra here: the tests use them all


def test_every_job_kind_runs_through_run_and_its_python_function_exists():
    # The job kinds' one table (values/JobKinds.h), as the native module exports it: each kind's Python function
    # exists and is public; every kind is a request sdfwb.run reads (an empty request names the missing fields).
    kinds = _native._job_kinds()
    assert len(kinds) >= 12
    names = [name for name, _, _ in kinds]
    assert len(set(names)) == len(names)
    for name, needs_gl, function in kinds:
        assert isinstance(needs_gl, bool)
        if function:
            assert function in sdfwb.__all__, f"{name}: sdfwb.{function} is not public"
            assert callable(getattr(sdfwb, function)), f"{name}: sdfwb.{function}"
    with pytest.raises(Exception, match="unknown kind 'paint'") as refused:
        sdfwb.run({"kind": "paint"})
    for name in names:  # the message lists every kind of the table
        assert name in str(refused.value)


# --- the stubs' TypedDicts against the dicts the functions return ----------------------------------------------------
# The TypedDicts in the stubs are the one place the Python side names the keys of what the functions return; this
# compares them with the dicts themselves, so a key added, renamed or dropped on either side fails here.
def typed_dicts():
    """Each TypedDict of the stubs: (its required keys, its NotRequired keys)."""
    out = {}
    for node in ast.parse(open(STUB).read()).body:
        if isinstance(node, ast.ClassDef) and any(getattr(base, "id", "") == "TypedDict" for base in node.bases):
            required, optional = set(), set()
            for item in node.body:
                if isinstance(item, ast.AnnAssign):
                    wrapped = ast.unparse(item.annotation).startswith("NotRequired[")
                    (optional if wrapped else required).add(item.target.id)
            out[node.name] = (required, optional)
    return out


def assert_keys_as_stubbed(result, name, stubs):
    required, optional = stubs[name]
    keys = set(result)
    assert required <= keys, f"{name}: the stubs promise {sorted(required - keys)}, which the function does not return"
    assert keys <= required | optional, f"{name}: the function returns {sorted(keys - required - optional)}, unstubbed"


def test_the_stubs_typed_dicts_name_the_keys_the_functions_return(tmp_path):
    stubs = typed_dicts()
    assert {"SampleResult", "EvaluateResult", "SampleMetadata", "LoadResult", "MeshResult", "ParameterInfo",
            "ParamsReport", "SdfEntry"} <= set(stubs)
    sample = sdfwb.sample("sphere", "rand", 64)
    assert_keys_as_stubbed(sample, "SampleResult", stubs)
    assert_keys_as_stubbed(sdfwb.evaluate("sphere", np.zeros((4, 3), np.float32)), "EvaluateResult", stubs)
    out = str(tmp_path / "rows.npz")
    sdfwb.run({"kind": "sample", "sdf": "sphere", "pattern": "rand", "n": 64, "output": out})
    loaded = sdfwb.load(out)
    assert_keys_as_stubbed(loaded, "LoadResult", stubs)
    assert_keys_as_stubbed(loaded["metadata"], "SampleMetadata", stubs)
    assert_keys_as_stubbed(sdfwb.mesh("sphere", resolution=16), "MeshResult", stubs)
    report = sdfwb.params("uniform float radius = 0.5; // @range 0.1 1.0\nfloat sdf(vec3 p) { return length(p) - radius; }\n")
    assert_keys_as_stubbed(report, "ParamsReport", stubs)
    assert_keys_as_stubbed(report["parameters"][0], "ParameterInfo", stubs)
    for entry in sdfwb.list_sdfs()[:3]:
        assert_keys_as_stubbed(entry, "SdfEntry", stubs)
