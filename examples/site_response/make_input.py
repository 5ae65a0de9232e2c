#!/usr/bin/env python3
"""Writes the input record of the site_response example: 24 s of Gaussian
white noise (seeded, so every run is the same), sampled at 200 Hz, followed
by 2 s of rest, as t, ax, ay (m/s^2; x horizontal, y up; the vertical at
half the horizontal RMS, independent of it). The scenario band-passes it to
0.3-8 Hz and ramps it in over 0.5 s; its amplitude is small (a linear
response).

    make_input.py OUT.csv [--seed 7] [--rms 0.05]
"""
import argparse

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--rms", type=float, default=0.05, help="RMS of the noise before filtering, m/s^2")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    dt, duration, rest = 0.005, 24.0, 2.0
    t = np.arange(0.0, duration + rest + dt / 2, dt)
    ax = a.rms * rng.standard_normal(t.size)
    ay = 0.5 * a.rms * rng.standard_normal(t.size)
    ax[t > duration] = 0.0
    ay[t > duration] = 0.0
    with open(a.out, "w") as f:
        f.write("t,ax,ay\n")
        for ti, xi, yi in zip(t, ax, ay):
            f.write(f"{ti:.3f},{xi:.6e},{yi:.6e}\n")


if __name__ == "__main__":
    main()
