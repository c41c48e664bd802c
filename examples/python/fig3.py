#!/usr/bin/env python3
"""Fig. 3 of the paper from Python: the step I per period against the impact phase phi0.

Panel 1: the paper's example, F = 0.5 sin(phi + phi0) + 0.5, T0 = 1 (no valid orbit: the inner
body would leave the shell). Panel 2: A = 0.2, c = 0.03, T0 = 1, which has valid orbits. The
curve is every orbit that exists; dots mark the valid ones (green when also stable).

Usage: PYTHONPATH=build/python /usr/bin/python3 examples/python/fig3.py fig3.png [--points N]
"""

import argparse

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import capsubot  # noqa: E402

CASES = [
    ("paper's example: A = c = 0.5, T0 = 1", dict(A=0.5, c=0.5, T0=1.0)),
    ("a case with valid orbits: A = 0.2, c = 0.03, T0 = 1", dict(A=0.2, c=0.03, T0=1.0)),
]


def main():
    parser = argparse.ArgumentParser(description="Fig. 3: I against phi0 (PNG)")
    parser.add_argument("png", help="the PNG file to write")
    parser.add_argument("--points", type=int, default=7201, help="phases from -pi to pi")
    args = parser.parse_args()

    phi0 = np.linspace(-np.pi, np.pi, args.points)
    fig, axes = plt.subplots(2, 1, figsize=(9, 9), constrained_layout=True)
    for ax, (title, force) in zip(axes, CASES):
        g = capsubot.solve_grid(phi0=phi0, **force, stability=True)
        valid = g["valid"]
        stable = valid & g["stable"]
        ax.plot(phi0, g["I"], color="0.5", lw=1.2, label="every orbit (invalid ones included)")
        ax.plot(phi0[valid & ~stable], g["I"][valid & ~stable], ".", color="tab:orange", ms=3,
                label=f"valid orbit, unstable ({np.count_nonzero(valid & ~stable)} phases)")
        ax.plot(phi0[stable], g["I"][stable], ".", color="tab:green", ms=3,
                label=f"valid and stable orbit ({np.count_nonzero(stable)} phases)")
        if valid.any():
            best = np.nanargmax(np.where(valid, g["I"], np.nan))
            ax.plot(phi0[best], g["I"][best], "s", mfc="none", mec="k", ms=10, mew=1.5,
                    label=f"best valid: I = {g['I'][best]:.4g} at phi0 = {phi0[best]:.3f}")
        else:
            ax.plot([], [], " ", label="no valid orbit at any phase")
        ax.set_title(title)
        ax.set_xlabel("impact phase phi0 [rad]")
        ax.set_ylabel("step per period I [L]")
        ax.set_xlim(-np.pi, np.pi)
        ax.set_xticks([-np.pi, -np.pi / 2, 0, np.pi / 2, np.pi],
                      ["-pi", "-pi/2", "0", "pi/2", "pi"])
        ax.grid(True, alpha=0.4)
        ax.legend(loc="best", fontsize=9)
    fig.suptitle("Fig. 3: step I of the one-impact orbit against the impact phase (e = 1)")
    fig.savefig(args.png, dpi=120)
    print(f"written: {args.png}")


if __name__ == "__main__":
    main()
