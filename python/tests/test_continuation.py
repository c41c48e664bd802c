"""continue_branch: the continuation of a periodic motion in one parameter, as the command line
follows it."""

import numpy as np
import pytest

import capsubot
from conftest import cli_json, same

# The stable one-impact orbit with clearance of docs/orbit.md, followed in alpha
# (docs/continuation.md's example, fewer points).
ROBOT = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5, alpha=0.2792869076315278)
CLI_ROBOT = ["--A", 0.05, "--c", 0.02, "--phi0", -2.842, "--T0", 0.1, "--e", 0.5, "--alpha",
             0.2792869076315278]


def test_equals_the_command_line():
    found = capsubot.continue_branch(**ROBOT, from_orbit=True, param="alpha", from_=0.2, to=0.3,
                                     max_points=30)
    cli = cli_json("continue", *CLI_ROBOT, "--from-orbit", "--param", "alpha", "--from", 0.2,
                   "--to", 0.3, "--max-points", 30)
    points = found.pop("points")
    cli_points = cli.pop("points")
    assert same(found, cli)
    assert found["status"] == "ok" and len(cli_points) == 30
    # The points as columns: one NumPy array per key of the command line's points.
    assert set(points) == set(cli_points[0])
    for key, column in points.items():
        if key == "multipliers":
            want = np.array([[complex(*z) for z in p["multipliers"]] for p in cli_points])
            assert column.dtype == complex and column.shape == (30, 2)
        else:
            want = np.array([p[key] for p in cli_points])
            assert column.shape == (30,)
        assert np.array_equal(column, want), key
    assert points["alpha"].dtype == float and points["period"].dtype == np.int64
    assert points["stable"].dtype == bool and points["label"].dtype.kind == "U"
    # The branch passes its fold near alpha = 0.29035 (docs/continuation.md).
    folds = [s for s in found["special_points"] if s["type"] == "fold"]
    assert len(folds) == 1 and abs(folds[0]["alpha"] - 0.29035) < 1e-5


def test_bad_input_names_the_parameter():
    base = dict(ROBOT, param="alpha", from_=0.2, to=0.3)
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**base, from_orbit=True, max_points=1)
    assert str(err.value) == "max_points = 1 is invalid: expected 2 <= max_points <= 100000"
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**base, x0=0.5)
    assert str(err.value) == "the start is missing: give all of x0, u0, v0, psi (or from_orbit=True)"
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**dict(base, to=0.25), from_orbit=True)
    assert str(err.value).startswith("the robot's alpha = 0.2792869076315278 is outside the range")
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**dict(base, param="mu"), from_orbit=True)
    assert str(err.value).startswith("parameter = mu is invalid")


def test_switch_and_curve_equal_the_command_line():
    # The period doubling at alpha = 0.2229 followed in (alpha, A) over A in [0.04, 0.06], and
    # the period-2 branch born there (docs/continuation.md).
    args = dict(ROBOT, from_orbit=True, param="alpha", from_=0.2, to=0.3)
    found = capsubot.continue_branch(**args, switch=True, param2="A", from2=0.04, to2=0.06,
                                     follow="period_doubling")
    cli = cli_json("continue", *CLI_ROBOT, "--from-orbit", "--param", "alpha", "--from", 0.2,
                   "--to", 0.3, "--switch", "--param2", "A", "--from2", 0.04,
                   "--to2", 0.06, "--follow", "period_doubling")
    curve, cli_curve = found.pop("curve"), cli.pop("curve")
    assert set(curve) == set(cli_curve[0]) and len(cli_curve) >= 10
    for key, column in curve.items():
        want = [p[key] for p in cli_curve]
        if key == "multipliers":
            want = [[complex(*z) for z in m] for m in want]
        assert np.array_equal(column, np.array(want)), key
    # Every point of the curve has the multiplier -1.
    assert np.abs(curve["multipliers"] + 1).min(axis=1).max() < 1e-8
    assert found["follow"] == cli["follow"] and found["follow"]["status"] == "ok"
    switched, cli_switched = found.pop("switched"), cli.pop("switched")
    assert switched["status"] == "ok" and switched["points"]["period"].tolist() == [
        p["period"] for p in cli_switched["points"]]
    found.pop("points"), cli.pop("points")
    assert same(found, cli)


def test_bad_curve_input_names_the_parameter():
    base = dict(ROBOT, param="alpha", from_=0.2, to=0.3, from_orbit=True)
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**base, param2="A", from2=0.04, to2=0.06)
    assert str(err.value) == "the curve is incomplete: give all of param2, from2, to2, follow (or none)"
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**base, param2="A", from2=0.04, to2=0.06, follow="hopf")
    assert str(err.value).startswith("follow = hopf is invalid: expected one of fold,")
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**base, param2="alpha", from2=0.04, to2=0.06, follow="fold")
    assert str(err.value) == "param2 = alpha is invalid: expected a parameter other than param = alpha"
    with pytest.raises(ValueError) as err:  # named param2, not the "parameter" of param
        capsubot.continue_branch(**base, param2="mu", from2=0.04, to2=0.06, follow="fold")
    assert str(err.value).startswith("param2 = mu is invalid: expected one of A, c, alpha,")


# The robust gait of results/optimum.json followed in alpha over the range of its robustness: it
# grazes the left wall at alpha = 0.6319567436 with alpha falling (docs/continuation.md).
GAIT = dict(A=0.31611673290226067, c=0.0623092212807503, phi0=-3.089378590956282, T0=1.0, e=1.0,
            alpha=0.6322584367241656)
CLI_GAIT = ["--A", 0.31611673290226067, "--c", 0.0623092212807503, "--phi0", -3.089378590956282,
            "--T0", 1.0, "--e", 1.0, "--alpha", 0.6322584367241656]


def test_switch_at_grazing_equals_the_command_line():
    found = capsubot.continue_branch(**GAIT, from_orbit=True, param="alpha",
                                     from_=0.3161292183620828, to=0.8161292183620828,
                                     switch="grazing")
    cli = cli_json("continue", *CLI_GAIT, "--from-orbit", "--param", "alpha", "--from",
                   0.3161292183620828, "--to", 0.8161292183620828, "--switch-at", "grazing")
    switched, cli_switched = found.pop("switched"), cli.pop("switched")
    points, cli_points = switched.pop("points"), cli_switched.pop("points")
    assert same(switched, cli_switched) and switched["status"] == "ok"
    assert set(points) == set(cli_points[0]) and len(cli_points) >= 10
    for key, column in points.items():
        want = [p[key] for p in cli_points]
        if key == "multipliers":
            want = [[complex(*z) for z in m] for m in want]
        assert np.array_equal(column, np.array(want)), key
    # Beyond the grazing, with other impacts per period than the gait's one right impact.
    start = switched["start_index"]
    grazing = [s for s in found["special_points"]
               if s["type"] == "grazing" and s["wall"] == "left"][0]
    assert points["alpha"][start] < grazing["alpha"]
    assert points["impacts_left"][start] > 0
    found.pop("points"), cli.pop("points")
    assert same(found, cli)
    # False: no switch (True, the period doubling, is tested above).
    assert "switched" not in capsubot.continue_branch(**GAIT, from_orbit=True, param="alpha",
                                                      from_=0.6, to=0.7, switch=False)


def test_bad_switch_names_the_parameter():
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**ROBOT, from_orbit=True, param="alpha", from_=0.2, to=0.3,
                                 switch="fold")
    assert str(err.value) == "switch = fold is invalid: expected period_doubling or grazing"
    # A number is no switch (it was read as True: the period doubling).
    with pytest.raises(TypeError):
        capsubot.continue_branch(**ROBOT, from_orbit=True, param="alpha", from_=0.2, to=0.3,
                                 switch=2.5)
