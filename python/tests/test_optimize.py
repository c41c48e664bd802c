"""optimize: the command line's object for each problem (every gait checked from rest), the
reach problem and the main job, and P1 checked by a dense scan."""

import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import capsubot
from conftest import cli_json, same


# A force shape with valid orbits (the second panel of Fig. 3): A = 0.2, c = 0.03, T0 = 1.
SHAPE = dict(A=0.2, c=0.03)
SCAN_POINTS = 200001
# A small reach search (budgets far below its 20 s time limit, so the search is the same on
# any machine; no wall-clock time is in the result) and small grids from rest.
REACH = dict(reach_starts="2x2", reach_evaluations=6, reach_local_evaluations=2,
             from_rest_starts="3x3")
CLI_REACH = ["--reach-starts", "2x2", "--reach-evaluations", 6, "--reach-local-evaluations", 2,
             "--from-rest-starts", "3x3"]


def test_phase_equals_the_command_lines_json():
    d = capsubot.optimize(problem="phase", **SHAPE)
    assert same(d, cli_json("optimize", "--problem", "phase", "--A", 0.2, "--c", 0.03))
    assert d["status"] == "ok" and d["valid"] is True and d["problem"] == "phase"


def test_phase_optimum_is_the_best_valid_point_of_a_dense_scan():
    # The command line's margins d_s = s = 0.02 (validity, as solve_grid checks it), without
    # the stability requirement (solve_grid does not bound the spectral radius).
    d = capsubot.optimize(problem="phase", **SHAPE, rho_max=math.inf)
    assert (d["margin_stroke"], d["stick_margin"], d["rho_max"]) == (0.02, 0.02, None)
    phi0 = np.linspace(-math.pi, math.pi, SCAN_POINTS)
    g = capsubot.solve_grid(**SHAPE, phi0=phi0, margin_stroke=0.02, stick_margin=0.02)
    valid_I = np.where(g["valid"], g["I"], np.nan)
    best = np.nanmax(valid_I)
    assert np.count_nonzero(g["valid"]) > 1000  # the valid arcs are well sampled
    assert best <= d["I"] + 1e-12
    # The optimum lies on an arc edge (the stroke clearance binds), within one scan step of a
    # valid scan point: the scan's best is below it by at most the largest change of I per step.
    assert d["active_constraints"] == ["clearance"] and d["binding"] == ["clearance_stroke"]
    step_change = np.nanmax(np.abs(np.diff(valid_I)))
    assert 0.0 <= d["I"] - best <= step_change, (d["I"] - best, step_change)


def test_stable_phase_equals_the_command_line():
    d = capsubot.optimize(problem="phase", **SHAPE, stable=True)
    assert same(d, cli_json("optimize", "--problem", "phase", "--A", 0.2, "--c", 0.03, "--stable"))
    assert d["spectral_radius"] <= 1.0 and d["stable"] is True
    assert same(capsubot.optimize(problem="phase", **SHAPE, rho_max=1.0), d)


def test_margins_and_rho_max_equal_the_command_line():
    args = dict(margin=0.01, margin_stroke=0.0, stick_margin=0.05, rho_max=math.inf)
    d = capsubot.optimize(problem="phase", **SHAPE, **args)
    assert same(d, cli_json("optimize", "--problem", "phase", "--A", 0.2, "--c", 0.03, "--margin",
                         0.01, "--margin-stroke", 0, "--stick-margin", 0.05, "--rho-max", "inf"))
    assert (d["margin"], d["margin_stroke"], d["stick_margin"], d["rho_max"]) == (
        0.01, 0.0, 0.05, None)


def test_main_job_equals_the_command_line():
    d = capsubot.optimize(T0=0.1, starts=2, hops=2, **REACH)
    assert same(d, cli_json("optimize", "--T0", 0.1, "--starts", 2, "--hops", 2, *CLI_REACH))
    assert [d[k]["problem"] for k in ("paper", "robust", "fastest", "fastest_stable")] == [
        "phase", "forcing", "forcing", "forcing"]
    # The robust gait is checked from rest on the full grid; it seeds the reach search.
    assert d["robust"]["from_rest"]["starts"] == 9 and d["reach"]["attractors"]["starts"] == 9
    assert d["reach"]["seed"]["I"] == d["robust"]["I"]
    # The robust gait pays for its margins: never faster than the exact optimum.
    assert d["robust"]["I"] <= d["fastest"]["I"] and d["rho_max"] == 0.9


def test_forcing_and_fourier_equal_the_command_line():
    budget = dict(T0=0.1, starts=2)
    forcing = capsubot.optimize(problem="forcing", **budget, hops=2)
    assert same(forcing, cli_json("optimize", "--problem", "forcing", "--T0", 0.1, "--starts", 2,
                               "--hops", 2))
    assert forcing["status"] == "ok" and forcing["A"] + forcing["c"] <= 0.1 * (1 + 1e-12)
    fourier = capsubot.optimize(problem="fourier", **budget, harmonics=2)
    assert same(fourier, cli_json("optimize", "--problem", "fourier", "--T0", 0.1, "--starts", 2,
                               "--harmonics", 2))
    assert fourier["A"] is None and len(fourier["cos"]) == len(fourier["sin"]) == 2
    assert fourier["coefficients"] == {"c": fourier["c"], "cos": fourier["cos"],
                                       "sin": fourier["sin"]}
    # P3 starts from the P2 optimum: never below it.
    assert fourier["gain"] >= 0.0 and fourier["I"] >= fourier["baseline_I"]


def test_reach_equals_the_command_line():
    d = capsubot.optimize(problem="reach", T0=0.1, starts=2, hops=2, **REACH)
    cli = cli_json("optimize", "--problem", "reach", "--T0", 0.1, "--starts", 2, "--hops", 2,
                   *CLI_REACH)
    assert same(d, cli)
    assert "search_seconds" not in d and d["status"] == "ok"
    assert d["A"] + d["c"] <= 0.1 * (1 + 1e-12) and 0 < d["alpha"] < 1
    # The winner's attractors on the full grid (3 x 3 starts) give its mean velocity; the seed
    # is re-checked too, and the winner is never slower than the seed from rest.
    a = d["attractors"]
    assert a["starts"] == 9 and sum(x["starts"] for x in a["attractors"]) == 9
    assert d["mean_velocity"] == a["mean_velocity"]
    assert d["mean_velocity"] >= d["seed"]["mean_velocity_from_rest"]
    # A fixed mass ratio stays fixed.
    fixed = capsubot.optimize(problem="reach", T0=0.1, starts=2, hops=2, alpha=0.3, **REACH)
    assert fixed["alpha"] == 0.3


def test_every_problem_checks_its_gait_from_rest():
    d = capsubot.optimize(problem="phase", **SHAPE, from_rest_starts="2x3", threads=1)
    fr = d["from_rest"]
    assert fr["starts"] == 6 and fr["summary"]
    assert fr["reached"] == sum(a["starts"] for a in fr["attractors"] if a["one_impact_orbit"])


def test_calls_from_several_threads_give_the_serial_results():
    # optimize and simulate release the GIL: concurrent calls must not share state.
    shapes = [dict(A=0.2, c=0.03), dict(A=0.2, c=0.03, stable=True), dict(A=0.1, c=0.02),
              dict(A=0.3, c=0.05)]
    serial = [capsubot.optimize(problem="phase", **s) for s in shapes]
    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(lambda s: capsubot.optimize(problem="phase", **s), shapes))
    assert parallel == serial and len(parallel) == 4
