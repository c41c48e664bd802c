#!/usr/bin/env python3
"""Speed of solve_grid against the command line's sweep on the same 1,000,000 points.

Usage (from the repository root, after building):
    PYTHONPATH=build/python /usr/bin/python3 python/bench/solve_grid_bench.py \\
        [--cli build/capsubot] [--points 1000000] [--threads 2] [--repeats 5]

Both compute the orbit and its exact validity at phi0 = -pi..pi (A = c = 0.5, T0 = e = 1):
`capsubot sweep --grid phi0=-pi:pi:N --A 0.5 --c 0.5 -o FILE --threads T` (which also
formats and writes the CSV) and capsubot.solve_grid(A=0.5, c=0.5, phi0=..., threads=T).
Each is repeated and the best wall time is reported: on a shared machine the best run is the
one least disturbed by others. Not a test: it asserts nothing.
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import capsubot


def best_time(run, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times), times


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default="build/capsubot", help="the built capsubot program")
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()

    # The sweep's grid: n equally spaced values from -pi to pi inclusive.
    phi0 = np.linspace(-np.pi, np.pi, args.points)
    grid, grid_times = best_time(
        lambda: capsubot.solve_grid(A=0.5, c=0.5, phi0=phi0, threads=args.threads),
        args.repeats)
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "sweep.csv")
        command = [args.cli, "sweep", "--grid", f"phi0=-pi:pi:{args.points}", "--A", "0.5",
                   "--c", "0.5", "-o", out, "--threads", str(args.threads)]
        sweep, sweep_times = best_time(lambda: subprocess.run(command, check=True),
                                       args.repeats)

    print(f"points {args.points}, threads {args.threads}, best of {args.repeats} runs")
    print(f"  solve_grid   {grid:.3f} s   ({args.points / grid:,.0f} points/s)   "
          f"runs: {', '.join(f'{t:.3f}' for t in grid_times)}")
    print(f"  cli sweep    {sweep:.3f} s   ({args.points / sweep:,.0f} points/s)   "
          f"runs: {', '.join(f'{t:.3f}' for t in sweep_times)}")
    print(f"  solve_grid / sweep = {grid / sweep:.2f} (target: at most 3)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
