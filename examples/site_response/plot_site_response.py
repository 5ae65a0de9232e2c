#!/usr/bin/env python3
"""Figures and the check of the site_response example.

    plot_site_response.py OUT -o FIGDIR

Reads what run.sh left in OUT (history.csv, outcrop.csv, the spectra CSVs
and JSON summaries) and writes FIGDIR/velocities.png (the horizontal
velocity at the crest, the cliff edge and the plain, and the outcrop
motion), FIGDIR/spectral_ratios.png (crest/base and edge/base, and the
plain against the outcrop) and FIGDIR/hv.png (H/V at the crest and on the
plain). Prints a JSON summary.

Check (exit status 1 if it fails): the plain's receiver, 600 m from the
cliff foot on the free surface, must move with the outcrop motion, the
record integrated once: a vertically incident wave doubles at a free
surface, and the incident mode sends in half the outcrop velocity. The
median of the smoothed ratio |V_base| / |V_outcrop| over 0.5-5 Hz must lie
within 15 % of 1 (the mountain's scattered waves and the side boundaries
make it wander around 1 with frequency).
"""
import argparse
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def readable_log_axis(axis):
    """Ticks at 1, 2, 3 and 5 per decade as plain numbers (0.5, 1, 2, 3 Hz):
    matplotlib's default labels only the powers of ten, one tick here."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 3.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("-o", "--outdir", required=True)
    a = ap.parse_args()
    o = a.out
    h = table(f"{o}/history.csv")
    rec = table(f"{o}/outcrop.csv")

    fig, ax = plt.subplots(4, 1, figsize=(9, 8), sharex=True)
    for axis, (label, t, v) in zip(ax, [("outcrop (input)", rec["t"], rec["vx"]), ("plain (base)", h["t"], h["base.vx"]),
                                         ("cliff edge", h["t"], h["edge.vx"]), ("crest", h["t"], h["crest.vx"])]):
        axis.plot(t, 1000 * v, lw=0.6)
        axis.set_ylabel("vx (mm/s)")
        axis.set_title(label, fontsize=9, loc="left")
        axis.grid(alpha=0.3)
    ax[-1].set_xlabel("time (s)")
    fig.suptitle("Horizontal velocity: outcrop input and three receivers", fontsize=10)
    fig.tight_layout()
    fig.savefig(f"{a.outdir}/velocities.png", dpi=130)

    crest, edge = table(f"{o}/ssr_crest.csv"), table(f"{o}/ssr_edge.csv")
    base, outcrop = table(f"{o}/spectrum_base.csv"), table(f"{o}/spectrum_outcrop.csv")
    plain = base["amplitude"] / np.interp(base["f"], outcrop["f"], outcrop["amplitude"])
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.semilogx(crest["f"], crest["ratio"], label="crest / plain")
    ax.semilogx(edge["f"], edge["ratio"], label="cliff edge / plain")
    ax.semilogx(base["f"], plain, "k--", lw=0.8, label="plain / outcrop (the check)")
    ax.axhline(1, color="0.5", lw=0.5)
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("spectral ratio (horizontal velocity)")
    ax.set_title("Site amplification: spectral ratios of the horizontal velocity, Konno-Ohmachi smoothed (b = 40)",
                 fontsize=10)
    readable_log_axis(ax.xaxis)
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{a.outdir}/spectral_ratios.png", dpi=130)

    hv_c, hv_b = table(f"{o}/hv_crest.csv"), table(f"{o}/hv_base.csv")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.loglog(hv_c["f"], hv_c["hv"], label="crest")
    ax.loglog(hv_b["f"], hv_b["hv"], label="plain")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("H/V spectral ratio (horizontal / vertical velocity)")
    ax.set_title("H/V ratio at the crest and on the plain", fontsize=10)
    readable_log_axis(ax.xaxis)
    readable_log_axis(ax.yaxis)
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{a.outdir}/hv.png", dpi=130)

    band = (base["f"] >= 0.5) & (base["f"] <= 5.0)
    median = float(np.median(plain[band]))
    summary = {name: {k: json.load(open(f"{o}/{name}.json"))[k] for k in ("peak_frequency", "peak_value")}
               for name in ("ssr_crest", "ssr_edge", "hv_crest", "hv_base")}
    summary["plain_over_outcrop_median_0.5_5Hz"] = median
    print(json.dumps(summary, indent=2))
    if abs(median - 1) > 0.15:
        sys.exit(f"check failed: the plain moves with {median:.3f} times the outcrop motion (expected 1 within 15 %)")


if __name__ == "__main__":
    main()
