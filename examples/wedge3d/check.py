#!/usr/bin/python3
"""Checks the wedge of wedge3d.yaml against geometry and block theory.

The wedge is bounded by A, B, the ground z = 10 and the slope face through
(0, 10, 10) dipping 70 deg north. Its corners are the intersections of three
of those planes: computed here with numpy, independently of the cutter.
Expected (docs/validation.md, V4): the body slides on both planes
along trend 000.5 deg, plunge 27.63 deg. Exit status 1 if any check fails.
"""
import math
import sys

import h5py
import numpy as np


def normal(dip, dipdir):
    d, a = math.radians(dip), math.radians(dipdir)
    return np.array([math.sin(d) * math.sin(a), math.sin(d) * math.cos(a), math.cos(d)])


def meet(planes):
    n = np.array([p[0] for p in planes])
    return np.linalg.solve(n, np.array([p[0] @ p[1] for p in planes]))


T = np.array([0.0, 0, 10])
A, B = (normal(51.4, 65.8), T), (normal(51.4, 295.2), T)
top, face = (np.array([0.0, 0, 1]), T), (normal(70, 0), np.array([0.0, 10, 10]))
corners = [meet([A, B, top]), meet([A, B, face]), meet([A, top, face]), meet([B, top, face])]
p0 = corners[0]
volume = abs(np.dot(corners[1] - p0, np.cross(corners[2] - p0, corners[3] - p0))) / 6
centroid = np.mean(corners, axis=0)

folder = sys.argv[1] if len(sys.argv) > 1 else "out"
with h5py.File(f"{folder}/blocks3d.h5") as f:
    cen = f["blocks/centroid"][()]
    body = f["blocks/body"][()]
    bvol = f["bodies/volume"][()]
    mode = f["bodies/removability"][()]
    sdir = f["bodies/sliding_direction"][()]

# The body whose volume-weighted centroid is the wedge's.
k = int(np.argmin([np.linalg.norm(cen[body == b].mean(axis=0) - centroid) for b in range(len(bvol))]))
ok = True


def check(name, got, want, tol):
    global ok
    good = abs(got - want) <= tol
    ok &= good
    print(f"{name:34s} {got:12.6f}  expected {want:12.6f}  {'ok' if good else 'FAILED'}")


d = sdir[k]
check("wedge volume (m^3)", bvol[k], volume, 1e-9 * volume)
check("sliding plunge (deg)", math.degrees(math.asin(-d[2])), 27.63, 0.01)
check("sliding trend (deg)", math.degrees(math.atan2(d[0], d[1])) % 360, 0.5, 0.05)
check("mode (5 = slides on two faces)", mode[k], 5, 0)
others = [m for b, m in enumerate(mode) if b != k and m >= 3]
print(f"other bodies gravity moves: {len(others)}")
sys.exit(0 if ok else 1)
