#!/usr/bin/env python3
"""The fastest drives of `capsubot optimize --problem reach --harmonics K -o drives.json`.

    drives.py args JSON K        the force and mass flags of the winner of K harmonics
                                 (for `capsubot simulate` and `capsubot attractors`)
    drives.py force JSON CSV     one period of every winner's force: phi, F_K1, F_K2, ...
                                 (phi = motor phase minus phi0, as the JSON's drive counts it)
    drives.py speed K_CSV T0_CSV JSON...
                                 the best speed of every ladder step of every file (one file a
                                 T0): at T0 = 1 against K (K, mean_velocity in omega L), and
                                 against T0 for each K (T0, then the physical speed
                                 mean_velocity / sqrt(T0) in sqrt(mu g L) of K = 1, 2, ...;
                                 empty where a file's ladder stops below that K)
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


def speed(k_csv, t0_csv, paths):
    rows = {}
    for path in paths:
        with open(path) as f:
            j = json.load(f)
        rows[j["T0"]] = {s["harmonics"]: s["mean_velocity"] for s in j["ladder"]}
    source = "# the best speed from rest by number of harmonics K, from {}\n".format(" ".join(paths))
    with open(k_csv, "w") as out:
        out.write(source + "K,mean_velocity\n")
        for K, v in sorted(rows.get(1.0, {}).items()):
            out.write("{},{!r}\n".format(K, v))
    most = max(max(r) for r in rows.values())
    with open(t0_csv, "w") as out:
        out.write(source + "T0," + ",".join("speed_K{}".format(k) for k in range(1, most + 1)) + "\n")
        for T0, r in sorted(rows.items()):
            cells = [repr(r[k] / math.sqrt(T0)) if k in r else "" for k in range(1, most + 1)]
            out.write("{!r},{}\n".format(T0, ",".join(cells)))


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
    if len(argv) >= 5 and argv[1] == "speed":
        speed(argv[2], argv[3], argv[4:])
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
