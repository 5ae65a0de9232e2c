"""The facts of a run that `dda report` lists, taken from a results file
(results_data.Results): provenance, model, run statistics, the energy
balance, warnings and the measurement points' final and peak values. Pure
data (lists of (label, value) rows); report_html.py turns them into HTML.
"""

import re

import numpy as np

from results_quantities import readable_unit

# As df/core/energy.hpp: energy created beyond this share of the energy moved is
# reported (dda df warns, dda info shows it).
ENERGY_CREATED_WARNING = 0.1


def scenario_name(r):
    m = re.search(r"^name:\s*(\S.*?)\s*(#.*)?$", r.scenario_text, flags=re.M)
    return m.group(1).strip("'\"") if m else None


def provenance(r):
    a = r.attrs
    rows = [("results file", r.path), ("format", f"{r.format} (version {a.get('format_version', '?')})"),
            ("program version", a.get("program_version", "not recorded")),
            ("written", a.get("created_utc", "not recorded")),
            ("scenario", a.get("scenario_path", "not recorded")),
            ("input kind", a.get("input_kind", "not recorded")),
            ("blocks file it started from", a.get("blocks_path", "not recorded")),
            ("seed (of the joint network)", a.get("seed", "not recorded"))]
    if "solver" in a:
        rows.append(("solver", a["solver"]))
    # The results file keeps the scenario, not the command line.
    scen = a.get("scenario_path")
    rows.append(("command", f"dda run {scen} (or dda df; the results file keeps the scenario, not the command)"
                 if scen else "not recorded"))
    return rows


def size_summary(values, unit):
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if len(v) == 0:
        return "not recorded"
    return f"min {v.min():.4g}, median {np.median(v):.4g}, max {v.max():.4g} {unit}"


def model(r):
    rows = [("blocks", str(r.num_blocks))]
    if r.dim == 3 and len(r.fixed) == r.num_blocks:
        rows.append(("fixed blocks", str(int(np.sum(r.fixed)))))
    rows.append(("vertices", str(len(r.vertices0))))
    if r.dim == 2:
        rows.append(("block area", size_summary(r.sizes, "m²")))
    else:
        rows.append(("block volume", size_summary(r.sizes, "m³")))
    extent = r.vertices0.max(axis=0) - r.vertices0.min(axis=0)
    rows.append(("extent", " × ".join(f"{e:.4g}" for e in extent) + " m"))
    rows.append(("measurement points", ", ".join(r.point_names) if r.point_names else "none"))
    rows.append(("frames saved", f"{len(r.frame_time)} (t = {r.frame_time[0]:g} to {r.frame_time[-1]:g} s)"))
    return rows


def run(r):
    steps = len(r.step_time)
    rows = [("status", "complete" if r.complete else "incomplete (stopped or in progress)"),
            ("model time reached", f"{r.end_time:g} s"), ("steps", str(steps))]
    if steps:
        dt = r.step_dt
        rows.append(("step length dt", f"min {dt.min():.4g}, median {np.median(dt):.4g}, max {dt.max():.4g} s"))
        if len(r.step_cuts) == steps:
            rows.append(("steps redone with a smaller dt", str(int(np.sum(r.step_cuts > 0)))))
        if len(r.step_converged) == steps:
            rows.append(("steps accepted unsettled at the smallest dt", str(int(np.sum(r.step_converged == 0)))))
        it = r.step_iterations
        rows.append(("open-close iterations (solves) per step", f"mean {it.mean():.3g}, max {int(it.max())}"))
        last = {s: int(v[-1]) for s, v in r.step_states.items() if len(v) == steps}
        if last:
            rows.append(("contacts at the last step", ", ".join(f"{v} {s}" for s, v in last.items())))
    return rows


def energy_balance(r):
    """Rows of the energy balance at the end, or None without an energy
    record (3D files written before the 3D ledger)."""
    e = r.energy
    if not e or len(e.get("time", [])) == 0:
        return None
    stored = sum(e[k] for k in ("kinetic", "elastic", "contact", "fixed", "bolts") if k in e)
    work = sum(e[k] for k in ("gravity_work", "load_work") if k in e)
    losses = sum(e[k] for k in ("friction", "damping", "breakage", "radiation") if k in e)
    moved = np.maximum(np.abs(work), np.abs(stored - stored[0]) + losses)
    factor, unit = readable_unit([moved[-1], work[-1]], "J/m" if r.dim == 2 else "J")
    share = e["residual"][-1] / moved[-1] if moved[-1] > 0 else 0.0
    return [("work done (gravity, loads)", f"{work[-1] * factor:.4g} {unit}"),
            ("change of stored energy", f"{(stored[-1] - stored[0]) * factor:.4g} {unit}"),
            ("losses (friction, damping, breakage, radiation)", f"{losses[-1] * factor:.4g} {unit}"),
            ("residual (penalty springs, implicit step)",
             f"{e['residual'][-1] * factor:.4g} {unit} = {100 * share:.2f} % of the energy moved")]


def most_energy_created(r):
    """(time, share of the energy moved) where the run created the most
    energy, as df::most_energy_created; None without an energy record."""
    e = r.energy
    if not e or len(e.get("time", [])) < 2:
        return None
    stored = sum(e[k] for k in ("kinetic", "elastic", "contact", "fixed", "bolts") if k in e)
    work = sum(e[k] for k in ("gravity_work", "load_work") if k in e)
    losses = sum(e[k] for k in ("friction", "damping", "breakage", "radiation") if k in e)
    scale = np.maximum.accumulate(np.maximum(np.abs(work), np.abs(stored - stored[0]) + losses))
    ratio = np.where(scale > 0, e["residual"] / np.where(scale > 0, scale, 1), 0.0)[1:]
    k = int(np.argmin(ratio))
    return float(e["time"][k + 1]), float(ratio[k])


def warnings(r, notes):
    out = []
    if not r.complete:
        out.append(f"The run is incomplete: it stopped at t = {r.end_time:g} s (dda df --resume continues it).")
    created = most_energy_created(r)
    if created and created[1] < -ENERGY_CREATED_WARNING:
        out.append(f"The run created {-100 * created[1]:.1f} % of the energy it moved (worst at t = "
                   f"{created[0]:g} s): look for overlapping blocks or slivers thinner than the contact search "
                   f"distance.")
    if len(r.step_converged) and np.any(r.step_converged == 0):
        out.append(f"{int(np.sum(r.step_converged == 0))} steps were accepted unsettled at the smallest dt.")
    out += [n[0].upper() + n[1:] + ("" if n.endswith(".") else ".") for n in notes if n]
    return out


def point_table(r):
    """Header and rows: final and peak displacement and peak speed of every
    measurement point, in a unit common to the table."""
    if not r.point_names:
        return None, []
    u, v, t = r.displacement, r.velocity, r.series_time
    mag = np.linalg.norm(u, axis=2)
    speed = np.linalg.norm(v, axis=2)
    uf, uu = readable_unit(mag, "m")
    vf, vu = readable_unit(speed, "m/s")
    comps = "xyz"[: r.dim]
    header = (["point"] + [f"final u{c} ({uu})" for c in comps] +
              [f"final |u| ({uu})", f"peak |u| ({uu})", "at t (s)", f"peak speed ({vu})", "at t (s)"])
    rows = []
    for k, name in enumerate(r.point_names):
        i, j = int(np.argmax(mag[:, k])), int(np.argmax(speed[:, k]))
        rows.append([name] + [f"{u[-1, k, c] * uf:.4g}" for c in range(r.dim)] +
                    [f"{mag[-1, k] * uf:.4g}", f"{mag[i, k] * uf:.4g}", f"{t[i]:g}",
                     f"{speed[j, k] * vf:.4g}", f"{t[j]:g}"])
    return header, rows
