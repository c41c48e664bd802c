"""design: a real robot in SI units, as the command line designs it."""

import pytest

import capsubot
from conftest import cli_json, same

# The example robot of docs/design.md (examples/robot.toml).
ROBOT = dict(m1=0.2, L=0.02, mu=0.3, e=0.7, force_amplitude=0.5, force_bias=0.1)
CLI_ROBOT = ["--m1", 0.2, "--L", 0.02, "--mu", 0.3, "--e", 0.7, "--force-amplitude", 0.5,
             "--force-bias", 0.1]


def test_equals_the_command_line():
    found = capsubot.design(**ROBOT, frequency=20)
    assert same(found, cli_json("design", *CLI_ROBOT, "--frequency", 20))
    assert found["status"] == "ok" and found["one_impact"]["status"] == "ok"
    # The gait's robustness, in mu, e and kg (docs/design.md): its lower limit in m2 is the
    # period doubling where the stable design sits, 0.2128 kg.
    assert set(found["robustness"]) == {"mu", "e", "m2_kg"}
    assert found["robustness"]["m2_kg"]["down"]["type"] == "period_doubling"
    assert found["robustness"]["m2_kg"]["down"]["m2_kg"] == pytest.approx(0.2128, abs=1e-4)
    ranged = capsubot.design(**ROBOT, frequency_range=(15, 25), m2_range=(0.01, 1),
                             scan_points=8, rho_max=0.8)
    assert same(ranged, cli_json("design", *CLI_ROBOT, "--frequency-range", "15:25", "--m2-range",
                              "0.01:1", "--scan-points", 8, "--rho-max", 0.8))


def test_band_levels_equal_the_command_line():
    found = capsubot.design(**ROBOT, frequency=20, band_levels=[0.9, 0.8])
    assert same(found, cli_json("design", *CLI_ROBOT, "--frequency", 20, "--band-levels",
                                "0.9,0.8"))
    for name in ("mu", "e", "m2_kg"):
        levels = found["robustness"][name]["band"]["levels"]
        assert [level["level"] for level in levels] == [0.9, 0.8]


def test_fourier_force_equals_the_command_line():
    robot = {k: v for k, v in ROBOT.items() if k != "force_amplitude"}
    found = capsubot.design(**robot, force_sin=[0.5, 0.1], force_cos=[0.0, 0.05], frequency=20)
    assert same(found, cli_json("design", *CLI_ROBOT[:-4], "--force-bias", 0.1, "--force-sin",
                             "0.5,0.1", "--force-cos", "0,0.05", "--frequency", 20))


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError) as err:
        capsubot.design(**{**ROBOT, "e": 1.3}, frequency=20)
    assert str(err.value) == "restitution e = 1.3 is invalid: expected 0 <= e <= 1"
    with pytest.raises(ValueError) as err:
        capsubot.design(**ROBOT)
    assert str(err.value) == "frequency is missing: give frequency (or frequency_range)"
    with pytest.raises(ValueError) as err:
        capsubot.design(**ROBOT, frequency=20, frequency_range=(10, 30))
    assert str(err.value) == "frequency and frequency_range are exclusive: give one of them"


def test_from_rest_equals_the_command_line():
    # Small budgets so that the search ends on its evaluation budget, not on the clock (the
    # result is then deterministic); only the search's wall-clock seconds differ.
    budget = dict(from_rest_starts="3x3", reach_starts="2x2", reach_evaluations=6,
                  reach_local_evaluations=2, threads=1)
    found = capsubot.design(**ROBOT, frequency=20, from_rest=True, **budget)
    expected = cli_json("design", *CLI_ROBOT, "--frequency", 20, "--from-rest",
                        "--from-rest-starts", "3x3", "--reach-starts", "2x2",
                        "--reach-evaluations", 6, "--reach-local-evaluations", 2,
                        "--threads", 1)
    assert same(found, expected)  # no wall-clock time in either
    assert set(found["from_rest_best"]) >= {"forward", "backward", "evaluations"}
    assert "from_rest_best" not in capsubot.design(**ROBOT, frequency=20)
