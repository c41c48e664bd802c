"""solve_grid: the same numbers as solve at every point, NumPy broadcasting, threads."""

import math
import os
import signal
import threading

import numpy as np
import pytest

import capsubot

COLUMNS = ["phi1", "alpha", "u", "v_plus", "I", "v_mean", "x_min", "x_max"]
RANDOM_POINTS = 1000


def as_array_value(value):
    """A solve() value as solve_grid stores it (None -> NaN)."""
    return math.nan if value is None else value


def same(a, b):
    """Bit-for-bit equal or both NaN: solve_grid calls the same library code as solve."""
    return (math.isnan(a) and math.isnan(b)) or a == b


def random_points(rng, n):
    """Half over the whole domain (mostly invalid or absent orbits), half around the valid
    orbit A = 0.05, c = 0.02, phi0 = -2.842, T0 = 0.1 (mostly valid ones)."""
    m = n // 2
    broad = dict(A=rng.uniform(0.0, 1.0, m), c=rng.uniform(-0.1, 0.6, m),
                 phi0=rng.uniform(-math.pi, math.pi, m), T0=rng.uniform(0.05, 1.5, m),
                 e=rng.uniform(0.0, 1.0, m), margin=rng.uniform(0.0, 0.3, m))
    near = dict(A=rng.uniform(0.04, 0.06, n - m), c=rng.uniform(0.015, 0.025, n - m),
                phi0=rng.uniform(-3.1, -2.6, n - m), T0=np.full(n - m, 0.1),
                e=rng.uniform(0.3, 0.7, n - m), margin=rng.uniform(0.0, 0.3, n - m))
    return {k: np.concatenate([broad[k], near[k]]) for k in broad}


def test_agrees_with_solve_on_random_points():
    rng = np.random.default_rng(20240615)
    p = random_points(rng, RANDOM_POINTS)
    g = capsubot.solve_grid(**p, stability=True, threads=2)
    kinds = {}
    for i in range(RANDOM_POINTS):
        d = capsubot.solve(**{k: float(v[i]) for k, v in p.items()}, stability=True)
        for key in COLUMNS + ["spectral_radius"]:
            assert same(float(g[key][i]), as_array_value(d[key])), (i, key, g[key][i], d[key])
        assert bool(g["valid"][i]) == d["valid"]
        assert bool(g["stable"][i]) == d["stable"]
        names = [n for bit, n in enumerate(capsubot.CONDITIONS) if g["violations"][i] >> bit & 1]
        assert names == d["violations"]
        kinds[(d["status"], d["valid"])] = kinds.get((d["status"], d["valid"]), 0) + 1
    # The sample covers valid, invalid and absent orbits (each many times).
    assert sorted(kinds) == [("no_mass_ratio", False), ("non_positive_mean_force", False),
                             ("ok", False), ("ok", True)]
    assert min(kinds.values()) >= 20, kinds


def test_broadcasts_like_numpy():
    phi0 = np.linspace(-math.pi, math.pi, 7)
    c = np.array([[0.02], [0.03], [0.05]])
    g = capsubot.solve_grid(A=0.2, c=c, phi0=phi0, T0=[1.0], threads=1)
    assert g["I"].shape == (3, 7) and g["valid"].shape == (3, 7) and g["valid"].dtype == bool
    for i in range(3):
        for j in range(7):
            d = capsubot.solve(A=0.2, c=float(c[i, 0]), phi0=float(phi0[j]))
            assert same(g["I"][i, j], as_array_value(d["I"]))


def test_scalars_give_zero_dimensional_arrays():
    g = capsubot.solve_grid(A=0.5, c=0.5, phi0=-2.944899971002)
    assert g["alpha"].shape == () and "spectral_radius" not in g
    assert float(g["alpha"]) == capsubot.solve(A=0.5, c=0.5, phi0=-2.944899971002)["alpha"]


def test_empty_and_strided_inputs():
    assert capsubot.solve_grid(A=0.5, c=0.5, phi0=np.empty((0, 4)))["I"].shape == (0, 4)
    phi0 = np.linspace(-3, 3, 40)
    every_other = capsubot.solve_grid(A=0.2, c=0.03, phi0=phi0[::2])["I"]  # a strided view
    np.testing.assert_array_equal(every_other, capsubot.solve_grid(A=0.2, c=0.03,
                                                                   phi0=phi0)["I"][::2])
    fortran = np.asfortranarray(np.linspace(0.01, 0.05, 6).reshape(2, 3))
    np.testing.assert_array_equal(capsubot.solve_grid(A=0.2, c=fortran, phi0=-2.6)["I"],
                                  capsubot.solve_grid(A=0.2, c=fortran.copy(order="C"),
                                                      phi0=-2.6)["I"])
    ints = capsubot.solve_grid(A=0, c=1, phi0=[0, 1], T0=2)  # integers are converted
    assert ints["I"].shape == (2,) and ints["I"].dtype == np.float64


def test_any_thread_count_gives_the_same_arrays():
    phi0 = np.linspace(-math.pi, math.pi, 10001)  # several blocks of points
    one = capsubot.solve_grid(A=0.5, c=0.5, phi0=phi0, stability=True, threads=1)
    for threads in (2, 3, None):
        other = capsubot.solve_grid(A=0.5, c=0.5, phi0=phi0, stability=True, threads=threads)
        assert sorted(other) == sorted(one)
        for key, column in one.items():
            np.testing.assert_array_equal(other[key], column)


def test_shapes_that_do_not_broadcast_name_both_inputs():
    with pytest.raises(ValueError) as err:
        capsubot.solve_grid(A=[0.1, 0.2, 0.3], c=[0.1, 0.2], phi0=0.0)
    assert str(err.value) == ("A of shape (3,) and c of shape (2,) cannot be broadcast together "
                              "(NumPy rules)")


def test_a_rejected_point_names_its_index_and_the_rule():
    T0 = np.ones((2, 3))
    T0[1, 2] = -1.0
    T0[1, 0] = 0.0
    with pytest.raises(ValueError) as err:
        capsubot.solve_grid(A=0.1, c=0.05, phi0=0.0, T0=T0, threads=2)
    # The first bad point in C order, whatever the threads did.
    assert str(err.value) == ("at index (1, 0): friction bound T0 = 0 is invalid: expected a "
                              "finite T0 > 0")
    with pytest.raises(ValueError, match=r"^at index \(2,\): A = nan is invalid: expected a "
                                         r"finite number$"):
        capsubot.solve_grid(A=[0.1, 0.2, math.nan], c=0.05, phi0=0.0)
    with pytest.raises(ValueError, match=r"^at index \(0,\): A = -0.1 is invalid: expected "
                                         r"A >= 0$"):
        capsubot.solve_grid(A=[-0.1], c=0.05, phi0=0.0)
    with pytest.raises(ValueError, match=r"^at index \(1,\): phi0 = inf is invalid"):
        capsubot.solve_grid(A=0.1, c=0.05, phi0=[0.0, math.inf])
    with pytest.raises(ValueError, match=r"^at index \(\): restitution e = 1.5 is invalid: "
                                         r"expected 0 <= e <= 1$"):
        capsubot.solve_grid(A=0.1, c=0.05, phi0=0.0, e=1.5)


@pytest.mark.parametrize("threads", [0, -3, 1025])
def test_bad_thread_counts_are_rejected(threads):
    with pytest.raises(ValueError) as err:
        capsubot.solve_grid(A=0.1, c=0.05, phi0=0.0, threads=threads)
    assert str(err.value) == (f"threads = {threads} is invalid: expected 1 <= threads <= 1024 "
                              "(None: all cores)")


def test_inputs_that_are_not_numbers_raise_type_error():
    with pytest.raises(TypeError, match="^phi0 must be a number or an array of numbers"):
        capsubot.solve_grid(A=0.1, c=0.05, phi0="north")
    with pytest.raises(TypeError, match="^c must be a number or an array of numbers"):
        capsubot.solve_grid(A=0.1, c=[[0.1, 0.2], [0.3]], phi0=0.0)
    with pytest.raises(TypeError):
        capsubot.solve_grid(A=0.1, c=0.05, phi0=0.0, threads=1.5)


def test_ctrl_c_interrupts_a_long_grid():
    # About 2 s of work on one thread; SIGINT arrives after 50 ms.
    phi0 = np.linspace(-math.pi, math.pi, 2_000_000)
    timer = threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            capsubot.solve_grid(A=0.5, c=0.5, phi0=phi0, stability=True, threads=1)
    finally:
        timer.join()
    assert capsubot.solve_grid(A=0.5, c=0.5, phi0=phi0[:3])["I"].shape == (3,)  # still usable
