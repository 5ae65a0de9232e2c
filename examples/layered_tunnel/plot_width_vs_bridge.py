#!/usr/bin/env python3
"""Mean block width against bridge / length (the seed report's Figure 6).

Reads OUT/sg_L{L}_b{b}/stats.json written by `dda run` and, for reference,
OUT/layered/stats.json (drawn as a horizontal line).
"""
import argparse
import glob
import json
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("outdir")
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    series = {}
    for path in glob.glob(os.path.join(a.outdir, "sg_L*_b*", "stats.json")):
        m = re.search(r"sg_L(\d+)_b(\d+)", path)
        L, b = int(m.group(1)), int(m.group(2))
        with open(path) as f:
            st = json.load(f)
        series.setdefault(L, []).append((b / L, st["width"]["mean"]))
    if not series:
        sys.exit("plot_width_vs_bridge: no sg_L*_b*/stats.json under " + a.outdir)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for L in sorted(series):
        pts = sorted(series[L])
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"Shi-Goodman, joint length L = {L} m")
    layered = os.path.join(a.outdir, "layered", "stats.json")
    if os.path.exists(layered):
        with open(layered) as f:
            w = json.load(f)["width"]["mean"]
        ax.axhline(w, color="k", ls="--", label=f"layered (FSI 1.3): {w:.2f} m")
    ax.set_xlabel("rock bridge / joint length (ratio)")
    ax.set_ylabel("mean block width (m)")
    ax.set_title("Mean block width against bridge / length")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.output, dpi=130)


if __name__ == "__main__":
    main()
