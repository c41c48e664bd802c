"""simulate: the command line's object, the tables as arrays, and the analytic orbit confirmed."""

import math

import numpy as np
import pytest

import capsubot
from conftest import cli_json
from test_solve import cli_args

# A valid, stable orbit (spectral radius 0.16, the README's simulation example).
VALID = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5)
PERIODS = 10
# The simulator locates events to ~1e-13 in phase; over 10 periods the state agrees with the
# analytic orbit to this (absolute, in L and omega L).
SIM_VS_ANALYTIC_TOL = 1e-11


def without_tables(d):
    return {k: v for k, v in d.items() if k not in ("event_table", "trajectory")}


def test_from_orbit_returns_to_the_analytic_orbit():
    s = capsubot.simulate(**VALID, from_orbit=True, periods=PERIODS)
    o = s["orbit"]
    # The orbit of simulate is solve's dict without the energy (as `simulate --from-orbit`).
    solved = capsubot.solve(**VALID)
    assert "energy" in solved and "energy" not in o
    assert o == {k: v for k, v in solved.items() if k != "energy"} and o["valid"] is True
    assert (s["status"], s["impacts_right"], s["impacts_left"], s["stops"]) == ("ok", 10, 0, 10)
    # After whole periods the state is the one right after the impact (docs/model.md s. 4).
    assert s["phi"] == pytest.approx(PERIODS * 2 * math.pi, abs=1e-12)
    assert s["x"] == pytest.approx(1.0, abs=SIM_VS_ANALYTIC_TOL)
    assert s["u"] == pytest.approx(-VALID["e"] * o["u"], abs=SIM_VS_ANALYTIC_TOL)
    assert s["v"] == pytest.approx(o["v_plus"], abs=SIM_VS_ANALYTIC_TOL)
    assert s["displacement"] == pytest.approx(PERIODS * o["I"], abs=SIM_VS_ANALYTIC_TOL)
    assert s["v_mean"] == pytest.approx(o["v_mean"], abs=SIM_VS_ANALYTIC_TOL)


@pytest.mark.parametrize("state", [dict(from_orbit=True),
                                   dict(alpha=0.3, x0=0.5, u0=0.1, v0=0.0, y0=2.0),
                                   dict(from_orbit=True, transient=2.0)],
                         ids=["from_orbit", "given_state", "transient"])
def test_dict_is_the_command_lines_json(state):
    args = [*cli_args(VALID), "--periods", 3]
    for key, value in state.items():
        args += [f"--{key.replace('_', '-')}"] + ([] if value is True else [repr(value)])
    s = capsubot.simulate(**VALID, **state, periods=3, events=True, trajectory=True)
    assert without_tables(s) == cli_json("simulate", *args)
    assert ("transient" in s) == ("transient" in state) and "energy" in s


def test_event_table_lists_every_event():
    s = capsubot.simulate(**VALID, from_orbit=True, periods=PERIODS, events=True)
    t = s["event_table"]
    assert sorted(t) == sorted(["phase", "kind", "x", "u", "v", "y", "u_before", "v_before",
                                "mode"])
    assert all(len(column) == s["events"] for column in t.values()) and s["events"] == 20
    assert np.count_nonzero(t["kind"] == "impact_right") == s["impacts_right"]
    assert np.count_nonzero(t["kind"] == "stop") == s["stops"]
    # The right-wall impacts come once per period, at phi = k tau, with the orbit's velocity.
    impacts = t["kind"] == "impact_right"
    np.testing.assert_allclose(t["phase"][impacts], 2 * math.pi * np.arange(1, PERIODS + 1),
                               rtol=0, atol=1e-9)
    np.testing.assert_allclose(t["u_before"][impacts], s["orbit"]["u"], rtol=0,
                               atol=SIM_VS_ANALYTIC_TOL)
    assert t["y"][-1] == s["y"] and t["mode"][-1] == s["mode"]


def test_trajectory_is_sampled_on_the_grid():
    per_period = 40
    s = capsubot.simulate(**VALID, from_orbit=True, periods=PERIODS, trajectory=True,
                          samples_per_period=per_period)
    t = s["trajectory"]
    assert sorted(t) == sorted(["phi", "x", "u", "v", "y", "mode"])
    assert len(t["phi"]) == PERIODS * per_period + 1 and "event_table" not in s
    np.testing.assert_allclose(np.diff(t["phi"]), 2 * math.pi / per_period, rtol=1e-12)
    assert np.all((t["x"] >= 0.0) & (t["x"] <= 1.0))
    assert np.all(np.diff(t["y"]) >= 0.0)  # the capsule only slides forward on this orbit
    assert set(t["mode"]) == {"rest", "slide_forward"}
