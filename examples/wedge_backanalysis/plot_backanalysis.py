#!/usr/bin/env python3
"""Figures of the wedge back-analysis (the seed report's Figures 19, 20, 21).

Reads what run.sh wrote in OUT: table.csv (the processed record), the
`dda sliding3d` histories sliding_degrading.csv, sliding_phi30.csv and
sliding_backfit.csv with their JSON summaries, measured.csv, backfit.json and
wedge*.json; writes into the output folder:

* displacement.png: table acceleration with the yield accelerations, the
  displacement down the line of intersection (measured, constant-friction
  analytical, back-fitted), the sliding speed, and a close-up of the first
  segment;
* friction_segments.png: true and back-fitted friction angle against cycles
  of motion, with the mean sliding speed per cycle and per segment;
* mu_lnv.png: friction coefficient against ln of the mean sliding speed per
  segment, with the regression mu = a + b ln(v / v_ref) and its R^2.
"""
import argparse
import json
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.ticker
import numpy as np

from friction_table import read_friction_table  # (this folder)

G = 9.81


def load_json(path):
    with open(path) as f:
        return json.load(f)


def history(out, name):
    """t, s (down the line, m), v (along the line, m/s), speed (m/s) of a sliding3d run."""
    h = np.genfromtxt(os.path.join(out, name + ".csv"), delimiter=",", names=True)
    e = np.array(load_json(os.path.join(out, name + ".json"))["reference_direction"], dtype=float)
    u = np.column_stack([h["ux"], h["uy"], h["uz"]])
    v = np.column_stack([h["vx"], h["vy"], h["vz"]])
    return h["t"], u @ e, v @ e, np.linalg.norm(v, axis=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("outdir")
    ap.add_argument("--friction-table", required=True, help="the true friction table")
    ap.add_argument("--freq", type=float, default=2.0, help="input frequency (Hz), for cycles of motion")
    ap.add_argument("-o", "--output", required=True, help="folder for the PNG files")
    a = ap.parse_args()
    out = a.outdir
    os.makedirs(a.output, exist_ok=True)

    rec = np.genfromtxt(os.path.join(out, "table.csv"), delimiter=",", names=True)
    meas = np.genfromtxt(os.path.join(out, "measured.csv"), delimiter=",", names=True)
    t_c, s_c, v_c, _ = history(out, "sliding_phi30")
    t_b, s_b, v_b, sp_b = history(out, "sliding_backfit")
    t_d, s_d, _, _ = history(out, "sliding_degrading")
    bf = load_json(os.path.join(out, "backfit.json"))
    segs = bf["segments"]
    true = np.array(read_friction_table(a.friction_table))
    yields = []
    for name in sorted(f for f in os.listdir(out) if f.startswith("wedge") and f.endswith(".json")):
        w = load_json(os.path.join(out, name))
        phi = 30.0 if name == "wedge.json" else float(name[len("wedge_phi"):-len(".json")])
        yields.append((phi, w["yield_acceleration_g"]))
    yields.sort(reverse=True)
    noise = float(np.std(meas["s"] - np.interp(meas["t"], t_d, s_d)))

    # ---- Figure 1: acceleration, displacement, speed, close-up (cf. seed Fig. 19)
    fig = plt.figure(figsize=(10, 12))
    gs = fig.add_gridspec(4, 1, height_ratios=[1.0, 1.6, 1.0, 1.3], hspace=0.35)
    ax_a = fig.add_subplot(gs[0])
    ax_s = fig.add_subplot(gs[1], sharex=ax_a)
    ax_v = fig.add_subplot(gs[2], sharex=ax_a)
    ax_z = fig.add_subplot(gs[3])

    ax_a.plot(rec["t"], rec["ay"] / G, color="0.3", lw=0.6, label="table acceleration $a_y$ (north +)")
    colors = ["tab:green", "tab:orange", "tab:red", "tab:purple"]
    for (phi, ky), c in zip(yields, colors):
        ax_a.axhline(-ky, color=c, ls="--", lw=1.0, label=f"$-k_y$ = {-ky:.4f} g ($\\varphi$ = {phi:g}°)")
    ax_a.set_ylabel("table accel. [g]")
    ax_a.set_title("V4 wedge on a shaking table: 2 Hz, 0.22 g along north, 5 s ramp "
                   "(the wedge slides north when $a_y < -k_y$)", fontsize=10)
    ax_a.set_ylim(-0.42, 0.26)
    ax_a.legend(loc="lower center", fontsize=7, ncol=4, framealpha=0.95)
    ax_a.grid(alpha=0.3)

    ax_s.plot(meas["t"], 1000 * meas["s"], ".", color="0.55", ms=2,
              label=f"measured (synthetic: degrading friction + noise sd {1000 * noise:.2f} mm)")
    ax_s.plot(t_c, 1000 * s_c, color="tab:blue", lw=1.5, label="3D analytical, constant $\\varphi$ = 30°")
    ax_s.plot(t_b, 1000 * s_b, color="tab:red", lw=1.2, ls="--", label="3D analytical, back-fitted segments")
    for s in segs:
        if s["t0"] > 0:
            for ax in (ax_s, ax_v, ax_z):
                ax.axvline(s["t0"], color="k", lw=0.6, ls=":")
    ymax = 1000 * max(s_b.max(), meas["s"].max())
    for s in segs:
        ax_s.text(0.5 * (s["t0"] + s["t1"]), 0.9 * ymax,
                  f"{s['t0']:g}–{s['t1']:g} s\n$\\varphi$ = {s['phi_deg']:.2f}°",
                  ha="center", va="top", fontsize=8,
                  bbox=dict(boxstyle="round", fc="white", ec="0.7", alpha=0.9))
    ax_s.set_ylabel("displacement down the\nline of intersection [mm]")
    ax_s.legend(loc="center left", fontsize=8)
    ax_s.grid(alpha=0.3)

    ax_v.plot(t_b, 1000 * v_b, color="tab:red", lw=0.7, label="back-fitted")
    ax_v.plot(t_c, 1000 * v_c, color="tab:blue", lw=0.7, label="constant $\\varphi$ = 30°")
    ax_v.set_ylabel("sliding velocity\nalong the line [mm/s]")
    ax_v.set_xlabel("time [s]")
    ax_v.set_xlim(0, t_b[-1])
    ax_v.legend(loc="upper left", fontsize=8)
    ax_v.grid(alpha=0.3)

    t1 = segs[0]["t1"]
    m = meas["t"] <= t1
    ax_z.plot(meas["t"][m], 1000 * meas["s"][m], ".", color="0.55", ms=2.5, label="measured")
    ax_z.plot(t_c[t_c <= t1], 1000 * s_c[t_c <= t1], color="tab:blue", lw=1.5, label="constant $\\varphi$ = 30°")
    ax_z.plot(t_b[t_b <= t1], 1000 * s_b[t_b <= t1], color="tab:red", lw=1.2, ls="--", label="back-fitted")
    ax_z.set_xlim(0, t1)
    ax_z.set_ylim(-0.6, 1000 * max(meas["s"][m].max(), s_c[t_c <= t1].max()) + 0.6)
    ax_z.set_title(f"close-up of the first segment (0–{t1:g} s)", fontsize=9)
    ax_z.set_xlabel("time [s]")
    ax_z.set_ylabel("displacement [mm]")
    ax_z.legend(loc="upper left", fontsize=8)
    ax_z.grid(alpha=0.3)
    fig.savefig(os.path.join(a.output, "displacement.png"), dpi=120, bbox_inches="tight")
    plt.close(fig)

    # ---- Figure 2: friction angle and mean sliding speed against cycles (cf. seed Fig. 20).
    # The speed has its own panel below: on a twin log axis its markers were
    # drawn over the friction-angle curves.
    fig, (ax, ax2) = plt.subplots(2, 1, sharex=True, figsize=(9, 6.5), gridspec_kw={"height_ratios": [3, 2]})
    ax.plot(true[:, 0] * a.freq, true[:, 1], color="k", lw=2.0, label="true (friction_true.csv)")
    xs, ys = [], []
    for s in segs:
        xs += [s["t0"] * a.freq, s["t1"] * a.freq]
        ys += [s["phi_deg"], s["phi_deg"]]
        ax.text(0.5 * (s["t0"] + s["t1"]) * a.freq, s["phi_deg"] + 0.25,
                f"{s['phi_deg']:.3f}°", ha="center", fontsize=9, color="tab:red")
    ax.plot(xs, ys, color="tab:red", lw=1.5, ls="--", label="back-fitted (dda backfit)")
    ax.set_ylabel("friction angle [°]")
    lo = min(true[:, 1].min(), min(s["phi_deg"] for s in segs))
    hi = max(true[:, 1].max(), max(s["phi_deg"] for s in segs))
    ax.set_ylim(lo - 1.5, hi + 1.5)
    ax.set_xlim(0, t_b[-1] * a.freq)
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    # mean speed per cycle of the back-fitted model (path length / period)
    period = 1.0 / a.freq
    ncyc = int(round(t_b[-1] / period))
    dt = np.diff(t_b)
    path = np.concatenate([[0.0], np.cumsum(0.5 * (sp_b[1:] + sp_b[:-1]) * dt)])
    edges = np.arange(ncyc + 1) * period
    pc = np.interp(edges, t_b, path)
    vcyc = np.diff(pc) / period
    centres = (np.arange(ncyc) + 0.5)
    ok = vcyc > 0
    ax2.semilogy(centres[ok], 1000 * vcyc[ok], "o", color="tab:blue", ms=3, mfc="none",
                 label="mean sliding speed per cycle (back-fitted model)")
    for i, s in enumerate(segs):
        ax2.semilogy([s["t0"] * a.freq, s["t1"] * a.freq], [1000 * s["mean_speed"]] * 2, color="tab:blue",
                     ls=":", lw=1.5, label="mean sliding speed per segment" if i == 0 else None)
    ax2.yaxis.set_major_locator(matplotlib.ticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    ax2.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda y, _: f"{y:g}"))
    ax2.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax2.set_ylabel("mean sliding speed [mm/s]")
    ax2.set_xlabel(f"cycles of motion ({a.freq:g} Hz)")
    ax2.grid(alpha=0.3, which="both")
    ax2.legend(loc="best", fontsize=8)
    ax.set_title("Friction per segment (same angle on both planes) and mean sliding speed", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(a.output, "friction_segments.png"), dpi=120)
    plt.close(fig)

    # ---- Figure 3: mu against ln v (cf. seed Fig. 21)
    vref = bf["v_ref"]
    r = bf["regression"]
    x = np.array([math.log(s["mean_speed"] / vref) for s in segs])
    mu = np.array([s["mu"] for s in segs])
    fig, ax = plt.subplots(figsize=(7, 5))
    xx = np.linspace(x.min() - 0.5, x.max() + 0.5, 50)
    unit = "1 mm/s" if abs(vref - 1e-3) < 1e-12 else f"{vref:g} m/s"
    ax.plot(xx, r["a"] + r["b"] * xx, color="k", lw=1.2,
            label=f"$\\mu$ = {r['a']:.4f} {r['b']:+.5f} ln(v / {unit}),  $R^2$ = {r['r2']:.3f}")
    ax.plot(x, mu, "D", ms=8, mfc="none", mec="tab:red", mew=1.5, label="back-fitted segments")
    mids = [0.5 * (s["t0"] + s["t1"]) for s in segs]
    tphi = [float(np.interp(tm, true[:, 0], true[:, 1])) for tm in mids]
    ax.plot(x, np.tan(np.radians(tphi)), "o", ms=4, color="k", label="true tan $\\varphi$ of the segment")
    for i, (xi, mi, s) in enumerate(zip(x, mu, segs)):
        above = mi >= r["a"] + r["b"] * xi  # write on the side away from the line
        ha = "left" if i == 0 else "right" if i == len(segs) - 1 else "center"
        ax.annotate(f"{s['t0']:g}–{s['t1']:g} s\n$\\varphi$ = {s['phi_deg']:.2f}°, v = {1000 * s['mean_speed']:.3g} mm/s",
                    (xi, mi), textcoords="offset points",
                    xytext=({"left": -8, "right": 8, "center": 0}[ha], 12 if above else -14),
                    ha=ha, va="bottom" if above else "top", fontsize=8)
    ax.set_xlabel(f"ln(v / {unit}), v = mean sliding speed of the segment")
    ax.set_ylabel("friction coefficient $\\mu$ = tan $\\varphi$")
    top = ax.secondary_xaxis("top", functions=(lambda z: np.exp(z) * vref * 1000,
                                               lambda v: np.log(np.maximum(v, 1e-12) / (vref * 1000))))
    top.set_xticks([t for t in (0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200)
                    if xx[0] <= math.log(t / (vref * 1000)) <= xx[-1]])
    top.set_xticklabels([f"{t:g}" for t in top.get_xticks()])
    top.set_xlabel("v [mm/s]")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower left", fontsize=8)
    ax.set_title("Friction coefficient against ln of the mean sliding speed", fontsize=10, pad=12)
    span = mu.max() - mu.min()
    ax.set_ylim(mu.min() - 0.3 * span, mu.max() + 0.2 * span)
    ax.set_xlim(xx[0] - 0.3, xx[-1] + 0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(a.output, "mu_lnv.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
