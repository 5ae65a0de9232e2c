#!/usr/bin/env python3
"""The figures of a study (`dda study`, docs/studies.md), from its
summary.csv:

* measure_<m>_vs_<v>.png: each measure against each value column, a box
  and the cases as dots per value for a grid key (few values), a scatter
  for a sampled key;
* exceedance_<m>.png: the fraction of cases whose measure exceeds x, against x;
* failure_vs_<v>.png: the probability of failure per value of each grid
  key, with its 95 % Wilson interval (when the study has a failure rule);
* fs_histogram.png (a wedge study): the histogram of the factor of safety
  with P(FS < 1).

    dda_study_plot.py summary.csv -o FIGURES --value KEY ... --measure NAME ...
        [--linked KEY,KEY ...] [--failure NAME below|above X] [--wedge]

--linked names key paths that change together (one grid axis): they are
drawn once more as one axis, a value per combination ("5, 1").
"""

import argparse
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_io  # noqa: E402
from plot_io import fail, save_atomically  # noqa: E402

plot_io.PROG = "dda_study_plot.py"

try:
    import numpy as np
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as exc:  # pragma: no cover - depends on the machine
    fail(f"needs numpy and matplotlib ({exc}); run it with /usr/bin/python3")

GRID_VALUES = 20  # a column with at most this many distinct values is drawn per value


def file_part(name):
    return re.sub(r"[^A-Za-z0-9]+", "_", name).strip("_")


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def wilson(k, n, z=1.959963984540054):
    """95 % Wilson score interval of k successes in n (Wilson 1927)."""
    if n == 0:
        return 0.0, 1.0
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z / (1 + z * z / n) * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return max(0.0, centre - half), min(1.0, centre + half)


def read_summary(path):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as exc:
        fail(f"{path}: cannot read: {exc.strerror or exc}")
    return [r for r in rows if r.get("status") == "ok"]


def ordered_values(texts):
    """Distinct values in numeric order when they are all numbers, else as first seen."""
    distinct = list(dict.fromkeys(texts))
    if all(not math.isnan(number(t)) for t in distinct):
        distinct.sort(key=number)
    return distinct


def turn_labels(ax, labels):
    """Many or long tick labels are turned so that they do not overlap."""
    if len(labels) > 8 or max(len(t) for t in labels) > 6:
        for label in ax.get_xticklabels():
            label.set_rotation(45)
            label.set_horizontalalignment("right")


def measure_against(rows, value, measure, out):
    texts = [r[value] for r in rows]
    ys = np.array([number(r[measure]) for r in rows])
    fig, ax = plt.subplots(figsize=(6, 4))
    distinct = ordered_values(texts)
    if len(distinct) <= GRID_VALUES:
        groups = [ys[[t == d for t in texts]] for d in distinct]
        groups = [g[np.isfinite(g)] for g in groups]
        ax.boxplot(groups, labels=distinct, showfliers=False)
        turn_labels(ax, distinct)
        rng = np.random.default_rng(0)  # a fixed jitter: the figure is the same on every run
        for i, g in enumerate(groups):
            ax.plot(i + 1 + rng.uniform(-0.15, 0.15, len(g)), g, ".", color="tab:blue", alpha=0.5, markersize=4)
    else:
        xs = np.array([number(t) for t in texts])
        ax.plot(xs, ys, ".", alpha=0.4, markersize=3)
    ax.set_xlabel(value)
    ax.set_ylabel(measure)
    ax.set_title(f"{measure} ({len(rows)} cases)")
    save_atomically(fig, os.path.join(out, f"measure_{file_part(measure)}_vs_{file_part(value)}.png"))
    plt.close(fig)


def exceedance(rows, measure, out):
    ys = np.sort(np.array([number(r[measure]) for r in rows]))
    ys = ys[np.isfinite(ys)]
    if len(ys) == 0:
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    # P(X > y_i) for the sorted values: (n - i - 1) / n, a step at each case.
    p = 1.0 - np.arange(1, len(ys) + 1) / len(ys)
    ax.step(ys, p, where="post")
    ax.set_xlabel(measure)
    ax.set_ylabel(f"P({measure} > x)")
    ax.set_ylim(0, 1.02)
    ax.set_title(f"exceedance of {measure} ({len(ys)} cases)")
    ax.grid(alpha=0.3)
    save_atomically(fig, os.path.join(out, f"exceedance_{file_part(measure)}.png"))
    plt.close(fig)


def failed(rows, rule):
    measure, side, limit = rule
    out = []
    for r in rows:
        v = number(r[measure])
        out.append(None if math.isnan(v) else (v < limit if side == "below" else v > limit))
    return out


def failure_against(rows, value, rule, out):
    texts = [r[value] for r in rows]
    distinct = ordered_values(texts)
    if len(distinct) > GRID_VALUES:
        return
    flags = failed(rows, rule)
    ps, los, his = [], [], []
    for d in distinct:
        f = [x for t, x in zip(texts, flags) if t == d and x is not None]
        k, n = sum(f), len(f)
        lo, hi = wilson(k, n)
        ps.append(k / n if n else math.nan)
        los.append(lo)
        his.append(hi)
    ps, los, his = np.array(ps), np.array(los), np.array(his)
    fig, ax = plt.subplots(figsize=(6, 4))
    x = np.arange(len(distinct))
    ax.errorbar(x, ps, yerr=[ps - los, his - ps], fmt="o", capsize=4)
    ax.set_xticks(x, distinct)
    turn_labels(ax, distinct)
    ax.set_ylim(-0.02, 1.02)
    measure, side, limit = rule
    ax.set_xlabel(value)
    ax.set_ylabel(f"P({measure} {'<' if side == 'below' else '>'} {limit:g})")
    ax.set_title("probability of failure, 95 % Wilson intervals")
    ax.grid(alpha=0.3)
    save_atomically(fig, os.path.join(out, f"failure_vs_{file_part(value)}.png"))
    plt.close(fig)


def fs_histogram(rows, out):
    fs = np.array([number(r["fs"]) for r in rows])
    fs = fs[np.isfinite(fs)]
    if len(fs) == 0:
        return
    pf = float(np.mean(fs < 1.0))
    lo, hi = wilson(int(np.sum(fs < 1.0)), len(fs))
    fig, ax = plt.subplots(figsize=(6, 4))
    # The few wedges whose line of intersection is nearly flat have a huge FS:
    # the bins span the lowest 99.5 % so that the rest keeps its detail.
    top = float(np.percentile(fs, 99.5))
    ax.hist(fs, bins=50, range=(0, top), color="tab:gray", edgecolor="white")
    above = int(np.sum(fs > top))
    if above:
        ax.text(0.98, 0.95, f"{above} cases above {top:.3g}", transform=ax.transAxes, ha="right", va="top")
    ax.axvline(1.0, color="tab:red")
    ax.set_xlabel("factor of safety")
    ax.set_ylabel("cases")
    ax.set_title(f"FS of {len(fs)} wedges: P(FS < 1) = {pf:.3g} ({lo:.3g} to {hi:.3g})")
    save_atomically(fig, os.path.join(out, "fs_histogram.png"))
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="dda_study_plot.py")
    parser.add_argument("summary")
    parser.add_argument("-o", dest="out", required=True)
    parser.add_argument("--value", action="append", default=[])
    parser.add_argument("--measure", action="append", default=[])
    parser.add_argument("--linked", action="append", default=[])
    parser.add_argument("--failure", nargs=3)
    parser.add_argument("--wedge", action="store_true")
    args = parser.parse_args(argv)
    rows = read_summary(args.summary)
    if not rows:
        return 0  # no case succeeded: nothing to draw
    for name in args.value + args.measure:
        if name not in rows[0]:
            fail(f"{args.summary}: has no column '{name}'")
    os.makedirs(args.out, exist_ok=True)
    for group in args.linked:
        keys = group.split(",")
        for name in keys:
            if name not in rows[0]:
                fail(f"{args.summary}: has no column '{name}'")
        axis = ", ".join(keys)
        for r in rows:
            r[axis] = ", ".join(r[k] for k in keys)
        args.value.append(axis)
    rule = None
    if args.failure:
        rule = (args.failure[0], args.failure[1], float(args.failure[2]))
    for m in args.measure:
        for v in args.value:
            measure_against(rows, v, m, args.out)
        exceedance(rows, m, args.out)
    if rule:
        for v in args.value:
            failure_against(rows, v, rule, args.out)
    if args.wedge and "fs" in args.measure:
        fs_histogram(rows, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
