"""bifurcation: the brute-force diagram, as the command line writes it."""

import math

import numpy as np
import pytest

import capsubot
from conftest import cli_csv, cli_error, cli_flags, same_columns

ROBOT = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5, alpha=0.2792869076315278)
QUICK = dict(transient=40, record=8, max_period=4)
CLI_ROBOT = ["--A", 0.05, "--c", 0.02, "--phi0", -2.842, "--T0", 0.1, "--e", 0.5, "--alpha",
             0.2792869076315278, "--transient", 40, "--record", 8, "--max-period", 4]
# The long-run mean velocity of a periodic motion: the simulator's mean over whole periods after
# a long transient, against the diagram's recorded mean. Both are sums over the same exact
# events, so they agree to round-off of a few hundred periods' sums.
MEAN_VELOCITY_TOL = 1e-9


def test_tables_equal_the_command_lines_csvs():
    found = capsubot.bifurcation(**ROBOT, param="T0", from_=0.08, to=0.12, steps=3, **QUICK)
    files = cli_csv("bifurcation", *CLI_ROBOT, "--param", "T0", "--from", 0.08, "--to", 0.12,
                    "--steps", 3, summary="--summary")
    assert same_columns(found["impacts"], files["main"])
    assert same_columns(found["summary"], files["summary"])
    # up, down and the analytic orbits, at each of the 3 values.
    assert set(found["summary"]["direction"]) == {"up", "down", "analytic"}
    assert found["provenance"]["command"] == "bifurcation"
    assert found["provenance"]["options"]["from_"] == 0.08


def test_two_parameter_study_without_analytic_equals_the_command_line():
    found = capsubot.bifurcation(**ROBOT, param="T0", from_=0.08, to=0.12, steps=2,
                                 direction="down", start=(0.25, 1.0), over="e=0.4,0.6",
                                 no_analytic=True, **QUICK, threads=1)
    files = cli_csv("bifurcation", *CLI_ROBOT, "--param", "T0", "--from", 0.08, "--to", 0.12,
                    "--steps", 2, "--direction", "down", "--start", "0.25,1", "--over",
                    "e=0.4,0.6", "--no-analytic", summary="--summary")
    assert list(found["summary"])[0] == "e"
    assert same_columns(found["impacts"], files["main"])
    assert same_columns(found["summary"], files["summary"])
    assert set(found["summary"]["direction"]) == {"down"}


def test_up_sweep_is_the_long_run_motion_of_each_value():
    """This robot has one attractor from rest at these T0 (a stable one-impact orbit): the
    diagram's mean velocity at each value is a direct long simulation's there."""
    values = [0.08, 0.1, 0.12]
    summary = capsubot.bifurcation(**ROBOT, param="T0", from_=values[0], to=values[-1],
                                   steps=len(values), direction="up", **QUICK)["summary"]
    up = summary["direction"] == "up"
    assert np.array_equal(summary["param"][up], values)
    for T0, mean_velocity, status in zip(values, summary["mean_velocity"][up],
                                         summary["status"][up]):
        assert status == "periodic"
        run = capsubot.simulate(**{**ROBOT, "T0": T0}, x0=0.5, u0=0.0, v0=0.0, transient=400,
                                periods=400)
        assert math.isclose(run["v_mean"], mean_velocity, rel_tol=0, abs_tol=MEAN_VELOCITY_TOL)


@pytest.mark.parametrize("python", [
    dict(direction="sideways"), dict(steps=1), dict(to=0.08), dict(param="mu"),
    dict(over="e=0:1:200000"), dict(over="T0=0.1,0.2"), dict(record=4),
])
def test_bad_input_has_the_command_lines_message(python):
    arguments = {**ROBOT, **QUICK, "param": "T0", "from_": 0.08, "to": 0.12, **python}
    with pytest.raises(ValueError) as err:
        capsubot.bifurcation(**arguments)
    assert str(err.value) == cli_error("bifurcation", *cli_flags(arguments), "-o", "/dev/null")


def test_a_range_that_is_not_finite_is_refused():
    # (The command line refuses --from inf when it reads the number, before the library.)
    with pytest.raises(ValueError) as err:
        capsubot.bifurcation(**ROBOT, **QUICK, param="T0", from_=float("inf"), to=0.12)
    assert str(err.value) == "range from = inf to = 0.12 is invalid: expected two finite numbers"


def test_alpha_is_needed_unless_stepped():
    args = {**ROBOT, **QUICK, "param": "T0", "from_": 0.08, "to": 0.12}
    del args["alpha"]
    with pytest.raises(ValueError) as err:
        capsubot.bifurcation(**args)
    assert str(err.value) == "alpha is missing: give the mass ratio of the robot"
    stepped = capsubot.bifurcation(**{**args, "param": "alpha", "from_": 0.27, "to": 0.28},
                                   steps=2, direction="up")
    assert np.array_equal(stepped["summary"]["param"][:2], [0.27, 0.28])
