#!/usr/bin/env python3
"""Synthetic shaking-table record: a sinusoid of one component, in g.

Writes a CSV `t, a_g` (s, g) sampled at --dt from 0 to --duration. The
linear ramp-up is left to `dda record --ramp`, which also places the
component on the table axis (`--axis y`, north) and converts it to m/s^2.
"""
import argparse

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--amplitude", type=float, required=True, help="amplitude (g)")
    ap.add_argument("--freq", type=float, required=True, help="frequency (Hz)")
    ap.add_argument("--duration", type=float, required=True, help="duration (s)")
    ap.add_argument("--dt", type=float, default=1e-3, help="sampling step (s)")
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    n = int(round(a.duration / a.dt))
    t = np.arange(n + 1) * a.dt
    acc = a.amplitude * np.sin(2.0 * np.pi * a.freq * t)
    with open(a.output, "w") as f:
        f.write(f"# {a.freq:g} Hz sinusoid, amplitude {a.amplitude:g} g (ramp applied by dda record)\n")
        f.write("t,a_g\n")
        for ti, ai in zip(t, acc):
            f.write(f"{ti:.6f},{ai:.9f}\n")


if __name__ == "__main__":
    main()
