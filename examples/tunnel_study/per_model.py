#!/usr/bin/python3
"""The tunnel study per joint model: over the seeds of each (L, b), the
fraction of realisations in which a block fell into the opening, the mean
peak crown displacement and the mean block count; and the same per trace
length L. Prints a table and writes per_model.json (the README's numbers).

Usage: per_model.py SUMMARY_CSV -o per_model.json
"""
import argparse
import csv
import json
from collections import OrderedDict

L_KEY, B_KEY = "joint_sets[0].mean_length", "joint_sets[0].mean_bridge"


def summarise(rows):
    ok = [r for r in rows if r["status"] == "ok"]
    n = len(ok)
    return {
        "cases": n,
        "p_fall": sum(int(r["failed"]) for r in ok) / n if n else None,
        "mean_crown_peak_mm": 1000 * sum(float(r["crown_peak"]) for r in ok) / n if n else None,
        "mean_blocks": sum(float(r["blocks"]) for r in ok) / n if n else None,
        "mean_block_area": sum(float(r["mean_area"]) for r in ok) / n if n else None,
    }


def main():
    p = argparse.ArgumentParser()
    p.add_argument("summary")
    p.add_argument("-o", dest="out", required=True)
    args = p.parse_args()
    rows = list(csv.DictReader(open(args.summary, newline="")))
    models, lengths = OrderedDict(), OrderedDict()
    for r in rows:
        models.setdefault(f"L{r[L_KEY]}_b{r[B_KEY]}", []).append(r)
        lengths.setdefault(f"L{r[L_KEY]}", []).append(r)
    result = {"models": {k: summarise(v) for k, v in models.items()},
              "lengths": {k: summarise(v) for k, v in lengths.items()},
              "all": summarise(rows)}
    with open(args.out, "w") as f:
        json.dump(result, f, indent=2)
    print(f"   {'model':<10} {'cases':>5} {'P(fall)':>8} {'crown peak (mm)':>16} {'blocks':>7}")
    for k, s in list(result["models"].items()) + list(result["lengths"].items()):
        print(f"   {k:<10} {s['cases']:>5} {s['p_fall']:>8.2f} {s['mean_crown_peak_mm']:>16.1f} {s['mean_blocks']:>7.1f}")


if __name__ == "__main__":
    main()
