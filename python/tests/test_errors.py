"""Bad input: ValueError (or TypeError for a wrong type) with the library's message naming the
parameter, its value and the rule; nothing crashes the interpreter."""

import math

import numpy as np
import pytest

import capsubot

HARMONIC = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5)


def message(fn, **kwargs):
    with pytest.raises(ValueError) as err:
        fn(**kwargs)
    return str(err.value)


@pytest.mark.parametrize("fn", [capsubot.solve, capsubot.trajectory])
def test_model_parameters_name_the_rule(fn):
    assert message(fn, **{**HARMONIC, "e": 1.3}) == (
        "restitution e = 1.3 is invalid: expected 0 <= e <= 1")
    assert message(fn, **{**HARMONIC, "T0": -1.0}) == (
        "friction bound T0 = -1 is invalid: expected a finite T0 > 0")
    assert message(fn, **{**HARMONIC, "A": -0.5}) == "A = -0.5 is invalid: expected A >= 0"
    assert message(fn, **{**HARMONIC, "A": math.nan}) == (
        "A = nan is invalid: expected a finite number")
    assert message(fn, **{**HARMONIC, "c": math.inf}) == (
        "c = inf is invalid: expected a finite number")
    assert message(fn, **{**HARMONIC, "phi0": math.nan}) == (
        "phi0 = nan is invalid: expected a finite number")


def test_margin_names_the_rule():
    assert message(capsubot.solve, **HARMONIC, margin=0.5) == (
        "margin d = 0.5 is invalid: expected 0 <= d < 0.5")


def test_force_arguments_that_are_missing_or_contradict():
    assert message(capsubot.solve, c=0.02, phi0=0.0) == (
        "A is missing: give the amplitude A (or sin/cos)")
    assert message(capsubot.solve, A=0.05, c=0.02) == (
        "phi0 is missing: give the impact phase phi0 [rad]")
    assert message(capsubot.solve, A=0.05, c=0.02, phi0=0.0, sin=[0.1]).startswith(
        "A and sin are exclusive")
    assert message(capsubot.solve, c=0.02, phi0=0.0, cos=[0.1]).startswith("cos needs sin")
    assert message(capsubot.solve, c=0.02, phi0=0.0, cos=[0.1], sin=[0.1, 0.2]) == (
        "Fourier coefficients: 1 cosine and 2 sine terms given: expected as many of each")
    assert message(capsubot.solve, c=0.02, sin=[0.1] * 17) == (
        "harmonics K = 17 is invalid: expected K <= 16")
    assert message(capsubot.solve, c=0.02, sin=[0.1, math.nan]) == (
        "b_2 = nan is invalid: expected a finite number")


def test_wrong_types_raise_type_error():
    with pytest.raises(TypeError):
        capsubot.solve(A="big", c=0.02, phi0=0.0)
    with pytest.raises(TypeError):
        capsubot.solve(A=0.05, c=0.02, phi0=0.0, sin="abc")
    with pytest.raises(TypeError):
        capsubot.solve(0.05, 0.02, 0.0)  # keyword arguments only
    with pytest.raises(TypeError):
        capsubot.solve(A=0.05, phi0=0.0)  # c is required


def test_trajectory_needs_samples_and_an_orbit():
    assert message(capsubot.trajectory, **HARMONIC, samples=1) == (
        "samples = 1 is invalid: expected 2 <= samples <= 10000000")
    assert message(capsubot.trajectory, A=0.05, c=-0.02, phi0=0.0) == (
        "no one-impact orbit exists for this force, T0 and e (non_positive_mean_force): no "
        "trajectory")


def test_simulate_messages():
    sim = capsubot.simulate
    assert message(sim, **HARMONIC, from_orbit=True, alpha=0.3).startswith(
        "from_orbit takes the state and alpha from the analytic orbit")
    assert message(sim, **HARMONIC) == "alpha is missing: give the mass ratio (or from_orbit=True)"
    assert message(sim, **HARMONIC, alpha=0.3, x0=0.5) == (
        "the initial state is missing: give all of x0, u0, v0 (or from_orbit=True)")
    assert message(sim, A=0.05, c=-0.02, phi0=0.0, from_orbit=True) == (
        "from_orbit: no one-impact orbit exists for this force, T0 and e "
        "(non_positive_mean_force)")
    state = dict(alpha=0.3, x0=0.5, u0=0.0, v0=0.0)
    assert message(sim, **HARMONIC, **state, samples_per_period=0, trajectory=True) == (
        "samples_per_period = 0 is invalid: expected 1 <= samples_per_period <= 1000000")
    assert message(sim, **HARMONIC, **{**state, "alpha": 1.0}) == (
        "mass ratio alpha = 1 is invalid: expected 0 < alpha < 1")
    assert message(sim, **HARMONIC, **{**state, "x0": math.nan}) == (
        "initial position x0 = nan is invalid: expected 0 <= x0 <= 1")
    assert message(sim, **HARMONIC, **state, periods=0.0) == (
        "periods = 0 is invalid: expected 0 < periods <= 1e8")
    assert message(sim, **HARMONIC, **state, max_events_per_period=5) == (
        "max_events_per_period = 5 is invalid: expected >= 10")


def test_optimize_messages():
    opt = capsubot.optimize
    assert message(opt, problem="speed") == (
        "problem = 'speed' is invalid: expected 'phase', 'forcing', 'fourier', 'reach' or None "
        "(the main job)")
    assert message(opt, problem="phase", A=0.2) == (
        "problem='phase' needs the force shape: give A and c (F = A sin(phi + phi0) + c)")
    assert message(opt, problem="forcing", bound=math.nan) == (
        "bound = nan is invalid: expected a finite bound > 0 (at most T0)")
    assert message(opt, problem="forcing", bound=-1.0) == (
        "bound = -1 is invalid: expected a finite bound > 0 (at most T0)")
    assert message(opt, problem="forcing", bound=2.0).startswith(
        "bound = 2 is invalid: expected at most the friction bound T0 = 1 (a force above it")
    assert message(opt, problem="forcing", starts=0) == (
        "starts = 0 is invalid: expected 1 <= starts <= 1000")
    assert message(opt, problem="forcing", rho_max=0.0) == (
        "rho_max = 0 is invalid: expected rho_max > 0 (inf: no stability requirement)")
    assert message(opt, problem="forcing", max_time=0.0) == (
        "max_time = 0 is invalid: expected a time limit > 0 seconds (inf: none)")
    assert message(opt, problem="phase", A=0.2, c=0.03, stable=True, rho_max=0.5) == (
        "stable conflicts with rho_max = 0.5: stable=True means rho_max = 1; give one of them")
    assert message(opt, problem="forcing", A=0.2) == (
        "A conflicts with problem='forcing': expected A only with problem='phase'")
    assert message(opt, problem="phase", A=0.2, c=0.03, starts=3) == (
        "starts conflicts with problem='phase': expected starts only with the main job "
        "(problem=None) or problem='forcing' or problem='fourier' or problem='reach'")
    assert message(opt, problem="forcing", alpha=0.3) == (
        "alpha conflicts with problem='forcing': expected alpha only with problem='reach'")
    assert message(opt, problem="phase", A=0.2, c=0.03, from_rest_starts="8by8") == (
        "from_rest_starts = 8by8 is invalid: expected NXxNPSI, two whole numbers from 1 to 100000 "
        "(e.g. 8x8)")
    # The command line's grammar and limits: a size of 0 is no grid.
    assert message(opt, problem="reach", reach_starts="0x4").startswith(
        "reach_starts = 0x4 is invalid: expected NXxNPSI")
    assert message(opt, problem="reach", reach_evaluations=0) == (
        "reach_evaluations = 0 is invalid: expected at least 1")
    assert message(opt, reach_seconds=-1.0) == (
        "reach_seconds = -1 is invalid: expected a time > 0 (infinity: none)")
    assert message(opt, problem="phase", A=0.2, c=0.03, stick_margin=1.0).startswith(
        "stick margin s = 1 is invalid")
    assert message(opt, problem="forcing", local_algorithm="LN_NOPE") == (
        'local_algorithm = "LN_NOPE" is invalid: expected one of LN_COBYLA, LD_SLSQP, LD_MMA, '
        "LD_CCSAQ")
    assert message(opt, problem="fourier", harmonics=0) == (
        "harmonics K = 0 is invalid: expected 1 <= K <= 16")
    assert message(opt, problem="phase", A=0.2, c=0.03, e=-1.0) == (
        "restitution e = -1 is invalid: expected 0 <= e <= 1")
    with pytest.raises(TypeError):
        opt(problem="phase", A=0.2, c=0.03, stable="yes")


def test_orbits_messages():
    assert message(capsubot.orbits, alpha=1.5, A=0.05, c=0.02) == (
        "mass ratio alpha = 1.5 is invalid: expected 0 < alpha < 1")
    assert message(capsubot.orbits, alpha=0.3, A=0.05, c=0.02, max_evaluations=0) == (
        "max_evaluations = 0 is invalid: expected 1 <= max_evaluations <= 1000000000")


# What NumPy or pybind11 would convert silently is refused: one row per input, with the
# exception and a part of its message.
GRID = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5)
REFUSED = [
    ("grid_none", capsubot.solve_grid, {**GRID, "A": None}, TypeError,
     "A must be a number or an array of numbers: None is no number (got <class 'NoneType'>)"),
    ("grid_string_array", capsubot.solve_grid, {**GRID, "c": np.array(["0.02", "0.03"])},
     TypeError, "c must be a number or an array of numbers: strings are not converted"),
    ("grid_string", capsubot.solve_grid, {**GRID, "T0": "0.1"}, TypeError,
     "T0 must be a number or an array of numbers: strings are not converted"),
    ("grid_complex", capsubot.solve_grid, {**GRID, "A": np.array([0.05 + 0.0j])}, TypeError,
     "A must be a number or an array of numbers: complex numbers are not real numbers"),
    ("grid_objects", capsubot.solve_grid, {**GRID, "phi0": [0.0, None]}, TypeError,
     "phi0 must be a number or an array of numbers: its elements are not all numbers"),
    ("grid_booleans", capsubot.solve_grid, {**GRID, "e": np.array([True, False])}, TypeError,
     "e must be a number or an array of numbers: booleans are not numbers here"),
    ("grid_masked", capsubot.solve_grid,
     {**GRID, "A": np.ma.masked_array([0.05, 0.06], mask=[False, True])}, TypeError,
     "A must be a number or an array of numbers: a masked array's mask would be ignored"),
    ("grid_stability_int", capsubot.solve_grid, {**GRID, "stability": 2}, TypeError, ""),
    ("solve_stability_int", capsubot.solve, {**HARMONIC, "stability": 2}, TypeError, ""),
    ("simulate_trajectory_int", capsubot.simulate,
     {**HARMONIC, "from_orbit": True, "trajectory": 1}, TypeError, ""),
    ("optimize_stable_int", capsubot.optimize,
     {"problem": "phase", "A": 0.2, "c": 0.03, "stable": 1}, TypeError, ""),
    ("design_from_rest_int", capsubot.design,
     {"m1": 0.2, "L": 0.02, "mu": 0.3, "e": 0.7, "force_amplitude": 0.5, "force_bias": 0.1,
      "frequency": 20.0, "from_rest": 1}, TypeError, ""),
    ("solve_empty_sin", capsubot.solve, {"c": 0.02, "sin": []}, ValueError,
     "sin = [] is invalid: expected the coefficients b_1..b_K, 1 <= K <= 16 (an empty series "
     "is no force)"),
    ("solve_empty_cos", capsubot.solve, {"c": 0.02, "cos": [], "sin": [0.1]}, ValueError,
     "cos = [] is invalid: expected the coefficients a_1..a_K, 1 <= K <= 16"),
    ("design_empty_force_sin", capsubot.design,
     {"m1": 0.2, "L": 0.02, "mu": 0.3, "e": 0.7, "force_sin": [], "force_bias": 0.1,
      "frequency": 20.0}, ValueError,
     "force_sin = [] is invalid: expected comma-separated numbers"),
    ("design_empty_frequency_range", capsubot.design,
     {"m1": 0.2, "L": 0.02, "mu": 0.3, "e": 0.7, "force_amplitude": 0.5, "force_bias": 0.1,
      "frequency_range": (10, 10)}, ValueError,
     "frequency_range = 10:10 is invalid: expected MIN:MAX with MIN < MAX"),
    ("design_inverted_m2_range", capsubot.design,
     {"m1": 0.2, "L": 0.02, "mu": 0.3, "e": 0.7, "force_amplitude": 0.5, "force_bias": 0.1,
      "frequency": 20.0, "m2_range": (0.3, 0.1)}, ValueError,
     "m2_range = 0.3:0.1 is invalid: expected MIN:MAX with MIN < MAX"),
]


@pytest.mark.parametrize("fn, kwargs, error, text", [r[1:] for r in REFUSED],
                         ids=[r[0] for r in REFUSED])
def test_refused_input(fn, kwargs, error, text):
    with pytest.raises(error) as err:
        fn(**kwargs)
    assert text in str(err.value)


# Phases are radians: refused beyond 1e6 rad (a double there carries no angle once added to
# another phase), reduced exactly modulo 2 pi below.
HUGE_PHASE = "is invalid: expected a phase |{}| <= 1e+06 rad (phases are in radians"


@pytest.mark.parametrize("fn, kwargs, start", [
    (capsubot.solve, {**HARMONIC, "phi0": 1e300}, "phi0 = 1e+300 "),
    (capsubot.trajectory, {**HARMONIC, "phi0": -1e16}, "phi0 = -1e+16 "),
    (capsubot.simulate, {**HARMONIC, "phi0": 1e300, "alpha": 0.3, "x0": 0.5, "u0": 0.0,
                         "v0": 0.0}, "phi0 = 1e+300 "),
    (capsubot.attractors, {**HARMONIC, "phi0": 1e16, "alpha": 0.28, "starts": "1x1"},
     "phi0 = 1e+16 "),
    (capsubot.solve_grid, {**GRID, "phi0": np.array([0.0, 1e300])}, "at index (1,): phi0 = 1e+300 "),
    (capsubot.periodic, {**HARMONIC, "alpha": 0.28, "from_rest": (0.5, 1e300)}, "psi = 1e+300 "),
], ids=["solve", "trajectory", "simulate", "attractors", "solve_grid", "periodic"])
def test_huge_phase_is_refused_naming_radians(fn, kwargs, start):
    text = message(fn, **kwargs)
    name = start.split()[-3] if start.startswith("at index") else start.split()[0]
    assert text.startswith(start) and HUGE_PHASE.format(name) in text, text


def test_large_phase_is_its_exact_remainder():
    # -2.9 + 10^5 turns as a double; its remainder from 300-bit arithmetic (mpmath).
    assert capsubot.solve(A=0.5, c=0.5, phi0=628315.6307179587)["phi0"] == -2.899999999974789
