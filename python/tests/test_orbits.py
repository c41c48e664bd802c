"""orbits: every orbit of a given robot, as the command line lists them."""

import math
import warnings

import pytest

import capsubot
from conftest import cli_json, same

MOTOR = dict(A=0.05, c=0.02, T0=0.1, e=0.5)
ALPHA = 0.28
ALPHA_TOL = 1e-12  # the roots alpha(phi0) = alpha are polished to the last bits


def scanned_roots(n=4000):
    """The brackets [p, q] of n + 1 phases phi0 over [-pi, pi] where alpha(phi0) - ALPHA changes
    sign between two valid orbits (solve at each phase: the closed form, not the root search)."""
    phases = [-math.pi + 2.0 * math.pi * k / n for k in range(n + 1)]
    rows = [capsubot.solve(**MOTOR, phi0=p) for p in phases]
    return [(p, q) for p, q, a, b in zip(phases, phases[1:], rows, rows[1:])
            if a["valid"] and b["valid"] and (a["alpha"] - ALPHA) * (b["alpha"] - ALPHA) < 0.0]


def test_equals_the_command_line_and_each_orbit_solves_back():
    found = capsubot.orbits(alpha=ALPHA, **MOTOR)
    assert same(found, cli_json("orbits", "--alpha", ALPHA, "--A", 0.05, "--c", 0.02, "--T0", 0.1,
                                "--e", 0.5)["orbits"])
    # The orbits are where a dense scan of alpha(phi0) crosses ALPHA with a valid orbit (one per
    # bracket, in order); this robot has two, a stable and an unstable one.
    brackets = scanned_roots()
    assert len(brackets) == 2
    assert [lo < o["phi0"] < hi for o, (lo, hi) in zip(found, brackets)] == [True] * len(found)
    assert len(found) == len(brackets)
    assert sorted(o["stable"] for o in found) == [False, True]
    margins = capsubot.orbits(alpha=ALPHA, **MOTOR, margin_stroke=0.3, stick_margin=0.1)
    assert same(margins, cli_json("orbits", "--alpha", ALPHA, "--A", 0.05, "--c", 0.02, "--T0",
                                  0.1, "--e", 0.5, "--margin-stroke", 0.3, "--stick-margin",
                                  0.1)["orbits"])
    for o in found:
        assert o["complete"] is True and abs(o["alpha"] - ALPHA) <= ALPHA_TOL
        # solve's stability adds the check from rest, which orbits leaves out.
        again = capsubot.solve(**MOTOR, phi0=o["phi0"], stability=True, from_rest_starts="1x1")
        assert again.pop("from_rest")["starts"] == 1
        assert same({k: v for k, v in o.items() if k != "complete"}, again)


def test_an_incomplete_search_warns():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        capsubot.orbits(alpha=ALPHA, **MOTOR, max_evaluations=1)
    assert [str(w.message) for w in caught] == [
        "the search stopped at its work bound (max_evaluations): orbits may be missing"]
    assert caught[0].category is RuntimeWarning
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(RuntimeWarning):
            capsubot.orbits(alpha=ALPHA, **MOTOR, max_evaluations=1)
