"""The program's CSV files begin with a '#' provenance line: NumPy and the csv module read them
the ways docs/sweep.md ("Provenance: the comment line") gives."""

import csv

import numpy as np
import pytest

from conftest import run_cli

ORBIT = ["--A", 0.05, "--c", 0.02, "--phi0", -2.842, "--T0", 0.1, "--e", 0.5]
ROBOT = [*ORBIT, "--alpha", 0.2792869076315278, "--transient", 40, "--record", 16]

# name: (the command up to the CSV's path, a column that holds a number in every row)
CASES = {
    "basins": (["basins", *ROBOT, "--starts", "2x2", "-o"], "x0"),
    "attractors": (["attractors", *ROBOT, "--starts", "2x2", "-o"], "x0"),
    "bifurcation": (["bifurcation", *ROBOT, "--param", "T0", "--from", 0.08, "--to", 0.12,
                     "--steps", 3, "-o"], "param"),
    "solve_trajectory": (["solve", *ORBIT, "--samples", 5, "--trajectory"], "phi"),
    "simulate_trajectory": (["simulate", *ORBIT, "--from-orbit", "--periods", 2,
                             "--samples-per-period", 4, "--trajectory"], "phi"),
    "simulate_events": (["simulate", *ORBIT, "--from-orbit", "--periods", 2, "--events"],
                        "phase"),
    "optimize_force": (["optimize", "--problem", "phase", "--A", 0.2, "--c", 0.03,
                        "--from-rest-starts", "1x1", "--force-csv"], "F"),
    "sweep": (["sweep", "--grid", "phi0=-pi:pi:5", "--A", 0.5, "--c", 0.5, "-o"], "phi0"),
    "design_grid": (["design", "--m1", 0.2, "--L", 0.02, "--mu", 0.3, "--e", 0.7,
                     "--force-amplitude", 0.5, "--force-bias", 0.1, "--frequency", 20,
                     "--grid", "m2=0.2,0.25", "-o"], "m2_kg"),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_numpy_and_the_csv_module_read_the_file(tmp_path, name):
    args, column = CASES[name]
    path = tmp_path / f"{name}.csv"
    status, _, err = run_cli(*args, path)
    assert status == 0, err
    lines = path.read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("# capsubot ") and f" {args[0]} " in lines[0]
    header, rows = lines[1].split(","), lines[2:]
    assert not lines[1].startswith("#") and rows

    # The csv module: the lines that do not begin with '#'.
    with open(path, encoding="utf-8") as f:
        table = list(csv.DictReader(line for line in f if not line.startswith("#")))
    assert list(table[0]) == header and len(table) == len(rows)
    expected = [float(row[column]) for row in table]

    # genfromtxt with names: skip_header=1 passes the comment line (else its words would be the
    # names).
    data = np.genfromtxt(path, delimiter=",", names=True, skip_header=1, dtype=None,
                         encoding="utf-8")
    assert list(data.dtype.names) == header
    np.testing.assert_array_equal(np.atleast_1d(data[column]), expected)

    # loadtxt skips '#' lines; skiprows counts them: the comment line and the header.
    values = np.loadtxt(path, delimiter=",", skiprows=2, usecols=header.index(column))
    np.testing.assert_array_equal(np.atleast_1d(values), expected)
