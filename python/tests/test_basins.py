"""basins: the attractor of every start of a plane, as the command line maps it."""

import json

import numpy as np
import pytest

import capsubot
from conftest import cli_csv, cli_error, cli_flags, run_cli, same, same_columns

# The robot of docs/attractors.md: a stable one-impact orbit beside an irregular motion.
ROBOT = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5, alpha=0.2792869076315278)
QUICK = dict(transient=40, record=16)
CLI_ROBOT = ["--A", 0.05, "--c", 0.02, "--phi0", -2.842, "--T0", 0.1, "--e", 0.5, "--alpha",
             0.2792869076315278, "--transient", 40, "--record", 16]


def test_columns_equal_the_command_lines_csv():
    found = capsubot.basins(**ROBOT, starts="4x3", **QUICK)
    assert same_columns(found["columns"], cli_csv("basins", *CLI_ROBOT, "--starts", "4x3"))
    # Both attractors of this robot are on the map (the test sees more than one label).
    assert set(found["columns"]["attractor"]) == {1, 2}
    # The rest of the dict is the command's --json.
    status, out, err = run_cli("basins", *CLI_ROBOT, "--starts", "4x3", "-o", "/dev/null",
                               "--json")
    assert status == 0, err
    expected = json.loads(out)
    expected.pop("provenance")
    rest = {k: v for k, v in found.items() if k not in ("columns", "provenance")}
    assert same(rest, expected)
    assert found["provenance"]["command"] == "basins"
    assert found["provenance"]["options"]["starts"] == "4x3"


def test_velocity_plane_equals_the_command_lines_csv():
    found = capsubot.basins(**ROBOT, starts="3x4", plane="x0-u0", psi=1.0, u_min=-0.5,
                            u_max=0.5, **QUICK, threads=1)
    assert list(found["columns"])[:2] == ["x0", "u0"]
    assert same_columns(found["columns"], cli_csv(
        "basins", *CLI_ROBOT, "--starts", "3x4", "--plane", "x0-u0", "--psi", 1.0, "--u-min",
        -0.5, "--u-max", 0.5))
    # u0 = u_min + (j + 0.5)(u_max - u_min)/4 (the documented plane).
    assert np.array_equal(found["columns"]["u0"][:4], [-0.375, -0.125, 0.125, 0.375])


def test_a_cell_is_the_attractor_of_its_start():
    """The start x0 = 0.5, psi = 0 is cell (1, 0) of a 3x3 map and the only start of a 1x1
    grid of attractors(): the same long-run motion."""
    columns = capsubot.basins(**ROBOT, starts="3x3", **QUICK)["columns"]
    cell = 3 * 1 + 0
    assert (columns["x0"][cell], columns["psi"][cell]) == (0.5, 0.0)
    (alone,) = capsubot.attractors(**ROBOT, starts="1x1", **QUICK)["attractors"]
    assert columns["period"][cell] == alone["period"]
    assert columns["impacts_right"][cell] == alone["impacts_right"]
    assert columns["impacts_left"][cell] == alone["impacts_left"]
    assert columns["mean_velocity"][cell] == alone["mean_velocity"]
    assert columns["status"][cell] == alone["status"]


def test_label_counts_are_the_attractors_starts():
    found = capsubot.basins(**ROBOT, starts="4x3", **QUICK)
    labels = found["columns"]["attractor"]
    assert found["attractors"]
    for k, attractor in enumerate(found["attractors"], start=1):
        assert np.count_nonzero(labels == k) == attractor["starts"]


@pytest.mark.parametrize("python", [dict(plane="x0-v0"), dict(starts="4by4"), dict(record=8),
                                    dict(alpha=1.5), dict(e=1.3)])
def test_bad_input_has_the_command_lines_message(python):
    arguments = {**ROBOT, **QUICK, **python}
    with pytest.raises(ValueError) as err:
        capsubot.basins(**arguments)
    assert str(err.value) == cli_error("basins", *cli_flags(arguments), "-o", "/dev/null")


def test_bad_velocity_range_names_the_arguments():
    with pytest.raises(ValueError) as err:
        capsubot.basins(**ROBOT, plane="x0-u0", u_min=0.5, u_max=-0.5)
    assert str(err.value) == "u_min = 0.5 and u_max = -0.5 are invalid: expected u_min < u_max"
    with pytest.raises(ValueError) as err:  # in either plane, as on the command line
        capsubot.basins(**ROBOT, u_min=1.0, u_max=1.0)
    assert str(err.value) == "u_min = 1 and u_max = 1 are invalid: expected u_min < u_max"
