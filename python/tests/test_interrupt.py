"""Ctrl-C (SIGINT) stops the calls whose library computations ask an interrupt: the optimisers
(P3 by multistart, P2 by an NLopt global algorithm, the reach search, the main job), Newton
shooting (periodic), the check from rest of solve(stability=True), design's from-rest
search and the basin map. Each call below runs for 15 s or more uninterrupted; a real SIGINT sent to the process
after 0.3 s must end it with KeyboardInterrupt within seconds, and the module must answer the
next call as before. (test_limits.py covers the other long calls: simulate, attractors,
design's one-impact search, orbits, trajectory.)"""

import os
import signal
import threading
import time

import pytest

import capsubot

# The SIGINT comes this long after the call starts.
SIGNAL_AFTER = 0.3
# The call ends within this after the SIGINT: the library asks its interrupt at every
# evaluation, Newton step, simulated period or block of starts (milliseconds apart; measured:
# 0.02 to 0.2 s after the SIGINT), generous for a loaded machine.
MAX_LATENCY = 10.0

# The chattering small orbit's robot (T0 = 0.1, e = 0.5), 4 us a simulated period.
HARMONIC = dict(A=0.05, c=0.02, phi0=-2.842, T0=0.1, e=0.5)
# The example robot of design (m1 = 0.2 kg, L = 20 mm, 0.5 sin + 0.1 N at 20 Hz).
ROBOT = dict(m1=0.2, L=0.02, mu=0.3, e=0.7, force_amplitude=0.5, force_bias=0.1, frequency=20.0)
# The paper's example orbit (README, capsubot solve): alpha = 0.35685746237742.
PAPER = dict(A=0.5, c=0.5, phi0=-2.944899971002)
# A short optimize: P1 for the force shape of test_optimize.py, checked from 2 x 2 starts.
SHORT_OPTIMIZE = dict(problem="phase", A=0.2, c=0.03, from_rest_starts="2x2")

# name: (function, arguments of a long call, arguments of a short one, a check of its result).
# Measured uninterrupted: the optimisers and design's from-rest search run to their time limits
# (30 s), periodic 40 s, solve 15 s.
LONG_CALLS = {
    # P3 with 16 harmonics and 1000 polishes, after its P2 seed: the multistart pipeline.
    "optimize_fourier": (capsubot.optimize, dict(problem="fourier", harmonics=16, starts=1000,
                                                 max_time=30),
                         SHORT_OPTIMIZE, lambda r: r["status"] == "ok"),
    # P2 from NLopt's DIRECT: the first evaluations are inside NLopt, the interrupt crosses it.
    "optimize_nlopt_global": (capsubot.optimize,
                              dict(problem="forcing", global_algorithm="GN_ORIG_DIRECT",
                                   global_evaluations=10**7, max_time=30),
                              SHORT_OPTIMIZE, lambda r: r["status"] == "ok"),
    # The seed's P2 ends after 0.1 s (0.15 s with its check): the SIGINT comes in the reach
    # search.
    "optimize_reach": (capsubot.optimize,
                       dict(problem="reach", starts=1, hops=0, max_time=0.1, reach_starts="8x8",
                            reach_evaluations=100000, reach_seconds=30),
                       SHORT_OPTIMIZE, lambda r: r["status"] == "ok"),
    "optimize_main_job": (capsubot.optimize, dict(max_time=30, reach_starts="8x8",
                                                  reach_evaluations=100000, reach_seconds=30),
                          SHORT_OPTIMIZE, lambda r: r["status"] == "ok"),
    # A transient of 1e7 periods from rest before Newton's method.
    "periodic": (capsubot.periodic, dict(HARMONIC, alpha=0.3, from_rest=(0.5, 0.0),
                                         transient=10**7),
                 dict(HARMONIC, alpha=0.3, from_rest=(0.5, 0.0), transient=100),
                 lambda r: r["status"] == "converged"),
    # The orbit checked from 360 000 starts from rest.
    "solve_stability": (capsubot.solve, dict(PAPER, stability=True, from_rest_starts="600x600"),
                        dict(PAPER, stability=True, from_rest_starts="2x2"),
                        lambda r: r["from_rest"]["starts"] == 4),
    # A basin map of 360 000 starts (200 + 100 periods each); its temporary folder goes too.
    "basins": (capsubot.basins, dict(HARMONIC, alpha=0.2792869076315278, starts="600x600"),
               dict(HARMONIC, alpha=0.2792869076315278, starts="2x2", transient=40, record=16),
               lambda r: len(r["columns"]["x0"]) == 4),
    # The one-impact design takes 0.1 s: the SIGINT comes in the from-rest search.
    "design_from_rest": (capsubot.design,
                         dict(ROBOT, from_rest=True, reach_evaluations=100000,
                              reach_local_evaluations=100000, reach_seconds=30),
                         dict(ROBOT), lambda r: r["status"] == "ok"),
}


@pytest.mark.parametrize("name", LONG_CALLS)
def test_sigint_stops_a_long_call_and_the_module_answers_the_next_one(name):
    fn, long_call, short_call, answers = LONG_CALLS[name]
    timer = threading.Timer(SIGNAL_AFTER, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            fn(**long_call)
    finally:
        timer.cancel()
    elapsed = time.monotonic() - start
    assert SIGNAL_AFTER <= elapsed < SIGNAL_AFTER + MAX_LATENCY, elapsed
    assert answers(fn(**short_call))
    assert capsubot.solve(**PAPER)["alpha"] == pytest.approx(0.35685746237742, rel=1e-12)
