#!/usr/bin/env python3
"""The synthetic "measurement": a `dda sliding3d` history projected on the
line of intersection, with optional seeded Gaussian noise.

Reads the sliding3d CSV (t, ux, uy, uz, ...) and its JSON summary (for
`reference_direction`, the unit vector down the line of intersection) and
writes `t, s` (s, m): the input `dda backfit --measured` expects.
"""
import argparse
import json

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("history", help="dda sliding3d CSV")
    ap.add_argument("summary", help="dda sliding3d --json output")
    ap.add_argument("--noise", type=float, default=0.0, help="standard deviation of the noise (m)")
    ap.add_argument("--seed", type=int, default=2026)
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    with open(a.summary) as f:
        e = np.array(json.load(f)["reference_direction"], dtype=float)
    h = np.genfromtxt(a.history, delimiter=",", names=True)
    s = np.column_stack([h["ux"], h["uy"], h["uz"]]) @ e
    if a.noise > 0:
        s = s + np.random.default_rng(a.seed).normal(0.0, a.noise, s.size)
    with open(a.output, "w") as f:
        f.write("t,s\n")
        for ti, si in zip(h["t"], s):
            f.write(f"{ti:.6f},{si:.9e}\n")
    print(f"measured: {s.size} samples, {h['t'][0]:g} .. {h['t'][-1]:g} s, "
          f"final s = {1000 * s[-1]:.2f} mm, noise sd {1000 * a.noise:g} mm (seed {a.seed})")


if __name__ == "__main__":
    main()
