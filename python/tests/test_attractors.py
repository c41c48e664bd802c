"""attractors: the long-run motions from rest, as the command line finds them."""

import pytest

import capsubot
from conftest import cli_json, same

# The robot of docs/attractors.md: a stable one-impact orbit with clearance.
ROBOT = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5, alpha=0.2792869076315278)
QUICK = dict(transient=40, record=16)
CLI_ROBOT = ["--A", 0.05, "--c", 0.02, "--phi0", -2.842, "--T0", 0.1, "--e", 0.5, "--alpha",
             0.2792869076315278]


def test_equals_the_command_line():
    found = capsubot.attractors(**ROBOT, starts="2x2", **QUICK)
    assert same(found, cli_json("attractors", *CLI_ROBOT, "--starts", "2x2", "--transient", 40,
                             "--record", 16))
    assert found["starts"] == 4
    assert sum(a["starts"] for a in found["attractors"]) == 4
    # The grid as n_x, n_psi and any thread count give the same dict.
    assert capsubot.attractors(**ROBOT, n_x=2, n_psi=2, threads=1, **QUICK) == found


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError) as err:
        capsubot.attractors(**ROBOT, starts="2by2")
    assert str(err.value) == (
        "starts = 2by2 is invalid: expected NXxNPSI, two whole numbers from 1 to 100000 (e.g. 8x8)")
    with pytest.raises(ValueError) as err:
        capsubot.attractors(**ROBOT, starts="2x2", n_x=3)
    assert str(err.value).startswith("starts and n_x, n_psi are exclusive")
    with pytest.raises(ValueError) as err:
        capsubot.attractors(**ROBOT, n_x=0)
    assert str(err.value).startswith("n_x = 0 is invalid")
