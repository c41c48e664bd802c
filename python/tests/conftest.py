"""Shared helpers of the Python module's tests: the built command-line program.

ctest runs these tests with PYTHONPATH pointing at the built module and CAPSUBOT_CLI at the
built program (python/CMakeLists.txt); by hand:
    PYTHONPATH=build/python CAPSUBOT_CLI=build/capsubot /usr/bin/python3 -m pytest python/tests
"""

import json
import os
import subprocess

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
    """The object `capsubot ARGS --json` prints (it must exit 0)."""
    status, out, err = run_cli(*args, "--json")
    assert status == 0, err
    return json.loads(out)


def without_from_rest(obj):
    """`obj` without the simulator's checks from rest that the command line adds to its gaits
    (the keys "from_rest" at any depth, the main job's "reach" and the words saying so in a
    "note"): the module's solve and
    optimize return the analytic gait only; capsubot.attractors gives the check from rest."""
    if isinstance(obj, dict):
        return {k: (v.removesuffix("; checked from rest") if k == "note" else without_from_rest(v))
                for k, v in obj.items() if k not in ("from_rest", "reach")}
    if isinstance(obj, list):
        return [without_from_rest(v) for v in obj]
    return obj
