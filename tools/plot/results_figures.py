"""Which figures a results file gets, under which names, and how one is
drawn: the entry point of dda_plot.py and dda_report.py for results files.

Kinds (the figure's file name is KIND.png when -o is a folder):
  blocks     deformed blocks at --times, coloured by --color-by
             (2D: the model plane; 3D: one panel per --look direction)
  sections   3D only: the blocks cut by --section planes (default: vertical
             sections through the model's middle)
  contacts   forces and states of the contacts of the last step
  histories  measurement points against time
  energy     the energy ledger against time (2D, and 3D from the 3D ledger on)
  steps      step length, iterations per step, contacts by state
"""

import numpy as np
import matplotlib.pyplot as plt

import results_maps as maps
import results_series as series
import results_views3d as v3

KINDS_2D = ("blocks", "contacts", "histories", "energy", "steps")
KINDS_3D = ("blocks", "sections", "contacts", "histories", "energy", "steps")
DEFAULT_LOOKS_3D = ("north", "west", "plan")


class FigureOptions:
    """What the user chose; defaults give the usual pictures."""

    def __init__(self, times=None, color_by="displacement", component="mean", vectors=False, looks=None,
                 sections=None):
        self.times = times or []
        self.color_by = color_by
        self.component = component
        self.vectors = vectors
        self.looks = looks or []
        self.sections = sections or []


def kinds_of(r):
    """The figures of a results file: a 3D file written before the 3D energy
    ledger has no energy record to draw."""
    kinds = KINDS_3D if r.dim == 3 else KINDS_2D
    return kinds if r.energy else tuple(k for k in kinds if k != "energy")


def check_kind(r, kind):
    """None when `kind` applies to `r`, otherwise why not (one sentence)."""
    if kind in kinds_of(r):
        return None
    if kind == "energy":
        return (f"{r.path}: keeps no energy record (a 3D results file written before the 3D energy ledger); "
                "run it again for --kind energy")
    if kind == "sections":
        return f"{r.path}: --kind sections is for 3D results; a 2D run is drawn whole with --kind blocks"
    return f"{r.path}: --kind {kind} does not apply to a results file (one of {', '.join(kinds_of(r))})"


def check_times(r, times):
    """Times outside the run are a mistake, not a request for the nearest frame."""
    lo, hi = float(r.frame_time[0]), float(r.frame_time[-1])
    for t in times:
        if not np.isfinite(t) or t < lo - 1e-9 or t > hi + 1e-9:
            return (f"{r.path}: --times {t:g} is outside the saved frames (t = {lo:g} to {hi:g} s)")
    return None


def parse_choices(r, opts):
    """(looks, sections) as numbers; ValueError with the user's mistake."""
    looks = [v3.parse_view(s) for s in (opts.looks or (DEFAULT_LOOKS_3D if r.dim == 3 else []))]
    sections = [v3.parse_section(s, r) for s in opts.sections]
    return looks, sections


def draw(r, kind, opts):
    """(figure, note): the figure of `kind`, and a sentence about what could
    not be drawn (or None)."""
    looks, sections = parse_choices(r, opts)
    frames = maps.frames_for(r, opts.times)
    if kind == "blocks":
        if r.dim == 2:
            return maps.deformed_2d(r, frames, opts.color_by, opts.component, opts.vectors), None
        return maps.deformed_3d(r, frames, opts.color_by, opts.component, opts.vectors, looks), None
    if kind == "sections":
        return maps.sections_3d(r, frames[-1], opts.color_by, opts.component, sections), None
    if kind == "contacts":
        return maps.contacts_figure(r, looks[0] if looks else None)
    if kind == "histories":
        return series.histories_figure(r), None
    if kind == "energy":
        return series.energy_figure(r), None
    if kind == "steps":
        return series.steps_figure(r), None
    raise ValueError(f"unknown kind {kind}")


def close(fig):
    plt.close(fig)
