"""Type stubs of the compiled module capsubot: every function with its keyword-only arguments,
their types and defaults, and what it returns; help(capsubot.<name>) gives the units and the
keys of the results. Installed as the stub-only package capsubot-stubs (PEP 561), which type
checkers and editors read for the module; the project's tests keep it in step with the module."""

from typing import Any, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

__version__: str

CONDITIONS: tuple[str, ...]
"""Names of the validity conditions: bit i of solve_grid's violations is CONDITIONS[i]."""

def solve(
    *,
    A: float | None = None,
    c: float,
    phi0: float | None = None,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    margin: float = 0.0,
    margin_stroke: float = 0.0,
    stick_margin: float = 0.0,
    stability: bool = False,
    from_rest_starts: str = "8x8",
    threads: int = 0,
) -> dict[str, Any]:
    """The one-impact periodic orbit and its validity (and stability, checked from rest)."""

def trajectory(
    *,
    A: float | None = None,
    c: float,
    phi0: float | None = None,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    samples: int = 1001,
) -> dict[str, NDArray[np.float64]]:
    """The state along one period of the one-impact orbit: arrays phi, x, u, v."""

def solve_grid(
    *,
    A: ArrayLike,
    c: ArrayLike,
    phi0: ArrayLike,
    T0: ArrayLike = 1.0,
    e: ArrayLike = 1.0,
    margin: ArrayLike = 0.0,
    margin_stroke: ArrayLike = 0.0,
    stick_margin: ArrayLike = 0.0,
    stability: bool = False,
    threads: int | None = None,
) -> dict[str, NDArray[Any]]:
    """solve at every point of arrays broadcast together: one array per column."""

def simulate(
    *,
    A: float | None = None,
    c: float | None = None,
    phi0: float | None = None,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    waveform: str | None = None,
    levels: Sequence[float] | None = None,
    switches: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    alpha: float | None = None,
    x0: float | None = None,
    u0: float | None = None,
    v0: float | None = None,
    y0: float = 0.0,
    from_orbit: bool = False,
    periods: float = 1.0,
    transient: float = 0.0,
    chatter_velocity: float = 1e-6,
    max_events_per_period: int = 100000,
    events: bool = False,
    trajectory: bool = False,
    samples_per_period: int = 100,
) -> dict[str, Any]:
    """The exact event-driven simulation: summary, and optionally events and trajectory."""

def optimize(
    *,
    problem: str | None = None,
    A: float | None = None,
    c: float | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    margin: float = 0.0,
    margin_stroke: float = 0.02,
    stick_margin: float = 0.02,
    bound: float | None = None,
    rho_max: float | None = None,
    stable: bool = False,
    max_time: float = 60.0,
    harmonics: int | None = None,
    global_algorithm: str = "multistart",
    local_algorithm: str = "LN_COBYLA",
    global_evaluations: int = 5000,
    hops: int = 20,
    starts: int | None = None,
    alpha: float | None = None,
    from_rest_starts: str = "8x8",
    reach_starts: str = "4x4",
    reach_evaluations: int = 150,
    reach_local_evaluations: int = 50,
    reach_seconds: float = 20.0,
    drive_evaluations: int = 400,
    drive_polishes: int = 4,
    drive_local_evaluations: int = 150,
    T0_range: tuple[float, float] | None = None,
    threads: int = 0,
) -> dict[str, Any]:
    """The fastest gait (problem 'phase', 'forcing', 'fourier'), the fastest motion from rest
    ('reach') or the main job (None)."""

def orbits(
    *,
    alpha: float,
    A: float | None = None,
    c: float,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    margin: float = 0.0,
    margin_stroke: float = 0.0,
    stick_margin: float = 0.0,
    max_evaluations: int = 4000000,
) -> list[dict[str, Any]]:
    """Every one-impact orbit of the robot with mass ratio alpha, sorted by phi0."""

def attractors(
    *,
    A: float | None = None,
    c: float | None = None,
    phi0: float | None = None,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    waveform: str | None = None,
    levels: Sequence[float] | None = None,
    switches: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    alpha: float,
    starts: str | None = None,
    n_x: int | None = None,
    n_psi: int | None = None,
    transient: int = 200,
    record: int = 100,
    max_period: int = 8,
    state_tolerance: float = 1e-6,
    converged_tolerance: float = 1e-11,
    chatter_velocity: float = 1e-6,
    max_events_per_period: int = 1000,
    threads: int = 0,
) -> dict[str, Any]:
    """The long-run motions reached from a grid of starts from rest, grouped into attractors."""

def periodic(
    *,
    A: float | None = None,
    c: float | None = None,
    phi0: float | None = None,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    waveform: str | None = None,
    levels: Sequence[float] | None = None,
    switches: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    alpha: float,
    x0: float | None = None,
    u0: float | None = None,
    v0: float | None = None,
    psi: float | None = None,
    from_rest: tuple[float, float] | None = None,
    transient: int | None = None,
    period: int | None = None,
    max_period: int = 8,
    step: float = 1e-6,
    chatter_velocity: float = 1e-6,
) -> dict[str, Any]:
    """A periodic motion of any kind by Newton shooting, with its multipliers."""

def continue_branch(
    *,
    A: float | None = None,
    c: float | None = None,
    phi0: float | None = None,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    waveform: str | None = None,
    levels: Sequence[float] | None = None,
    switches: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    alpha: float,
    param: str,
    from_: float,
    to: float,
    x0: float | None = None,
    u0: float | None = None,
    v0: float | None = None,
    psi: float | None = None,
    from_orbit: bool = False,
    switch: bool = False,
    param2: str | None = None,
    from2: float | None = None,
    to2: float | None = None,
    follow: str | None = None,
    max_points: int = 200,
    initial_step: float = 0.01,
    min_step: float = 1e-7,
    max_step: float = 0.05,
    max_period: int = 8,
    step: float = 1e-6,
    chatter_velocity: float = 1e-6,
) -> dict[str, Any]:
    """A periodic motion followed through one parameter, with its special points; on request
    the period-2p branch (switch) and a special point's curve in two parameters (param2)."""

def design(
    *,
    m1: float,
    L: float,
    mu: float,
    g: float = 9.81,
    e: float,
    force_amplitude: float | None = None,
    force_bias: float,
    force_cos: Sequence[float] | None = None,
    force_sin: Sequence[float] | None = None,
    frequency: float | None = None,
    frequency_range: tuple[float, float] | None = None,
    m2_range: tuple[float, float] | None = None,
    margin: float = 0.0,
    margin_stroke: float = 0.02,
    stick_margin: float = 0.02,
    rho_max: float = 0.9,
    scan_points: int = 64,
    from_rest: bool = False,
    from_rest_starts: str = "8x8",
    reach_starts: str = "4x4",
    reach_evaluations: int = 100,
    reach_local_evaluations: int = 30,
    reach_seconds: float = 20.0,
    threads: int = 0,
) -> dict[str, Any]:
    """A real robot in SI units: the inner mass (and frequency) of its fastest robust gait."""

def basins(
    *,
    A: float | None = None,
    c: float | None = None,
    phi0: float | None = None,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    waveform: str | None = None,
    levels: Sequence[float] | None = None,
    switches: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    alpha: float,
    starts: str = "64x64",
    plane: str = "x0-psi",
    psi: float = 0.0,
    u_min: float = -1.0,
    u_max: float = 1.0,
    transient: int = 200,
    record: int = 100,
    max_period: int = 8,
    state_tolerance: float = 1e-6,
    converged_tolerance: float = 1e-11,
    chatter_velocity: float = 1e-6,
    max_events_per_period: int = 1000,
    threads: int = 0,
) -> dict[str, Any]:
    """The attractor of every start of a plane of starts: the attractors of `capsubot basins
    --json`, the columns of its CSV map as NumPy arrays, and the provenance."""

def bifurcation(
    *,
    A: float | None = None,
    c: float | None = None,
    phi0: float | None = None,
    cos: Sequence[float] | None = None,
    sin: Sequence[float] | None = None,
    waveform: str | None = None,
    levels: Sequence[float] | None = None,
    switches: Sequence[float] | None = None,
    T0: float = 1.0,
    e: float = 1.0,
    alpha: float | None = None,
    param: str,
    from_: float,
    to: float,
    steps: int = 101,
    direction: str = "both",
    start: tuple[float, float] = (0.5, 0.0),
    over: str | None = None,
    no_analytic: bool = False,
    transient: int = 200,
    record: int = 100,
    max_period: int = 8,
    state_tolerance: float = 1e-6,
    converged_tolerance: float = 1e-11,
    chatter_velocity: float = 1e-6,
    max_events_per_period: int = 1000,
    threads: int = 0,
) -> dict[str, Any]:
    """The brute-force bifurcation diagram: the columns of `capsubot bifurcation`'s impacts
    (-o) and summary (--summary) CSVs as NumPy arrays, and the provenance."""
