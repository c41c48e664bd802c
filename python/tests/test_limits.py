"""The command line's bounds hold in the module: what a call holds in memory and how many threads
it starts are bounded before any work (the same numbers, from the library's limits.hpp), and
Ctrl-C (KeyboardInterrupt) stops a long call."""

import _thread
import os
import threading
import time

import pytest

import capsubot

HARMONIC = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5)
STATE = dict(alpha=0.3, x0=0.5, u0=0.0, v0=0.0)
# The small stable orbit's robot (docs/attractors.md).
ROBOT = dict(HARMONIC, alpha=0.2792869076315278)


def message(fn, **kwargs):
    with pytest.raises(ValueError) as err:
        fn(**kwargs)
    return str(err.value)


def test_trajectory_samples_are_bounded_as_the_command_line_samples():
    assert message(capsubot.trajectory, A=0.5, c=0.5, phi0=-2.9, samples=10**9) == (
        "samples = 1000000000 is invalid: expected 2 <= samples <= 10000000")


def test_simulated_trajectory_rows_are_bounded_over_the_whole_run():
    assert message(capsubot.simulate, **HARMONIC, **STATE, periods=1e8, trajectory=True,
                   samples_per_period=10**6) == (
        "samples_per_period = 1000000 with transient + periods = 100000000 is invalid: expected "
        "at most 10000000 rows of the trajectory (samples per period x periods + 1 = "
        "100000000000001)")
    # The transient is sampled too.
    assert "with transient + periods = 1000001 is invalid" in message(
        capsubot.simulate, **HARMONIC, **STATE, periods=1, transient=1e6, trajectory=True,
        samples_per_period=100)
    assert message(capsubot.simulate, **HARMONIC, **STATE, trajectory=True,
                   samples_per_period=10**7) == (
        "samples_per_period = 10000000 is invalid: expected 1 <= samples_per_period <= 1000000")


def test_work_bounds_are_those_of_the_command_line():
    assert message(capsubot.simulate, **HARMONIC, **STATE, max_events_per_period=2 * 10**9) == (
        "max_events_per_period = 2000000000 is invalid: expected 10 <= max_events_per_period <= "
        "1000000000")
    assert message(capsubot.orbits, alpha=0.3, A=0.05, c=0.02, max_evaluations=2 * 10**9) == (
        "max_evaluations = 2000000000 is invalid: expected 1 <= max_evaluations <= 1000000000")


def test_threads_are_lowered_to_four_per_core():
    """attractors(threads=64) runs at most 4 threads a core (each holds its record), as the
    command line lowers --threads: the threads of this process are counted while it runs."""
    def count():
        return len(os.listdir("/proc/self/task"))

    before = count()
    most = before
    worker = threading.Thread(target=capsubot.attractors, kwargs=dict(
        ROBOT, starts="8x8", transient=0, record=40000, converged_tolerance=0.0, threads=64))
    worker.start()
    while worker.is_alive():
        most = max(most, count())
        time.sleep(0.002)
    worker.join()
    # The Python thread and its workers (itself one of them: the calling thread).
    assert most - before <= 1 + 4 * os.cpu_count(), (before, most)
    assert most - before >= 2, "the run was too short to see its threads"


# Calls that run for a minute or more without an interrupt (measured: simulate 6.5 us a
# period of this chattering motion; 4096 starts of 2e4 periods; up to 160 000 robots; the orbit
# search of a robot whose T0 is 5e9 times its force, refined to 1e9 evaluations).
LONG_CALLS = {
    "simulate": (capsubot.simulate, dict(HARMONIC, **STATE, periods=1e7)),
    # Many short starts: the interrupt is asked after every block of starts, so a block is
    # what an interrupt waits for (4096 starts of 2e4 periods: minutes in all).
    "attractors": (capsubot.attractors,
                   dict(ROBOT, starts="64x64", transient=10**4, record=10**4,
                        converged_tolerance=0.0)),
    "design": (capsubot.design,
               dict(m1=0.2, L=0.02, mu=0.3, e=0.7, force_amplitude=0.5, force_bias=0.1,
                    frequency_range=(1.0, 1000.0), scan_points=300)),
    "orbits": (capsubot.orbits, dict(alpha=0.3333, A=0.00527714, c=0.00105543, T0=3e7, e=0.7,
                                     max_evaluations=10**9)),
}
# Interrupted calls end within this: a start or a robot in progress is finished first. Far
# below the length of the calls, which would otherwise end with their KeyboardInterrupt.
INTERRUPT_LATENCY = 15.0


@pytest.mark.parametrize("name", LONG_CALLS)
def test_keyboard_interrupt_stops_a_long_call(name):
    fn, kwargs = LONG_CALLS[name]
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            fn(**kwargs)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 0.3 + INTERRUPT_LATENCY


def test_design_with_a_friction_bound_that_dwarfs_the_motor_answers_at_its_work_bound():
    """g = 1e300 makes T0 1e298 times the motor force: the orbit searches cannot resolve the
    robots, and the design stops after 8 of them (it ran past 100 s) instead of refining every
    robot's circle."""
    r = capsubot.design(m1=0.2, L=0.02, mu=0.3, g=1e300, e=0.7, force_amplitude=0.5,
                        force_bias=0.1, frequency=20.0)
    assert (r["status"], r["complete"], r["robots"]) == ("no_gait", False, 8)
    assert "the search stopped after 8 robots" in r["message"]


def test_keyboard_interrupt_stops_a_long_trajectory():
    """trajectory at its largest (1e7 samples, about 4 s) checks for signals between samples:
    interrupted after 0.1 s it ends long before it would have."""
    timer = threading.Timer(0.1, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            capsubot.trajectory(A=0.5, c=0.5, phi0=-2.9, samples=10**7)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 2.0
