"""Time series of a results file: the measurement points' displacement and
speed, the energy ledger, and the run itself (step length, open-close
iterations per step, contacts by state)."""

import numpy as np
import matplotlib.pyplot as plt

from results_quantities import readable_unit

# Energy records (docs/formats.md, /energy): stored energies at the end of
# each step, then work and losses, cumulative.
STORED = ("kinetic", "elastic", "contact", "fixed", "bolts")
WORK = ("gravity_work", "load_work")
LOSSES = ("friction", "damping", "breakage", "radiation", "residual")
MAX_LEGEND = 16  # points named in the legend; beyond, the legend would hide the curves


def incomplete_note(r):
    return "" if r.complete else f" (run incomplete, stopped at t = {r.end_time:g} s)"


def histories_figure(r):
    """One panel per displacement component, one for the speed; a line per
    measurement point."""
    names = r.point_names
    comps = "xyz"[: r.dim]
    fig, axes = plt.subplots(r.dim + 1, 1, sharex=True, figsize=(8, 2.3 * (r.dim + 1) + 0.6), squeeze=False)
    axes = axes[:, 0]
    t = r.series_time
    series = [(f"u{c}", r.displacement[:, :, i], "m") for i, c in enumerate(comps)]
    series.append(("|v|", np.linalg.norm(r.velocity, axis=2), "m/s"))
    for ax, (what, values, unit) in zip(axes, series):
        factor, shown = readable_unit(values, unit)
        for k, name in enumerate(names):
            ax.plot(t, values[:, k] * factor, lw=1.1, label=name)
        what_text = "speed" if what == "|v|" else "displacement"
        ax.set_ylabel(f"{what_text} {what} ({shown})")
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("time (s)")
    if len(names) > MAX_LEGEND:
        axes[0].set_title(f"{len(names)} points (too many to name here; dda history lists them)", fontsize=8,
                          loc="left")
    elif names:
        axes[0].legend(fontsize=7, loc="best", ncol=2 if len(names) > 6 else 1)
    else:
        axes[0].text(0.5, 0.5, "the run has no measurement points", ha="center", transform=axes[0].transAxes)
    fig.suptitle("Measurement points: displacement from the start and speed" + incomplete_note(r), fontsize=11)
    fig.tight_layout()
    return fig


def energy_figure(r):
    """Stored energies above; work done and losses (cumulative) below."""
    e = r.energy
    t = e["time"]
    unit = "J/m" if r.dim == 2 else "J"  # 2D: per metre of thickness
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6.4))
    everything = np.concatenate([e[k] for k in STORED + WORK + LOSSES if k in e])
    factor, shown = readable_unit(everything, unit)
    silent = []
    for ax, keys in ((top, STORED), (bottom, WORK + LOSSES)):
        for k in keys:
            if k not in e:
                continue
            if not np.any(e[k] != 0):
                silent.append(k.replace("_", " "))
                continue
            style = "--" if k in WORK else "-"
            ax.plot(t, e[k] * factor, style, lw=1.2, label=k.replace("_", " "))
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, loc="best")
    top.set_ylabel(f"stored energy ({shown})")
    bottom.set_ylabel(f"work (dashed), losses ({shown})")
    bottom.set_xlabel("time (s)")
    if silent:
        bottom.set_title("zero throughout: " + ", ".join(silent), fontsize=8, loc="left")
    fig.suptitle("Energy per metre of thickness" + incomplete_note(r), fontsize=11)
    fig.tight_layout()
    return fig


def steps_figure(r):
    """The step length, the open-close iterations (solves) per step and the
    contacts by state, against time."""
    t = r.step_time
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(8, 7.0))
    if len(t) == 0:
        axes[0].text(0.5, 0.5, "no steps taken", ha="center", transform=axes[0].transAxes)
    else:
        axes[0].plot(t, r.step_dt, lw=1.0, color="#1b7837")
        positive = r.step_dt[r.step_dt > 0]
        if len(positive) and positive.max() / positive.min() > 20:
            axes[0].set_yscale("log")
        cuts = np.flatnonzero(r.step_cuts > 0) if len(r.step_cuts) == len(t) else []
        if len(cuts):
            axes[0].plot(t[cuts], r.step_dt[cuts], "v", ms=3, color="#d62728", label="dt cut")
            axes[0].legend(fontsize=7)
        axes[1].plot(t, r.step_iterations, lw=0.8, color="#762a83")
        for state, colour in (("open", "0.55"), ("sliding", "#e66101"), ("locked", "#2c7bb6")):
            if len(r.step_states[state]) == len(t):
                axes[2].plot(t, r.step_states[state], lw=1.0, color=colour, label=state)
        axes[2].legend(fontsize=7, loc="best")
    axes[0].set_ylabel("step length dt (s)")
    axes[1].set_ylabel("open-close iterations\nper step")
    axes[2].set_ylabel("contacts")
    axes[2].set_xlabel("time (s)")
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle(f"The run: {len(t)} steps" + incomplete_note(r), fontsize=11)
    fig.tight_layout()
    return fig
