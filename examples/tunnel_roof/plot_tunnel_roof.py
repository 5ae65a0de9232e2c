#!/usr/bin/env python3
"""Figures and the loosened zone of the tunnel_roof example.

    plot_tunnel_roof.py OUT/results.h5 -o FIGDIR [--threshold 0.001]

Writes FIGDIR/displacement_history.png (vertical displacement against time
at the five measurement points) and FIGDIR/deformed_mesh.png (the blocks at
the last frame, coloured by vertical displacement, the loosened blocks
outlined), and prints the height of the loosened zone over the opening.

Loosened: a block above the roof (y > 16 m) and over the opening (centroid
within 25..35 m) that has settled more than the rock at the same height
away from the opening by more than the threshold (default 1 mm). The
reference is the median settlement of the blocks whose centroids lie within
0.5 m of the same height and 10 to 20 m to either side of the tunnel axis:
neither next to the opening nor within 10 m of the model's sides, which are
held and settle less. The whole mass settles elastically under its own weight (about 2 mm at mid-height here),
so an absolute threshold would measure that, not the loosening. The zone's
height is the highest top of a loosened block above the roof, also in units
of the opening width B = 10 m; the summary gives it for thresholds of 0.5,
1 and 2 mm too, to show how much it depends on that choice.
"""
import argparse
import json
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

ROOF_Y, X0, X1, B = 16.0, 25.0, 35.0, 10.0
AXIS_X, NEAR, FAR, SAME_HEIGHT = 30.0, 10.0, 20.0, 0.5


def centroid(poly):
    x, y = poly[:, 0], poly[:, 1]
    xs, ys = np.roll(x, -1), np.roll(y, -1)
    c = x * ys - xs * y
    a = c.sum() / 2
    return np.array([((x + xs) * c).sum() / (6 * a), ((y + ys) * c).sum() / (6 * a)])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results")
    ap.add_argument("-o", "--outdir", required=True)
    ap.add_argument("--threshold", type=float, default=0.001,
                    help="settlement beyond the far field at the same height that marks a loosened block, m")
    args = ap.parse_args()

    with h5py.File(args.results, "r") as f:
        fmt = f.attrs.get("format", b"")  # fixed-length text: h5py gives bytes
        if (fmt.decode() if isinstance(fmt, bytes) else fmt) != "dda-results":
            sys.exit(f"{args.results}: not a dda-results file")
        names = list(f["points/name"].asstr()[()])
        t = f["series/time"][()]
        u = f["series/displacement"][()]
        off = f["model/blocks/offsets"][()]
        v0 = f["model/blocks/vertices"][()]
        frames_t = f["frames/time"][()]
        v1 = f["frames/vertices"][-1]
        complete = int(f.attrs["complete"])
        stopped_at = float(f.attrs["time"])

    # Vertical displacement against time.
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for k, name in enumerate(names):
        ax.plot(t, 1000 * u[:, k, 1], label=name)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("vertical displacement (mm)")
    ax.set_title("Vertical displacement of the measurement points above the roof (x = 30.1 m)"
                 + ("" if complete else f"; run incomplete, stopped at t = {stopped_at:g} s"), fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc="center right")
    fig.tight_layout()
    fig.savefig(f"{args.outdir}/displacement_history.png", dpi=150)

    # Deformed mesh and loosened zone.
    polys0 = np.split(v0, off[1:-1])
    polys1 = np.split(v1, off[1:-1])
    dy = np.array([centroid(p1)[1] - centroid(p0)[1] for p0, p1 in zip(polys0, polys1)])
    c0 = np.array([centroid(p) for p in polys0])
    far = (np.abs(c0[:, 0] - AXIS_X) > NEAR) & (np.abs(c0[:, 0] - AXIS_X) < FAR)
    far_dy = np.array([np.median(dy[far & (np.abs(c0[:, 1] - y) <= SAME_HEIGHT)])
                       if np.any(far & (np.abs(c0[:, 1] - y) <= SAME_HEIGHT)) else 0.0 for y in c0[:, 1]])
    over = (c0[:, 1] > ROOF_Y) & (c0[:, 0] > X0) & (c0[:, 0] < X1)

    def zone(threshold):
        loose = over & (dy - far_dy < -threshold)
        height = max((p[:, 1].max() - ROOF_Y for p, l in zip(polys0, loose) if l), default=0.0)
        return loose, height

    loose, height = zone(args.threshold)

    fig, ax = plt.subplots(figsize=(10, 7))
    # Signed (settlement negative, heave positive): a diverging map centred on 0.
    top = float(np.max(np.abs(1000 * dy))) or 1.0
    pc = PolyCollection(polys1, array=1000 * dy, cmap="RdBu_r", edgecolors="0.3", linewidths=0.2)
    pc.set_clim(-top, top)
    ax.add_collection(pc)
    ax.add_collection(PolyCollection([p for p, l in zip(polys1, loose) if l], facecolors="none",
                                     edgecolors="#ff7f00", linewidths=1.0))  # not red: red is heave here
    fig.colorbar(pc, ax=ax, label="vertical displacement of the centroid (mm, up positive)")
    ax.axhline(ROOF_Y + height, color="#ff7f00", ls="--", lw=1.0)
    ax.set_xlim(10, 50)
    ax.set_ylim(0, 40)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    if complete:
        when = f"t = {frames_t[-1]:g} s (end of the run)"
    else:  # an interrupted run: the last frame saved may be far behind where it stopped
        when = (f"t = {frames_t[-1]:g} s, the last frame saved of an incomplete run "
                f"(stopped at t = {stopped_at:g} s)")
    ax.set_title(f"Deformed blocks over the tunnel, {when}\nloosened (> {1000 * args.threshold:g} mm beyond the "
                 f"far field, orange outline): height {height:.2f} m = {height / B:.2f} B", fontsize=10)
    fig.tight_layout()
    fig.savefig(f"{args.outdir}/deformed_mesh.png", dpi=150)

    summary = {"time": float(frames_t[-1]), "complete": bool(complete), "threshold_m": args.threshold,
               "loosened_blocks": int(loose.sum()), "loosened_height_m": float(height),
               "loosened_height_over_B": float(height / B),
               "loosened_height_over_B_by_threshold_mm": {f"{1000 * th:g}": float(zone(th)[1] / B)
                                                         for th in (0.0005, 0.001, 0.002)},
               "final_uy_m": {n: float(u[-1, k, 1]) for k, n in enumerate(names)}}
    print(json.dumps(summary, indent=2))


if __name__ == "__main__":
    main()
