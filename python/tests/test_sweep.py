"""sweep: the orbit or the optimum at every point of a grid, as the command line writes it."""

import numpy as np
import pytest

import capsubot
from conftest import cli_csv, cli_error, cli_flags, same_columns

FORCE = dict(A=0.05, c=0.02)
GRID = ["phi0=-3:-2.4:4", "e=0.5,1"]
CLI_GRID = ["--grid", "phi0=-3:-2.4:4", "--grid", "e=0.5,1"]


def test_orbit_columns_equal_the_command_lines_csv():
    found = capsubot.sweep(grid=GRID, **FORCE, T0=0.1, stability=True)
    assert same_columns(found["columns"], cli_csv("sweep", *CLI_GRID, "--A", 0.05, "--c", 0.02,
                                                  "--T0", 0.1, "--stability"))
    assert len(found["columns"]["phi0"]) == 8
    assert found["provenance"]["command"] == "sweep"
    assert found["provenance"]["options"]["grid"] == GRID


def test_robot_and_optimum_columns_equal_the_command_lines_csv():
    # A grid over alpha: every orbit of each robot (rows per orbit, not per point).
    robot = capsubot.sweep(grid=["alpha=0.25,0.3"], **FORCE, T0=0.1, e=0.5)
    assert same_columns(robot["columns"], cli_csv("sweep", "--grid", "alpha=0.25,0.3", "--A",
                                                  0.05, "--c", 0.02, "--T0", 0.1, "--e", 0.5))
    # P1 at each point, stable orbits only.
    best = capsubot.sweep(grid=["e=0.4,0.6"], optimize="phi0", **FORCE, T0=0.1, stable_only=True,
                          scan_points=90)
    assert same_columns(best["columns"], cli_csv(
        "sweep", "--grid", "e=0.4,0.6", "--optimize", "phi0", "--A", 0.05, "--c", 0.02, "--T0",
        0.1, "--stable-only", "--scan-points", 90))
    assert "status" in best["columns"]


# The optimisers with small budgets (each point a fraction of a second): the same search, so
# the same rows, on every run.
OPTIMA = {
    "forcing": dict(grid=["T0=0.1,0.2"], starts=1, hops=0),
    "fourier": dict(grid=["e=0.5,1"], harmonics=2, starts=1, T0=0.1),
    "reach": dict(grid=["e=0.5"], T0=0.1, starts=1, hops=0, reach_evaluations=3,
                  reach_local_evaluations=1, reach_starts="2x2", from_rest_starts="2x2"),
}


@pytest.mark.parametrize("mode", OPTIMA)
def test_optimum_columns_equal_the_command_lines_csv(mode):
    arguments = OPTIMA[mode]
    found = capsubot.sweep(optimize=mode, **arguments)
    grid = [item for axis in arguments["grid"] for item in ("--grid", axis)]
    rest = cli_flags({k: v for k, v in arguments.items() if k != "grid"})
    assert same_columns(found["columns"], cli_csv("sweep", *grid, "--optimize", mode, *rest))
    assert set(found["columns"]["status"]) == {"ok"}


def test_a_point_is_solve_at_that_point():
    columns = capsubot.sweep(grid=GRID, **FORCE, T0=0.1, stability=True, threads=1)["columns"]
    checked = 0
    for k in range(len(columns["phi0"])):
        d = capsubot.solve(**FORCE, phi0=columns["phi0"][k], T0=0.1, e=columns["e"][k],
                           stability=True, from_rest_starts="1x1")
        for key in ("phi1", "alpha", "u", "v_plus", "I", "v_mean", "x_min", "spectral_radius"):
            expected = np.nan if d[key] is None else d[key]
            assert np.array_equal(columns[key][k], expected, equal_nan=True), (k, key)
        assert columns["valid"][k] == d["valid"] and columns["stable"][k] == d["stable"]
        checked += 1
    assert checked == 8


@pytest.mark.parametrize("python, cli", [
    (dict(grid=GRID, c=0.02, T0=0.1), [*CLI_GRID, "--c", 0.02, "--T0", 0.1]),
    (dict(grid=["phi0=-3:-2.4:4"], A=0.05, c=0.02, phi0=-3.0),
     ["--grid", "phi0=-3:-2.4:4", "--A", 0.05, "--c", 0.02, "--phi0", -3.0]),
    (dict(grid=["e=0.5,1"], A=0.05, c=0.02, phi0=-3.0, hops=2),
     ["--grid", "e=0.5,1", "--A", 0.05, "--c", 0.02, "--phi0", -3.0, "--hops", 2]),
    (dict(grid=["e=0.5,1"], optimize="phi0", A=0.05, c=0.02, scan_points=2),
     ["--grid", "e=0.5,1", "--optimize", "phi0", "--A", 0.05, "--c", 0.02, "--scan-points", 2]),
    (dict(grid=["e=0.5,1"], optimize="forcing", global_evaluations=100),
     ["--grid", "e=0.5,1", "--optimize", "forcing", "--global-evaluations", 100]),
    (dict(grid=["e=0.5,1"], optimize="reach", reach_evaluations=0),
     ["--grid", "e=0.5,1", "--optimize", "reach", "--reach-evaluations", 0]),
    (dict(grid=["e=0.5,1"], optimize="best", A=0.05, c=0.02),
     ["--grid", "e=0.5,1", "--optimize", "best", "--A", 0.05, "--c", 0.02]),
    (dict(grid=["q=0:1:2"], A=0.05, c=0.02, phi0=0.0),
     ["--grid", "q=0:1:2", "--A", 0.05, "--c", 0.02, "--phi0", 0.0]),
])
def test_bad_input_has_the_command_lines_message(python, cli):
    with pytest.raises(ValueError) as err:
        capsubot.sweep(**python)
    assert str(err.value) == cli_error("sweep", *cli, "-o", "/dev/null")


def test_stable_only_with_rho_max_is_refused():
    with pytest.raises(ValueError) as err:
        capsubot.sweep(grid=["e=0.5,1"], optimize="forcing", stable_only=True, rho_max=0.5)
    assert str(err.value).startswith("stable_only conflicts with rho_max = 0.5")
