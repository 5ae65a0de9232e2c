#!/usr/bin/python3
"""The probabilistic wedge against a plain Monte Carlo written here, apart
from dda: its own random numbers (numpy), its own Fisher draws (a rotation
of poles drawn about the vertical), and its own limit equilibrium (the
weight split along the two plane normals and the line of intersection by a
3 x 3 linear solve, instead of the cross products of tools/analysis).

The two estimates of the mean FS and of P(FS < 1) come from independent
samples, so they must agree within their sampling errors: the check fails
when a difference exceeds 4 standard errors of the difference (a chance of
6e-5 for a correct dda).

Usage: check_mc.py STUDY_OUT [--draws N] [--seed S] -o mc.json
"""
import argparse
import csv
import json
import math
import sys

import numpy as np

# The study file's laws (examples/probabilistic_wedge/study.yaml).
PLANES = [(51.4, 65.8), (51.4, 295.2)]
KAPPA = 100.0
PHI_MEAN, PHI_STD = 30.0, 4.0


def pole(dip, dip_direction):
    d, a = np.radians(dip), np.radians(dip_direction)
    return np.stack([np.sin(d) * np.sin(a), np.sin(d) * np.cos(a), np.cos(d) * np.ones_like(a)], axis=-1)


def fisher_poles(mean, kappa, n, rng):
    """n poles about `mean`: drawn about +z, then turned onto `mean` (Rodrigues)."""
    u = rng.uniform(size=n)
    cos_t = 1.0 + np.log(1.0 - u * (1.0 - math.exp(-2.0 * kappa))) / kappa
    sin_t = np.sqrt(np.clip(1.0 - cos_t**2, 0.0, None))
    az = rng.uniform(0.0, 2.0 * math.pi, size=n)
    p = np.stack([sin_t * np.cos(az), sin_t * np.sin(az), cos_t], axis=-1)
    z = np.array([0.0, 0.0, 1.0])
    axis = np.cross(z, mean)
    s, c = np.linalg.norm(axis), float(np.dot(z, mean))
    k = axis / s
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    rot = np.eye(3) + s * kx + (1 - c) * kx @ kx
    p = p @ rot.T
    return np.where(p[:, 2:3] < 0, -p, p)  # upward poles


def factor_of_safety(n1, n2, phi_deg):
    """FS under gravity of a wedge on two planes with upward normals n1, n2."""
    e = np.cross(n1, n2)
    e /= np.linalg.norm(e, axis=1, keepdims=True)
    e = np.where(e[:, 2:3] > 0, -e, e)  # down the line of intersection
    g = np.array([0.0, 0.0, -1.0])
    # Weight (per unit weight) = -N1 n1 - N2 n2 + D e: the planes push back
    # with N1, N2 and D drives the wedge down the line.
    a = np.stack([-n1, -n2, e], axis=-1)
    n1_, n2_, drive = np.linalg.solve(a, np.broadcast_to(g, n1.shape)[..., None])[..., 0].T
    tan_phi = np.tan(np.radians(phi_deg))
    fs = (n1_ + n2_) * tan_phi / drive
    # One plane in tension: the wedge leaves it and slides on the other
    # alone, FS = tan(phi) / tan(dip of that plane).
    dip1 = np.arccos(np.clip(n1[:, 2], -1, 1))
    dip2 = np.arccos(np.clip(n2[:, 2], -1, 1))
    fs = np.where(n2_ < 0, tan_phi / np.tan(dip1), fs)
    fs = np.where(n1_ < 0, tan_phi / np.tan(dip2), fs)
    return fs


def main():
    p = argparse.ArgumentParser()
    p.add_argument("study_out")
    p.add_argument("--draws", type=int, default=400000)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("-o", dest="out", required=True)
    args = p.parse_args()
    rng = np.random.default_rng(args.seed)
    n1 = fisher_poles(pole(*PLANES[0]), KAPPA, args.draws, rng)
    n2 = fisher_poles(pole(*PLANES[1]), KAPPA, args.draws, rng)
    phi = rng.normal(PHI_MEAN, PHI_STD, size=args.draws)
    fs = factor_of_safety(n1, n2, phi)
    mc_mean, mc_std, mc_pf = float(np.mean(fs)), float(np.std(fs, ddof=1)), float(np.mean(fs < 1))

    with open(f"{args.study_out}/summary.csv", newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "ok"]
    dda_fs = np.array([float(r["fs"]) for r in rows])
    n = len(dda_fs)
    dda_mean, dda_std, dda_pf = float(np.mean(dda_fs)), float(np.std(dda_fs, ddof=1)), float(np.mean(dda_fs < 1))

    se_mean = math.sqrt(dda_std**2 / n + mc_std**2 / args.draws)
    pooled = (dda_pf * n + mc_pf * args.draws) / (n + args.draws)
    se_pf = math.sqrt(pooled * (1 - pooled) * (1 / n + 1 / args.draws))
    z_mean = (dda_mean - mc_mean) / se_mean
    z_pf = (dda_pf - mc_pf) / se_pf if se_pf > 0 else 0.0
    result = {"dda": {"cases": n, "mean_fs": dda_mean, "std_fs": dda_std, "pf": dda_pf},
              "independent": {"draws": args.draws, "mean_fs": mc_mean, "std_fs": mc_std, "pf": mc_pf},
              "z_mean": z_mean, "z_pf": z_pf}
    with open(args.out, "w") as f:
        json.dump(result, f, indent=2)
    print(f"   dda study ({n} cases): mean FS {dda_mean:.4f}, std {dda_std:.4f}, P(FS < 1) {dda_pf:.4f}")
    print(f"   independent Monte Carlo ({args.draws} draws): mean FS {mc_mean:.4f}, std {mc_std:.4f}, "
          f"P(FS < 1) {mc_pf:.4f}")
    print(f"   differences: mean FS {z_mean:+.2f}, P(FS < 1) {z_pf:+.2f} standard errors (limit 4)")
    if abs(z_mean) > 4 or abs(z_pf) > 4:
        print("FAIL: the study and the independent Monte Carlo differ by more than their sampling error",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
