#!/usr/bin/python3
"""Reads the runs of examples/friction_instabilities/run.sh, compares each
with the theory of its friction law, writes OUT/summary.json and the
figures in OUT/figures/, and prints the summary.

Usage: analyse.py OUT_DIR. Exit status 1 if a run disagrees with its theory
(a stick-slip case that slides steadily or the reverse, a growth rate more
than 5 % off the linear-stability one, a map point on the wrong side of the
boundary).
"""
import json
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from summary_file import write_summary  # noqa: E402

MASS, WEIGHT = 1000.0, 1000.0 * 9.81
# The laws of make_cases.py.
A, B, DC, MU0, V0 = 0.01, 0.015, 1.0e-4, 0.6, 1.0e-6
RS_KC = WEIGHT * (B - A) / DC                     # Ruina's quasi-static critical stiffness
VS, MU_V = 0.01, 1.0
V_CR = VS * math.log(0.1 / (MU_V * VS))           # Stribeck: mu'(V_cr) = 0
SW_DC = 0.01
SW_KC = WEIGHT * 0.1 / SW_DC                      # slip weakening: W (mu_s - mu_d) / Dc


def rs_boundary(vd):
    """Rice & Ruina's critical stiffness with the slider's inertia."""
    return RS_KC * (1 + MASS * vd ** 2 / (WEIGHT * A * DC))


def stribeck_mu(v):
    return 0.5 + 0.1 * np.exp(-v / VS) + MU_V * v


def load(out, name):
    with h5py.File(os.path.join(out, name, "results.h5"), "r") as f:
        t = f["series/time"][()]
        x = f["series/displacement"][()][:, 0, 0]
        v = f["series/velocity"][()][:, 0, 0]
        force = f["bolts/force"][()][:, 0]
    return t, x, v, force


def events(t, v, fast):
    """Times of the speed's peaks above `fast`, one per slip event."""
    peaks = []
    above = v > fast
    i = 0
    while i < len(v):
        if above[i]:
            j = i
            while j < len(v) and above[j]:
                j += 1
            peaks.append(i + int(np.argmax(v[i:j])))
            i = j
        else:
            i += 1
    return [t[p] for p in peaks]


def last_cycle(t, v, force, vd, fast):
    """Slip events (peaks above `fast` m/s); over the last whole cycle (between
    the last two peaks) its period, the range of the spring force over W (the
    stress drop over the normal stress) and the peak speed over vd."""
    p = events(t, v, fast)
    if len(p) < 2:
        return {"events": len(p)}
    sel = (t >= p[-2]) & (t <= p[-1])
    return {"events": len(p), "period_s": p[-1] - p[-2], "stress_drop": float(np.ptp(force[sel]) / WEIGHT),
            "peak_speed_over_vd": float(np.max(v[sel]) / vd)}


def growth_rate(t, v, vd):
    """Least-squares slope of ln|V - vd| at its extremes (linear range)."""
    d = np.abs(v - vd)
    i = np.arange(1, len(d) - 1)
    ext = i[(d[i] >= d[i - 1]) & (d[i] >= d[i + 1]) & (d[i] < 0.2 * vd) & (t[i] > 0.2)]
    return float(np.polyfit(t[ext], np.log(d[ext]), 1)[0]), t[ext], d[ext]


def amplitude(t, v, vd, t0, t1):
    sel = (t >= t0) & (t <= t1)
    return float(np.max(np.abs(v[sel] - vd)))


def main():
    out = sys.argv[1]
    fig_dir = os.path.join(out, "figures")
    os.makedirs(fig_dir, exist_ok=True)
    s, problems = {}, []

    # ---- rate and state
    vd = 1e-3
    t, x, v, force = load(out, "rs_half")
    c = last_cycle(t, v, force, vd, 3 * vd)
    s["rate_state_half_kc"] = c
    if c["events"] < 2:
        problems.append("rate_state at 0.5 k_c: no stick-slip")
    t2, x2, v2, f2 = load(out, "rs_twice")
    late = t2 > t2[-1] - 1
    mu_ss = MU0 + (A - B) * math.log(vd / V0)
    s["rate_state_twice_kc"] = {"late_speed_min_over_vd": float(v2[late].min() / vd),
                                "late_speed_max_over_vd": float(v2[late].max() / vd),
                                "friction_end": float(f2[-1] / WEIGHT), "steady_state_friction": mu_ss}
    if not (0.99 < v2[late].min() / vd and v2[late].max() / vd < 1.01):
        problems.append("rate_state at 2 k_c: not sliding steadily")
    s["rate_state_kc_N_per_m"] = RS_KC
    s["rate_state_kc_with_inertia_N_per_m"] = rs_boundary(vd)

    fig, ax = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for (tt, vv, ff, label) in ((t, v, force, "k = 0.5 k_c"), (t2, v2, f2, "k = 2 k_c")):
        ax[0].semilogy(tt, np.maximum(vv / vd, 1e-3), label=label)
        ax[1].plot(tt, ff / WEIGHT, label=label)
    ax[0].set_ylabel("slider speed / load-point speed")
    ax[1].set_ylabel("spring force / normal force")
    ax[1].set_xlabel("t (s)")
    ax[0].legend()
    ax[0].set_title("Rate and state spring-slider: stick-slip below k_c, steady sliding above")
    fig.tight_layout()
    fig.savefig(os.path.join(fig_dir, "rate_state_history.png"), dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 5))
    for (vv, ff, label) in ((v, force, "k = 0.5 k_c (limit cycle)"), (v2, f2, "k = 2 k_c (spirals in)")):
        ok = vv > 1e-3 * vd
        ax.plot(np.log(vv[ok] / vd), ff[ok] / WEIGHT, lw=0.8, label=label)
    ln = np.linspace(-7, 4, 100)
    ax.plot(ln, mu_ss + (A - B) * ln, "k--", lw=1, label="steady state mu0 + (a - b) ln(V / V0)")
    ax.set_xlabel("ln(V / vd)")
    ax.set_ylabel("spring force / normal force")
    ax.set_title("Rate and state: phase portrait")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(fig_dir, "rate_state_phase.png"), dpi=120)
    plt.close(fig)

    # ---- Stribeck
    s["stribeck_critical_speed_m_per_s"] = V_CR
    fig, ax = plt.subplots(1, 2, figsize=(12, 5))
    for name, ratio in (("st_slow", 0.5), ("st_fast", 2.0)):
        vd = ratio * V_CR
        t, x, v, force = load(out, name)
        late = t > t[-1] - 1
        c = last_cycle(t, v, force, vd, 2 * vd)
        c["late_speed_min_over_vd"] = float(v[late].min() / vd)
        c["late_speed_max_over_vd"] = float(v[late].max() / vd)
        s["stribeck_%s_vcr" % ("half" if ratio < 1 else "twice")] = c
        sticks = v[late].min() < 0.01 * vd
        if sticks != (ratio < 1):
            problems.append("Stribeck at %g V_cr: %s" % (ratio, "sticks" if sticks else "slides steadily"))
        ax[0].plot(v / V_CR, force / WEIGHT, lw=0.8, label="vd = %g V_cr" % ratio)
    vv = np.linspace(0, 3 * V_CR, 200)
    ax[0].plot(vv / V_CR, stribeck_mu(vv), "k--", lw=1, label="mu(V)")
    ax[0].axvline(1, color="gray", lw=0.5)
    ax[0].set_xlabel("slider speed / V_cr")
    ax[0].set_ylabel("spring force / normal force")
    ax[0].set_title("Stribeck: phase portrait (stick-slip loop below V_cr)")
    ax[0].legend(fontsize=8)
    rates = {}
    for name, ratio in (("st_lin09", 0.9), ("st_lin11", 1.1)):
        vd = ratio * V_CR
        t, x, v, force = load(out, name)
        rate, te, de = growth_rate(t, v, vd)
        slope = MU_V - 0.1 / VS * math.exp(-vd / VS)
        theory = -WEIGHT * slope / (2 * MASS)
        rates["%.1f" % ratio] = {"measured_per_s": rate, "linear_stability_per_s": theory}
        if abs(rate - theory) > 0.05 * abs(theory):
            problems.append("Stribeck growth rate at %g V_cr: %.4f, linear stability %.4f" % (ratio, rate, theory))
        line, = ax[1].semilogy(te, de / vd, ".", ms=3, label="vd = %.1f V_cr: %.3f 1/s" % (ratio, rate))
        ax[1].semilogy(te, de[0] / vd * np.exp(theory * (te - te[0])), "-", color=line.get_color(), lw=0.8,
                       label="linear stability %.3f 1/s" % theory)
    s["stribeck_growth_rate"] = rates
    ax[1].set_xlabel("t (s)")
    ax[1].set_ylabel("|V - vd| / vd at the extremes")
    ax[1].set_title("Stribeck: growth and decay of a 0.1 % kick")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(fig_dir, "stribeck.png"), dpi=120)
    plt.close(fig)

    # ---- slip weakening
    s["slip_weakening_kc_N_per_m"] = SW_KC
    vd = 2e-3
    fig, ax = plt.subplots(1, 2, figsize=(12, 5))
    for name, ratio in (("sw_soft", 0.5), ("sw_stiff", 2.0)):
        t, x, v, force = load(out, name)
        i0, i1 = np.argmax(x > 0.1 * SW_DC), np.argmax(x > 0.9 * SW_DC)
        mean = (x[i1] - x[i0]) / (t[i1] - t[i0])
        s["slip_weakening_%s_kc" % ("half" if ratio < 1 else "twice")] = {
            "mean_weakening_speed_over_vd": float(mean / vd), "peak_speed_over_vd": float(v.max() / vd),
            "slip_at_end_m": float(x[-1])}
        if ratio > 1 and abs(mean / vd - 2) > 0.1:
            problems.append("slip weakening at 2 k_c: weakening at %.3f vd, quasi-static 2 vd" % (mean / vd))
        if ratio < 1 and v.max() < 20 * vd:
            problems.append("slip weakening at 0.5 k_c: no dynamic event")
        ax[0].plot(x * 1000, force / WEIGHT, lw=0.8, label="k = %g k_c" % ratio)
        ax[1].plot(t, v / vd, lw=0.8, label="k = %g k_c" % ratio)
    d = np.linspace(0, 40, 200)
    ax[0].plot(d, 0.6 - 0.1 * np.minimum(d / (SW_DC * 1000), 1), "k--", lw=1, label="strength mu(D)")
    ax[0].set_xlabel("slip (mm)")
    ax[0].set_ylabel("spring force / normal force")
    ax[0].set_title("Linear slip weakening, Dc = 10 mm")
    ax[0].legend(fontsize=8)
    ax[1].axhline(2, color="gray", lw=0.5)
    ax[1].set_yscale("log")
    ax[1].set_xlabel("t (s)")
    ax[1].set_ylabel("slider speed / load-point speed")
    ax[1].set_title("k > k_c: quasi-static at k vd / (k - k_c) = 2 vd")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(fig_dir, "slip_weakening.png"), dpi=120)
    plt.close(fig)

    # ---- stability map (rate and state)
    points = []
    for vd_text in ("0.5e-3", "1e-3", "2e-3", "3e-3"):
        for kk in ("0.5", "0.8", "1.25", "2.5"):
            vd, ratio = float(vd_text), float(kk)
            t, x, v, force = load(out, "map_%s_%s" % (vd_text, kk))
            unit = DC / vd
            early, late = amplitude(t, v, vd, 5 * unit, 15 * unit), amplitude(t, v, vd, 50 * unit, 60 * unit)
            unstable = late > early or late > 0.5 * vd
            theory = ratio * RS_KC < rs_boundary(vd)
            points.append({"vd": vd, "k_over_kc": ratio, "unstable": bool(unstable), "theory_unstable": bool(theory),
                           "amplitude_growth": late / early})
    agree = sum(p["unstable"] == p["theory_unstable"] for p in points)
    s["stability_map"] = {"points": len(points), "agree_with_theory": agree, "cases": points}
    if agree != len(points):
        problems.append("stability map: %d of %d points on the theory's side" % (agree, len(points)))
    fig, ax = plt.subplots(figsize=(7, 5))
    for p in points:
        ax.plot(p["vd"] * 1000, p["k_over_kc"], "o" if p["unstable"] else "s",
                color="tab:red" if p["unstable"] else "tab:blue", ms=8)
    vv = np.linspace(0, 3.3e-3, 100)
    ax.plot(vv * 1000, rs_boundary(vv) / RS_KC, "k-", label="k_c (1 + m vd^2 / (N a Dc))")
    ax.plot([], [], "o", color="tab:red", label="DDA: stick-slip (grows)")
    ax.plot([], [], "s", color="tab:blue", label="DDA: steady sliding (decays)")
    ax.set_xlabel("load-point speed vd (mm/s)")
    ax.set_ylabel("spring stiffness k / k_c")
    ax.set_title("Rate and state spring-slider: stability map")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(fig_dir, "stability_map.png"), dpi=120)
    plt.close(fig)

    s["problems"] = problems
    write_summary(os.path.join(out, "summary.json"), s)
    print(json.dumps({k: v for k, v in s.items() if k != "stability_map"}, indent=1))
    print("stability map: %d of %d points on the side of the boundary theory puts them" % (agree, len(points)))
    for p in problems:
        print("PROBLEM: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
