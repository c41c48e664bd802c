"""A pulse (piecewise-constant) force through the keywords levels=, switches=, waveform=: the
same numbers as the command line, the same run as the pulse's Fourier series in the limit of
many harmonics (an independent description of the same force), one-line errors."""

import math

import pytest

import capsubot
from conftest import cli_json, same

LEVELS = [0.3, -0.05]
SWITCHES = [0.0, 1.5]
PULSE = dict(levels=LEVELS, switches=SWITCHES, T0=0.1, e=0.5)
ROBOT = dict(**PULSE, alpha=0.3)
CLI_PULSE = ["--levels", "0.3,-0.05", "--switches", "0,1.5", "--T0", 0.1, "--e", 0.5]
CLI_ROBOT = CLI_PULSE + ["--alpha", 0.3]
START = dict(alpha=0.3, x0=0.5, u0=0.0, v0=0.0)


def without_tables(d):
    return {k: v for k, v in d.items() if k not in ("event_table", "trajectory")}


def fourier_series(levels, switches, harmonics):
    """c, a_k, b_k of G(s) = L_j on [s_j, s_j+1) (s_N = s_0 + 2 pi), integrated in closed form."""
    ends = switches[1:] + [switches[0] + 2 * math.pi]
    c = sum(L * (t - s) for L, s, t in zip(levels, switches, ends)) / (2 * math.pi)
    a = [sum(L * (math.sin(k * t) - math.sin(k * s)) for L, s, t in zip(levels, switches, ends))
         / (math.pi * k) for k in range(1, harmonics + 1)]
    b = [sum(L * (math.cos(k * s) - math.cos(k * t)) for L, s, t in zip(levels, switches, ends))
         / (math.pi * k) for k in range(1, harmonics + 1)]
    return c, a, b


def test_simulate_equals_the_command_line():
    s = capsubot.simulate(**PULSE, **START, phi0=0.4, periods=5, transient=2)
    cli = cli_json("simulate", *CLI_PULSE, "--alpha", 0.3, "--x0", 0.5, "--u0", 0, "--v0", 0,
                   "--phi0", 0.4, "--periods", 5, "--transient", 2)
    assert without_tables(s) == cli
    assert s["impacts_right"] + s["impacts_left"] > 0
    assert s["force"] == {"waveform": "pulse", "levels": LEVELS, "switches": SWITCHES,
                          "phi0": 0.4}


def test_simulate_is_the_limit_of_the_pulses_fourier_series():
    # Both levels inside T0 = 0.6: the capsule rests between impacts and the long-run motion is
    # robust to the series' overshoot near the jumps, so its mean velocity converges to the
    # pulse's as the harmonics grow (as in tests/simulate/simulator_pulse_test.cpp).
    levels, switches = [0.45, -0.3], [0.0, 2.6]
    run = dict(T0=0.6, e=0.5, alpha=0.5, x0=0.5, u0=0.0, v0=0.0, transient=300, periods=100)
    pulse = capsubot.simulate(levels=levels, switches=switches, **run)["v_mean"]
    assert abs(pulse) > 1e-3  # a directed motion
    gaps = []
    for k in (4, 8, 16):
        c, a, b = fourier_series(levels, switches, k)
        gaps.append(abs(capsubot.simulate(c=c, cos=a, sin=b, **run)["v_mean"] - pulse))
    assert gaps[2] < gaps[1] < gaps[0]
    assert gaps[2] < 0.05 * abs(pulse)
    # The levels swapped give another motion.
    swapped = capsubot.simulate(levels=levels[::-1], switches=switches, **run)["v_mean"]
    assert abs(swapped - pulse) > 2 * gaps[2]  # farther than the 16-harmonic series


def test_attractors_periodic_and_branch_equal_the_command_line():
    quick = dict(transient=40, record=16)
    found = capsubot.attractors(**ROBOT, starts="2x2", **quick)
    assert same(found, cli_json("attractors", *CLI_ROBOT, "--starts", "2x2", "--transient", 40,
                                "--record", 16))
    assert found["force"]["waveform"] == "pulse" and found["attractors"]
    motion = capsubot.periodic(**ROBOT, from_rest=(0.5, 0.0), transient=100)
    assert same(motion, cli_json("periodic", *CLI_ROBOT, "--from-rest", "0.5,0",
                                 "--transient", 100))
    assert motion["status"] == "converged"
    st = motion["state"]
    branch = capsubot.continue_branch(**ROBOT, param="T0", from_=0.095, to=0.105, x0=st["x"],
                                      u0=st["u"], v0=st["v"], psi=st["psi"], max_points=10)
    cli = cli_json("continue", *CLI_ROBOT, "--param", "T0", "--from", 0.095, "--to", 0.105,
                   "--x0", repr(st["x"]), "--u0", repr(st["u"]), "--v0", repr(st["v"]),
                   "--psi", repr(st["psi"]), "--max-points", 10)
    points, cli_points = branch.pop("points"), cli.pop("points")  # columns in the dict
    assert same(branch, cli) and len(cli_points) >= 3
    assert list(points["mean_velocity"]) == [p["mean_velocity"] for p in cli_points]


@pytest.mark.parametrize("kwargs,text", [
    (dict(levels=[1, 2], switches=[2, 1]),
     "switches: s_2 = 1 is invalid: expected it above s_1 = 2 (switch phases strictly "
     "increasing)"),
    (dict(levels=[1, 2], switches=[0, 7]),
     "switches: s_2 = 7 is invalid: expected 0 <= s < 2 pi (phases in radians)"),
    (dict(levels=[1, 2, 3], switches=[0, 1]),
     "switches: 2 phases given for 3 levels: expected one switch phase per level"),
    (dict(levels=[1, 2]),
     "switches is missing: a pulse force needs levels L_1,...,L_N and switches s_1,...,s_N [rad]"),
    (dict(levels=[1, 2], switches=[0, 1], A=0.5),
     "waveform pulse takes levels and switches: A is invalid with it"),
    (dict(levels=[1, 2], switches=[0, 1], c=0.5),
     "c = 0.5 is invalid with waveform pulse: expected no c (the levels give the mean force)"),
    (dict(waveform="square", c=0.1, A=0.1, phi0=0.0),
     "waveform = 'square' is invalid: expected sine, fourier or pulse"),
    (dict(waveform="sine", A=0.1, c=0.1, phi0=0.0, levels=[1.0]),
     "levels is invalid with waveform sine: expected it only with waveform pulse"),
    (dict(A=0.1, phi0=0.0), "c is missing: give the mean force c"),
])
def test_bad_pulse_input_names_the_parameter_and_the_rule(kwargs, text):
    for fn in (capsubot.simulate, capsubot.attractors, capsubot.periodic):
        with pytest.raises(ValueError) as err:
            fn(**kwargs, T0=0.1, alpha=0.3, **({"x0": 0.5, "u0": 0, "v0": 0}
                                               if fn is capsubot.simulate else
                                               {"from_rest": (0.5, 0.0)}
                                               if fn is capsubot.periodic else {"starts": "1x1"}))
        assert str(err.value) == text, fn.__name__


def test_a_pulse_cannot_start_on_the_analytic_orbit():
    with pytest.raises(ValueError) as err:
        capsubot.simulate(**PULSE, from_orbit=True)
    assert str(err.value).startswith(
        "a pulse force is invalid for from_orbit (a start on the analytic one-impact orbit): "
        "expected a sine or Fourier force")
    with pytest.raises(ValueError) as err:
        capsubot.continue_branch(**ROBOT, param="A", from_=0.0, to=1.0, x0=0.5, u0=0.0, v0=0.0,
                                 psi=0.0)
    assert str(err.value) == ("parameter = A is invalid for a pulse force: expected c (every "
                              "level moved), phi0, T0, e or alpha")
    with pytest.raises(TypeError):
        capsubot.solve(levels=LEVELS, switches=SWITCHES)  # the analytic orbit takes no pulse
