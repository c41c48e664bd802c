#!/usr/bin/env python3
"""The fastest drives of `capsubot optimize --problem reach --harmonics K -o drives.json`.

    drives.py args JSON K        the force and mass flags of the winner of K harmonics
                                 (for `capsubot simulate` and `capsubot attractors`)
    drives.py force JSON CSV     one period of every winner's force: phi, F_K1, F_K2, ...
                                 (phi = motor phase minus phi0, as the JSON's drive counts it)
"""
import json
import math
import sys


def ladder(path):
    with open(path) as f:
        return json.load(f)["ladder"]


def force(drive, t):
    s = t + drive["phi0"]
    return drive["c"] + sum(a * math.cos((k + 1) * s) + b * math.sin((k + 1) * s)
                            for k, (a, b) in enumerate(zip(drive["cos"], drive["sin"])))


def main(argv):
    if len(argv) == 4 and argv[1] == "args":
        step = ladder(argv[2])[int(argv[3]) - 1]
        d = step["drive"]
        print("--c {!r} --cos {} --sin {} --phi0 {!r} --alpha {!r}".format(
            d["c"], ",".join(repr(v) for v in d["cos"]), ",".join(repr(v) for v in d["sin"]),
            d["phi0"], step["alpha"]))
        return 0
    if len(argv) == 4 and argv[1] == "force":
        steps = ladder(argv[2])
        rows = 361
        with open(argv[3], "w") as out:
            out.write("# one period of the winners of {}\n".format(argv[2]))
            out.write("phi," + ",".join("F_K{}".format(s["harmonics"]) for s in steps) + "\n")
            for i in range(rows):
                t = 2.0 * math.pi * i / (rows - 1)
                out.write("{!r},".format(t) + ",".join(repr(force(s["drive"], t)) for s in steps) + "\n")
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
