"""solve and trajectory: the paper's example, and the same objects as `capsubot solve`."""

import csv
import math

import numpy as np
import pytest

import capsubot
from conftest import cli_json, run_cli, same


PAPER = dict(A=0.5, c=0.5, phi0=-2.944899971002)  # the paper's example (T0 = 1, e = 1)
# A valid and stable orbit (the README's simulation example).
VALID = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5)
# The same orbit with the margins of a robust gait (docs/model.md section 12).
MARGINS = dict(VALID, margin_stroke=0.1, stick_margin=0.05)
FOURIER = dict(c=0.02, cos=[0.01, 0.0, 0.005], sin=[0.04, 0.01, 0.0], phi0=-2.6, T0=0.1, e=0.7)

# phi1 is computed by an independent root search to this accuracy (bisection on doubles).
ROOT_TOL = 1e-13


def cli_args(case):
    """The command-line options of a case (keyword arguments named as the options)."""
    args = []
    for key, value in case.items():
        args += [f"--{key.replace('_', '-')}", ",".join(map(repr, value)) if isinstance(value, list) else repr(value)]
    return args


def bisect(f, lo, hi):
    """A root of f in [lo, hi] (f(lo), f(hi) of opposite signs), bisected to the last bit."""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if (f(mid) < 0) == (f(lo) < 0):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def test_paper_example_prints_the_documented_alpha():
    d = capsubot.solve(**PAPER)
    # The value docs/orbit.md gives for the paper's example.
    assert f"{d['alpha']:.14f}".startswith("0.35685746237742")
    assert d["status"] == "ok"
    assert d["valid"] is False and d["violations"] == ["left_wall"]
    assert d["x_max"] is None  # x has no interior maximum: null in JSON, None here


def test_paper_example_stop_phase_is_the_closed_form_root():
    # At the paper's example the stop phase solves 3 phi1 = 2 pi + 2 sin(phi1/2)
    # (docs/model.md section 6); solved here by bisection, independently of the library.
    phi1 = bisect(lambda p: 3 * p - 2 * math.pi - 2 * math.sin(p / 2), 2.0, 3.0)
    assert abs(capsubot.solve(**PAPER)["phi1"] - phi1) <= ROOT_TOL


@pytest.mark.parametrize("case", [PAPER, VALID, MARGINS, FOURIER, dict(A=0.5, c=-0.1, phi0=0.0)],
                         ids=["paper", "valid", "margins", "fourier", "no_orbit"])
@pytest.mark.parametrize("stability", [False, True])
def test_dict_is_the_command_lines_json(case, stability):
    # Same library call, same keys: the dict equals the parsed --json exactly (JSON numbers
    # round-trip), None where the JSON has null; with stability also the check from rest.
    expected = cli_json("solve", *cli_args(case), *(["--stability"] if stability else []))
    d = capsubot.solve(**case, stability=stability)
    assert same(d, expected)
    assert sorted(d["energy"]) == ["friction_loss", "impact_loss", "motor_work",
                                   "motor_work_positive"]
    assert {"stroke", "clearance"} <= set(d)


def test_from_rest_equals_the_command_line():
    # A non-default grid and thread count: the check from rest runs on 3 x 2 starts; the
    # result does not depend on the threads.
    d = capsubot.solve(**VALID, stability=True, from_rest_starts="3x2", threads=1)
    assert same(d, cli_json("solve", *cli_args(VALID), "--stability", "--from-rest-starts", "3x2"))
    fr = d["from_rest"]
    assert fr["starts"] == 6 and sum(a["starts"] for a in fr["attractors"]) == 6
    # The starts that end on the orbit are those of the attractor that is the orbit.
    assert fr["reached"] == sum(a["starts"] for a in fr["attractors"] if a["one_impact_orbit"])
    assert fr["summary"].startswith(f"reached from rest in {fr['reached']} of 6 starts")
    # Without an orbit there is nothing to check: None, as null in the JSON.
    assert capsubot.solve(A=0.5, c=-0.1, phi0=0.0, stability=True)["from_rest"] is None
    assert "from_rest" not in capsubot.solve(**VALID)


def test_margin_is_checked_as_clearance():
    # x_min = 0.4099 for this orbit: a clearance of 0.45 is not kept, 0.4 is.
    assert capsubot.solve(**VALID)["x_min"] == pytest.approx(0.4099, abs=1e-4)
    assert capsubot.solve(**VALID, margin=0.4)["valid"] is True
    d = capsubot.solve(**VALID, margin=0.45)
    assert d["valid"] is False and d["violations"] == ["clearance"]


def test_trajectory_equals_the_command_lines_csv(tmp_path):
    samples = 17
    path = tmp_path / "trajectory.csv"
    status, _, err = run_cli("solve", *cli_args(VALID), "--trajectory", path, "--samples", samples)
    assert status == 0, err
    with open(path, encoding="utf-8") as f:  # after its '#' provenance line
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    t = capsubot.trajectory(**VALID, samples=samples)
    assert sorted(t) == ["phi", "u", "v", "x"]
    assert len(rows) == samples
    for key in ("phi", "x", "u", "v"):
        assert t[key].shape == (samples,)
        np.testing.assert_array_equal(t[key], [float(r[key]) for r in rows])


def test_trajectory_closes_at_the_walls():
    t = capsubot.trajectory(**VALID, samples=1001)
    d = capsubot.solve(**VALID)
    assert t["phi"][0] == 0.0 and t["phi"][-1] == pytest.approx(2 * math.pi, abs=0)
    assert t["x"][0] == 1.0 and t["x"][-1] == pytest.approx(1.0, abs=1e-12)  # impact at x = 1
    assert t["v"][0] == pytest.approx(d["v_plus"], abs=1e-15)
    # The sampled positions stay inside the exact extrema.
    assert t["x"].min() >= d["x_min"] - 1e-15 and t["x"].max() <= 1.0 + 1e-15
