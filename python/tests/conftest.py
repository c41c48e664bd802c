"""Shared helpers of the Python module's tests: the built command-line program.

ctest runs these tests with PYTHONPATH pointing at the built module and CAPSUBOT_CLI at the
built program (python/CMakeLists.txt); by hand:
    PYTHONPATH=build/python CAPSUBOT_CLI=build/capsubot /usr/bin/python3 -m pytest python/tests
"""

import json
import os
import re
import subprocess
import tempfile

import numpy as np
import pytest


def cli_path():
    path = os.environ.get("CAPSUBOT_CLI")
    if not path:
        pytest.fail("CAPSUBOT_CLI is not set: run through ctest, or set it to build/capsubot")
    return path


def run_cli(*args):
    """Runs `capsubot ARGS`; returns (exit status, stdout, stderr)."""
    r = subprocess.run([cli_path(), *map(str, args)], capture_output=True, text=True,
                       timeout=600, check=False)
    return r.returncode, r.stdout, r.stderr


def cli_json(*args):
    """The object `capsubot ARGS --json` prints (it must exit 0), without its "provenance": the
    module's dicts do not carry one (the program records its command line there)."""
    status, out, err = run_cli(*args, "--json")
    assert status == 0, err
    obj = json.loads(out)
    provenance = obj.pop("provenance")
    assert provenance["command"] == args[0] and provenance["program"] == "capsubot"
    return obj


def _complex(z):
    """A multiplier of the JSON, {"re", "im"} or [re, im] (null: NaN), as a complex number."""
    re, im = (z["re"], z["im"]) if isinstance(z, dict) else z
    return complex(float("nan") if re is None else re, float("nan") if im is None else im)


def _multipliers(obj):
    """The JSON with its multipliers as the module gives them: NumPy complex arrays."""
    if isinstance(obj, dict):
        return {k: np.array([_complex(z) for z in v], dtype=complex)
                if k == "multipliers" and isinstance(v, list) else _multipliers(v)
                for k, v in obj.items()}
    if isinstance(obj, list):
        return [_multipliers(v) for v in obj]
    return obj


def same(a, b):
    """a and b equal at every depth; NumPy arrays element by element (NaN equal to NaN). The
    command line's JSON (b may be it) has its multipliers converted as the module converts them."""
    b = _multipliers(b)

    def equal(x, y):
        if isinstance(x, np.ndarray) or isinstance(y, np.ndarray):
            return (isinstance(x, np.ndarray) and isinstance(y, np.ndarray)
                    and x.shape == y.shape and np.array_equal(x, y, equal_nan=True))
        if isinstance(x, dict) and isinstance(y, dict):
            return x.keys() == y.keys() and all(equal(x[k], y[k]) for k in x)
        if isinstance(x, list) and isinstance(y, list):
            return len(x) == len(y) and all(equal(u, v) for u, v in zip(x, y))
        return x == y

    return equal(a, b)


def read_csv(path):
    """The CSV file at `path` as {column: list of cells (text)}, after its '#' lines."""
    with open(path, encoding="utf-8") as f:
        lines = [line for line in f.read().splitlines() if not line.startswith("#")]
    header = lines[0].split(",")
    rows = [line.split(",") for line in lines[1:]]
    assert all(len(row) == len(header) for row in rows)
    return {name: [row[k] for row in rows] for k, name in enumerate(header)}


def cli_csv(*args, output="-o", **more_outputs):
    """The CSV files `capsubot ARGS` writes (it must exit 0): the columns of the file of
    `output` (read_csv), and with more_outputs {name: option} also theirs, as a dict."""
    with tempfile.TemporaryDirectory() as folder:
        paths = {name: os.path.join(folder, name + ".csv") for name in ["main", *more_outputs]}
        extra = [arg for name, option in more_outputs.items() for arg in (option, paths[name])]
        status, _, err = run_cli(*args, output, paths["main"], *extra)
        assert status == 0, err
        files = {name: read_csv(path) for name, path in paths.items()}
    return files if more_outputs else files["main"]


def same_columns(columns, cells):
    """The module's columns equal the CSV's cells, in the same order: numbers bit for bit as
    Python's float() reads the text (an empty cell: NaN), names as the text."""
    assert list(columns) == list(cells)
    assert cells, "no columns"
    for name, text in cells.items():
        array = columns[name]
        assert isinstance(array, np.ndarray) and len(array) == len(text), name
        if array.dtype.kind in "iuf":
            expected = np.array([float(cell) if cell else np.nan for cell in text])
            assert np.array_equal(array.astype(float), expected, equal_nan=True), name
        else:
            assert array.dtype.kind == "U" and list(array) == text, name
    return True


def cli_error(*args):
    """The one-line error of `capsubot ARGS` (it must fail), with the option names as the module's
    arguments: "--reach-evaluations" -> "reach_evaluations", "--A" -> "A"."""
    status, _, err = run_cli(*args)
    assert status != 0
    message = err.strip().split("\n")[-1].split(": error: ", 1)[1]
    return re.sub(r"--([A-Za-z][A-Za-z0-9-]*)", lambda m: m.group(1).replace("-", "_"), message)


def cli_flags(arguments):
    """Keyword arguments as the command line's options: {"u_min": -1, "from_": 0} ->
    ["--u-min", -1, "--from", 0]."""
    return [item for name, value in arguments.items()
            for item in ("--" + name.rstrip("_").replace("_", "-"), value)]
