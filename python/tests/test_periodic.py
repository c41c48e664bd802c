"""periodic: a periodic motion by Newton shooting, as the command line finds it."""

import pytest

import capsubot
from conftest import cli_json, same

# The robot of docs/attractors.md whose motion from rest has 3 right + 1 left impacts.
ROBOT = dict(A=0.34063197373861814, c=0.06410131873607934, phi0=-3.1181183398453047,
             alpha=0.6435592358295166, T0=1, e=1)
CLI_ROBOT = ["--A", 0.34063197373861814, "--c", 0.06410131873607934, "--phi0",
             -3.1181183398453047, "--alpha", 0.6435592358295166, "--T0", 1, "--e", 1]


def test_equals_the_command_line():
    found = capsubot.periodic(**ROBOT, from_rest=(0.5, 1.0), transient=100)
    assert same(found, cli_json("periodic", *CLI_ROBOT, "--from-rest", "0.5,1", "--transient", 100))
    assert found["status"] == "converged"
    # Multipliers are one NumPy complex array, as from solve(stability=True).
    assert found["multipliers"].dtype == complex and found["multipliers"].shape == (2,)
    orbit = capsubot.solve(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5, stability=True)
    assert orbit["multipliers"].dtype == complex and orbit["multipliers"].shape == (2,)
    assert (found["period"], found["impacts_right"], found["impacts_left"]) == (1, 3, 1)
    # From the state it found, with no transient, as the command line does from a state.
    s = found["state"]
    again = capsubot.periodic(**ROBOT, x0=s["x"], u0=s["u"], v0=s["v"], psi=s["psi"])
    assert same(again, cli_json("periodic", *CLI_ROBOT, "--x0", s["x"], "--u0", s["u"], "--v0",
                             s["v"], "--psi", s["psi"]))
    # The period given: Newton from that state converges to the same motion.
    shot = capsubot.periodic(**ROBOT, x0=s["x"], u0=s["u"], v0=s["v"], psi=s["psi"], period=1)
    assert shot["status"] == "converged" and shot["period"] == 1
    assert abs(shot["mean_velocity"] - found["mean_velocity"]) <= 1e-12


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError) as err:
        capsubot.periodic(**ROBOT, x0=0.5, u0=0.0)
    assert str(err.value) == (
        "the start is missing: give all of x0, u0, v0, psi (or from_rest=(x0, psi))")
    with pytest.raises(ValueError) as err:
        capsubot.periodic(**ROBOT, from_rest=(0.5, 1.0), x0=0.5)
    assert str(err.value) == "from_rest gives the start: do not give x0, u0, v0 or psi with it"
    with pytest.raises(ValueError) as err:
        capsubot.periodic(**ROBOT, from_rest=(0.5, 1.0), max_period=0)
    assert str(err.value).startswith("max_period = 0 is invalid")
