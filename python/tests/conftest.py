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
    """The object `capsubot ARGS --json` prints (it must exit 0), without its "provenance": the
    module's dicts do not carry one (the program records its command line there)."""
    status, out, err = run_cli(*args, "--json")
    assert status == 0, err
    obj = json.loads(out)
    provenance = obj.pop("provenance")
    assert provenance["command"] == args[0] and provenance["program"] == "capsubot"
    return obj
