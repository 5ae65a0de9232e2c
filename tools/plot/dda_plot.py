#!/usr/bin/python3
"""Pictures of dda lines and blocks files (HDF5, see docs/formats.md).

    dda_plot.py FILE.h5 [FILE2.h5 ...] -o OUT.png|OUT.svg|OUT.pdf
                [--kind auto|lines|blocks|histograms|compare|spectra] [--labels A B ...]
                [--title T] [--bins N] [--fraction] [--no-names]

--kind auto (default) draws each file as what it is: a lines file as its
joint traces coloured by joint set with the domain and excavations outlined;
a blocks file as filled blocks (coloured by bed, alternating shades, when the
rock is layered) with thin black edges. Named points are marked in both:
fixed ^, load v, measurement o, hole x. Several files are drawn side by side.

--kind histograms draws the block width and block area distributions of one
or more blocks files overlaid (counts per bin), e.g. a mechanically layered
mesh against Shi-Goodman meshes. Block width is the extent of the block along
the bedding direction (cos d, sin d), d = bedding_dip_deg, exactly as
`dda stats` (dc/src/stats.cpp) computes it.

--kind compare draws the CSV `dda compare -o` writes: the DDA and the
reference displacement histories, and below them the relative error in %
(the seed report's Figure 13); --labels gives the two curve labels.

--kind spectra draws the CSV `dda spectra -o` writes, by its first column:
f (Hz) -- the amplitude spectrum on log-log axes, or with a ratio (columns
ratio or hv) the two spectra above and the ratio below, its peak marked;
T (s) -- the response spectra PSA and SA above and SD below against the
period, log period axis. --labels names the spectra (the signal, the
reference).

3D files (a fractures file from `dda dl`, a 3D blocks file from `dda dc`)
are drawn in a 3D view; see dda_plot3d.py for --color, --explode, --view.

A results file (dda-results, dda-results3d) is drawn by results_figures.py
(-o FOLDER: every figure; -o FIG.png --kind blocks|sections|contacts|
histories|energy|steps: one), with --times, --color-by, --component,
--vectors, --look and --section; docs/plots.md.

Needs numpy, h5py and matplotlib (Debian: python3-h5py, python3-matplotlib);
runs headless (Agg). Any problem is one line on stderr and exit status 2.
"""

import argparse
import math
import os
import sys

from plot_io import PROG, fail, label_user_coordinates, origin_of, save_atomically

POINT_STYLE = {  # kind code -> (marker, colour, label); codes as in docs/formats.md
    0: ("^", "black", "fixed point"),
    1: ("v", "#d62728", "load point"),
    2: ("o", "#1f77b4", "measurement point"),
    3: ("x", "#555555", "hole point"),
}


try:
    import numpy as np
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Polygon as PolygonPatch
except ImportError as exc:  # pragma: no cover - depends on the machine
    fail(f"needs numpy, h5py and matplotlib ({exc}); run it with /usr/bin/python3")

from results_data import RESULTS_FORMATS, text  # noqa: E402 (needs numpy)
from results_quantities import STRESS_2D, STRESS_CHOICES  # noqa: E402


# ----------------------------------------------------------------- reading


class Model:
    """What the plots need from a lines or blocks file, as numpy arrays."""

    def __init__(self, path):
        self.path = path
        if not os.path.exists(path):
            fail(f"{path}: file not found")
        if os.path.isdir(path):
            fail(f"{path}: is a folder, not a file")
        try:
            is_hdf5 = h5py.is_hdf5(path)
        except OSError as exc:
            fail(f"{path}: cannot read the file ({exc.strerror or exc})")
        if not is_hdf5:
            fail(f"{path}: is not an HDF5 file")
        try:
            with h5py.File(path, "r") as f:
                self.format = text(f.attrs.get("format", ""))
                if self.format not in ("dda-lines", "dda-blocks"):
                    fail(f"{path}: is not a dda lines or blocks file (no dda format attribute)")
                self._read(f)
        except (OSError, KeyError, ValueError, TypeError) as exc:
            fail(f"{path}: cannot read it as a {getattr(self, 'format', 'dda')} file ({exc})")

    def _read(self, f):
        def arr(name, shape_tail=(), dtype=float):
            if name in f:
                return np.asarray(f[name][()], dtype=dtype)
            return np.zeros((0,) + shape_tail, dtype=dtype)

        def strings(name):
            return [text(s) for s in f[name][()]] if name in f else []

        self.dip = float(f.attrs.get("bedding_dip_deg", 0.0))
        self.origin = origin_of(f, 2)
        self.set_names = strings("sets/name")
        self.point_names = strings("points/name")
        self.point_kind = arr("points/kind", dtype=int)
        self.point_xy = arr("points/xy", (2,)).reshape(-1, 2)
        self.layer_bottom = arr("layers/bottom")
        self.layer_top = arr("layers/top")
        if self.format == "dda-lines":
            self.domain = arr("domain/vertices", (2,)).reshape(-1, 2)
            ev = arr("excavations/vertices", (2,)).reshape(-1, 2)
            eo = arr("excavations/offsets", dtype=np.int64) if "excavations/offsets" in f else np.zeros(1, np.int64)
            self.excavations = [ev[eo[i]:eo[i + 1]] for i in range(len(eo) - 1)]
            self.endpoints = arr("lines/endpoints", (4,)).reshape(-1, 4)
            self.line_set = arr("lines/set", dtype=int)
            self.line_kind = arr("lines/kind", dtype=int)
        else:
            self.vertices = arr("blocks/vertices", (2,)).reshape(-1, 2)
            self.offsets = arr("blocks/offsets", dtype=np.int64)
            if len(self.offsets) == 0:
                self.offsets = np.zeros(1, np.int64)
            if self.offsets[0] != 0 or self.offsets[-1] != len(self.vertices) or np.any(np.diff(self.offsets) < 3):
                raise ValueError("/blocks/offsets does not match /blocks/vertices")
            self.area = arr("blocks/area")
            self.block_layer = arr("blocks/layer", dtype=int)
            if len(self.area) != self.num_blocks or len(self.block_layer) != self.num_blocks:
                raise ValueError("/blocks/area or /blocks/layer has the wrong length")

    @property
    def num_blocks(self):
        return len(self.offsets) - 1

    def polygons(self):
        return np.split(self.vertices, self.offsets[1:-1]) if self.num_blocks else []

    def widths(self):
        """Extent of each block along the bedding direction (cos d, sin d)."""
        if self.num_blocks == 0:
            return np.zeros(0)
        d = math.radians(self.dip)
        s = self.vertices @ np.array([math.cos(d), math.sin(d)])
        starts = self.offsets[:-1]
        return np.maximum.reduceat(s, starts) - np.minimum.reduceat(s, starts)


# ----------------------------------------------------------------- drawing


def set_colours(count):
    cmap = plt.get_cmap("tab10" if count <= 10 else "tab20")
    return [cmap(i % cmap.N) for i in range(max(count, 1))]


def draw_points(ax, m, names=True):
    handles = []
    for kind, (marker, colour, label) in POINT_STYLE.items():
        sel = np.flatnonzero(m.point_kind == kind)
        if len(sel) == 0:
            continue
        style = {} if marker == "x" else {"edgecolors": "white"}  # x is an unfilled marker
        ax.scatter(m.point_xy[sel, 0], m.point_xy[sel, 1], marker=marker, c=colour, s=36,
                   linewidths=1.2, zorder=5, **style)
        handles.append(Line2D([], [], ls="", marker=marker, color=colour, label=label))
        if names:
            for i in sel:
                ax.annotate(m.point_names[i] if i < len(m.point_names) else "",
                            m.point_xy[i], xytext=(4, 4), textcoords="offset points",
                            fontsize=7, zorder=6)
    return handles


def draw_lines(ax, m, names=True):
    handles = []
    colours = set_colours(len(m.set_names))
    segs = m.endpoints.reshape(-1, 2, 2)
    if len(segs):
        cols = [colours[s] if 0 <= s < len(colours) else (0, 0, 0, 1) for s in m.line_set]
        widths = np.where(m.line_kind == 1, 1.3, 0.7)
        ax.add_collection(LineCollection(segs, colors=cols, linewidths=widths, zorder=2))
    used = sorted(set(int(s) for s in m.line_set))
    for s in used:
        name = m.set_names[s] if 0 <= s < len(m.set_names) else f"set {s}"
        colour = colours[s] if 0 <= s < len(colours) else "black"
        handles.append(Line2D([], [], color=colour, lw=1.5, label=name))
    if len(m.domain) >= 3:
        ax.add_patch(PolygonPatch(m.domain, closed=True, fill=False, ec="black", lw=1.2, zorder=3))
    for e in m.excavations:
        ax.add_patch(PolygonPatch(e, closed=True, fc="white", ec="black", lw=1.0, zorder=3))
    handles += draw_points(ax, m, names)
    bounds = [a for a in (m.domain, segs.reshape(-1, 2), m.point_xy) if len(a)]
    return handles, bounds


def block_colours(m):
    n = m.num_blocks
    rng = np.random.default_rng(12345)  # same picture every time
    if len(m.layer_bottom) and np.any(m.block_layer >= 0):
        # Beds in alternating shades; a little lightness jitter per block.
        base = np.array([[0.85, 0.74, 0.56], [0.62, 0.72, 0.80]])
        rgb = np.where((m.block_layer % 2 == 0)[:, None], base[0], base[1])
        rgb = np.clip(rgb * rng.uniform(0.88, 1.08, size=(n, 1)), 0, 1)
        rgb[m.block_layer < 0] = (0.85, 0.85, 0.85)
        return rgb
    # Not layered: a qualitative palette, picked at random so that
    # neighbouring blocks are unlikely to share a colour.
    palette = np.array(plt.get_cmap("tab20").colors)
    palette = 0.55 * palette + 0.45  # lighter, so edges and points stay visible
    return palette[rng.integers(0, len(palette), size=n)]


def draw_blocks(ax, m, names=True):
    polys = m.polygons()
    if polys:
        lw = 0.4 if len(polys) < 5000 else (0.2 if len(polys) < 50000 else 0.1)
        ax.add_collection(PolyCollection(polys, facecolors=block_colours(m), edgecolors="black",
                                         linewidths=lw, zorder=2))
    handles = draw_points(ax, m, names)
    bounds = [a for a in (m.vertices, m.point_xy) if len(a)]
    return handles, bounds


def finish_map(ax, bounds, title, handles, axis_labels=("x (m)", "y (m)"), origin=(0.0, 0.0)):
    ax.set_aspect("equal")
    label_user_coordinates((ax.xaxis, ax.yaxis), origin)
    if bounds:
        allp = np.vstack(bounds)
        lo, hi = allp.min(axis=0), allp.max(axis=0)
        pad = 0.03 * max(hi[0] - lo[0], hi[1] - lo[1], 1e-9)
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_xlabel(axis_labels[0])
    ax.set_ylabel(axis_labels[1])
    ax.set_title(title, fontsize=10)
    if handles:
        ax.legend(handles=handles, fontsize=7, loc="upper right", framealpha=0.85)


def plot_maps(models, labels, kind, names, axis_labels):
    """Each file in its panel; the panel says what it holds (or --labels)."""
    n = len(models)
    cols = min(n, 3)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(6.5 * cols, 5.0 * rows), squeeze=False)
    for ax, m, label in zip(axes.flat, models, labels):
        want = {"lines": "dda-lines", "blocks": "dda-blocks"}.get(kind, m.format)
        if m.format != want:
            fail(f"{m.path}: is a {m.format} file, --kind {kind} needs a {want} file")
        if m.format == "dda-lines":
            handles, bounds = draw_lines(ax, m, names)
            sets = len(set(int(x) for x in m.line_set))
            sub = f"{len(m.endpoints)} joint traces in {sets} set{'s' if sets != 1 else ''}"
        else:
            handles, bounds = draw_blocks(ax, m, names)
            sub = f"{m.num_blocks} blocks"
        finish_map(ax, bounds, f"{label} ({sub})" if label else sub, handles, axis_labels, m.origin)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    return fig


def plot_histograms(models, labels, bins, fraction=False):
    for m in models:
        if m.format != "dda-blocks":
            fail(f"{m.path}: is a {m.format} file, --kind histograms needs dda-blocks files")
    widths = [m.widths() for m in models]
    areas = [np.asarray(m.area, dtype=float) for m in models]
    fig, (axw, axa) = plt.subplots(1, 2, figsize=(11, 4.2))

    def edges(values, log):
        allv = np.concatenate(values) if values else np.zeros(0)
        allv = allv[np.isfinite(allv)]
        if log:
            allv = allv[allv > 0]
        if len(allv) == 0:
            return None
        lo, hi = allv.min(), allv.max()
        if not hi > lo:
            lo, hi = (lo / 2, hi * 2) if log else (lo - 0.5, hi + 0.5)
        return np.geomspace(lo, hi, bins + 1) if log else np.linspace(lo, hi, bins + 1)

    nonzero = np.concatenate(areas) if areas else np.zeros(0)
    nonzero = nonzero[nonzero > 0]
    log_area = len(nonzero) > 0 and nonzero.max() / nonzero.min() > 100
    for ax, values, log, xlabel in ((axw, widths, False, "block width along the bedding (m)"),
                                    (axa, areas, log_area, "block area (m²)")):
        e = edges(values, log)
        for v, label in zip(values, labels):
            if e is not None and len(v):
                weights = np.full(len(v), 1.0 / len(v)) if fraction else None
                ax.hist(v, bins=e, weights=weights, histtype="step", linewidth=1.6,
                        label=f"{label} (n={len(v)})")
        if log:
            ax.set_xscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("fraction of blocks" if fraction else "number of blocks")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axw.set_title("Block width", fontsize=10)
    axa.set_title("Block area" + (" (logarithmic bins)" if log_area else ""), fontsize=10)
    return fig


# ------------------------------------------------------------------ compare


def plot_compare(path, labels):
    """`dda compare` output (t, dda, reference, difference, relative_error):
    both displacement histories above, the relative error (%) below, like the
    seed report's Figure 13."""
    import csv

    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        t = np.array([float(r["t"]) for r in rows])
        dda = np.array([float(r["dda"]) for r in rows])
        ref = np.array([float(r["reference"]) for r in rows])
        rel = np.array([float(r["relative_error"]) for r in rows])
    except (OSError, KeyError, ValueError, TypeError) as exc:
        fail(f"{path}: cannot read it as a dda compare CSV (t, dda, reference, difference, relative_error): {exc}")
    if len(t) == 0:
        fail(f"{path}: has no rows to draw")
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7.5, 6.5),
                                      gridspec_kw={"height_ratios": [2, 1]})
    top.plot(t, ref, color="black", lw=1.6, label=labels[1])
    top.plot(t, dda, color="#d62728", lw=1.2, ls="--", label=labels[0])
    top.set_ylabel("displacement (m)")
    top.grid(True, alpha=0.3)
    top.legend(loc="best")
    bottom.plot(t, 100 * rel, color="#1f77b4", lw=1.0)
    bottom.axhline(0, color="black", lw=0.6)
    bottom.set_ylabel("relative error (%)")
    bottom.set_xlabel("time (s)")
    bottom.grid(True, alpha=0.3)
    bottom.set_title(f"final relative error {100 * rel[-1]:+.2f} %", fontsize=9, loc="right")
    fig.tight_layout()
    return fig


# ------------------------------------------------------------------ spectra


def read_csv_columns(path, what):
    import csv

    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        if not rows:
            fail(f"{path}: has no rows to draw")
        return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    except (OSError, KeyError, ValueError, TypeError) as exc:
        fail(f"{path}: cannot read it as a {what} CSV: {exc}")


def readable_log_axis(axis):
    """Ticks at 1, 2, 3 and 5 per decade, written as plain numbers: the default
    shows one label ("10⁰") on an axis shorter than a decade or two."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 3.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def plot_spectra(path, labels, amplitude_unit=None):
    """`dda spectra` output: f, amplitude[, reference, ratio] or f, horizontal,
    vertical, hv (log-log, the ratio in its own panel), or T, SD, SV, PSV,
    PSA, SA (response spectra against the period)."""
    c = read_csv_columns(path, "dda spectra")
    if "T" in c:
        t = c["T"]
        pos = t > 0  # T = 0 (the PGA) has no place on a log axis
        fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7.5, 6.5),
                                          gridspec_kw={"height_ratios": [2, 1]})
        name = labels[0] if labels else "record"
        top.plot(t[pos], c["PSA"][pos], color="#d62728", lw=1.4, label=f"PSA, {name}")
        top.plot(t[pos], c["SA"][pos], color="black", lw=1.0, ls="--", label="SA (absolute)")
        top.set_ylabel("spectral acceleration")
        bottom.plot(t[pos], c["SD"][pos], color="#1f77b4", lw=1.2)
        bottom.set_ylabel("SD")
        bottom.set_xlabel("period T (s)")
        bottom.set_xscale("log")
        readable_log_axis(bottom.xaxis)
        for ax in (top, bottom):
            ax.grid(True, which="both", alpha=0.3)
        top.legend(loc="best")
        fig.tight_layout()
        return fig
    if "f" not in c:
        fail(f"{path}: is not a dda spectra CSV (its first column is neither f nor T)")
    f = c["f"]
    ratio_key = "ratio" if "ratio" in c else ("hv" if "hv" in c else None)
    curves = [k for k in ("amplitude", "reference", "horizontal", "vertical") if k in c]
    names = list(labels or []) + curves[len(labels or []):]
    if ratio_key is None:
        fig, top = plt.subplots(figsize=(7.5, 4.5))
    else:
        fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7.5, 6.5),
                                          gridspec_kw={"height_ratios": [1, 1]})
    for k, name, colour in zip(curves, names, ["#d62728", "black"]):
        top.loglog(f, c[k], color=colour, lw=1.2, label=name)
    top.set_ylabel(f"Fourier amplitude ({amplitude_unit})" if amplitude_unit else "Fourier amplitude")
    readable_log_axis(top.yaxis)
    top.grid(True, which="both", alpha=0.3)
    top.legend(loc="best")
    last = top
    if ratio_key is not None:
        r = c[ratio_key]
        bottom.loglog(f, r, color="#1f77b4", lw=1.4)
        bottom.axhline(1.0, color="black", lw=0.6)
        ok = np.isfinite(r)
        if ok.any():
            i = int(np.nanargmax(np.where(ok, r, np.nan)))
            bottom.plot([f[i]], [r[i]], "o", color="#d62728")
            bottom.set_title(f"peak {r[i]:.3g} at {f[i]:.3g} Hz", fontsize=9, loc="right")
        bottom.set_ylabel("H/V (ratio)" if ratio_key == "hv" else "spectral ratio")
        readable_log_axis(bottom.yaxis)
        bottom.grid(True, which="both", alpha=0.3)
        last = bottom
    last.set_xlabel("frequency (Hz)")
    readable_log_axis(last.xaxis)
    fig.tight_layout()
    return fig


# ----------------------------------------------------------------- 3D
THREE_D = ("dda-fractures", "dda-blocks3d")


def file_format(path):
    """The dda format attribute of an HDF5 file, after the checks every file gets."""
    if not os.path.exists(path):
        fail(f"{path}: file not found")
    if os.path.isdir(path):
        fail(f"{path}: is a folder, not a file")
    try:
        if not h5py.is_hdf5(path):
            fail(f"{path}: is not an HDF5 file")
        with h5py.File(path, "r") as f:
            return text(f.attrs.get("format", ""))
    except OSError as exc:
        fail(f"{path}: cannot read the file ({exc.strerror or exc})")


def plot_3d(paths, formats, labels, a):
    import dda_plot3d as p3

    n = len(paths)
    cols = min(n, 2)
    rows = (n + cols - 1) // cols
    fig = plt.figure(figsize=(7.5 * cols, 6.0 * rows))
    # Room on the left: the z label of a 3D axes lies outside its box.
    fig.subplots_adjust(left=0.08, right=0.95)
    for k, (path, fm, label) in enumerate(zip(paths, formats, labels)):
        ax = fig.add_subplot(rows, cols, k + 1, projection="3d")
        try:
            with h5py.File(path, "r") as f:
                def arr(name, shape_tail=(), dtype=float):
                    if name in f:
                        return np.asarray(f[name][()], dtype=dtype)
                    return np.zeros((0,) + shape_tail, dtype=dtype)
                set_names = [text(s) for s in f["sets/name"][()]] if "sets/name" in f else []
                m = p3.read_fractures(f, arr) if fm == "dda-fractures" else p3.read_blocks3d(f, arr)
        except (OSError, KeyError, ValueError, TypeError) as exc:
            fail(f"{path}: cannot read it as a {fm} file ({exc})")
        if label is None:
            label = p3.describe(m, fm, set_names)
        if fm == "dda-fractures":
            p3.draw_fractures(ax, m, set_names, set_colours(len(set_names)), a.view, label)
        else:
            p3.draw_blocks3d(ax, m, a.color, a.explode, a.view, label)
    return fig


# -------------------------------------------------------------------- main


# ----------------------------------------------------------------- results
RESULTS_ONLY_KINDS = ("sections", "contacts", "histories", "energy", "steps", "all")
FIGURE_EXTENSIONS = (".png", ".svg", ".pdf")


def plot_results(a):
    """A results file: one figure (-o FIG.png) or, when -o is a folder, every
    figure that applies (--kind all, the default there) as KIND.png."""
    import results_figures as rf
    from results_data import ResultsError, read_results

    try:
        r = read_results(a.files[0], h5py)
    except ResultsError as exc:
        fail(str(exc))
    ext = os.path.splitext(a.output)[1].lower()
    to_folder = os.path.isdir(a.output) or ext == ""
    if not to_folder and ext not in FIGURE_EXTENSIONS:
        fail(f"{a.output}: give a figure ending in .png, .svg or .pdf, or a folder for all the figures")
    if r.dim == 2 and a.component not in ("mean",) + STRESS_2D:
        fail(f"--component {a.component}: a 2D results file has the stresses mean, {', '.join(STRESS_2D)}")
    if to_folder:
        parent = os.path.dirname(os.path.abspath(a.output))
        if not os.path.isdir(parent):
            fail(f"{a.output}: cannot write: the folder {parent} does not exist")
        if os.path.exists(a.output) and not os.path.isdir(a.output):
            fail(f"{a.output}: is a file; give a folder, or a figure ending in .png, .svg or .pdf")
        os.makedirs(a.output, exist_ok=True)
        kinds = rf.kinds_of(r) if a.kind in ("auto", "all") else (a.kind,)
    else:
        if a.kind == "all":
            fail(f"--kind all writes several figures: give -o a folder, not {a.output}")
        folder = os.path.dirname(os.path.abspath(a.output))
        if not os.path.isdir(folder):
            fail(f"{a.output}: cannot write: the folder {folder} does not exist")
        kinds = ("blocks" if a.kind == "auto" else a.kind,)
    for kind in kinds:
        problem = rf.check_kind(r, kind)
        if problem:
            fail(problem)
    problem = rf.check_times(r, a.times or [])
    if problem:
        fail(problem)
    opts = rf.FigureOptions(a.times, a.color_by, a.component, a.vectors, a.look, a.section)
    try:
        rf.parse_choices(r, opts)
    except ValueError as exc:
        fail(str(exc))
    for kind in kinds:
        fig, note = rf.draw(r, kind, opts)
        if a.title:
            fig.suptitle(a.title)
        out = os.path.join(a.output, f"{kind}.png") if to_folder else a.output
        save_atomically(fig, out)
        rf.close(fig)
        if note:
            print(f"note: {note}.")
    return 0


class Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2
        fail(f"{message} (see {PROG} --help)")


def main(argv=None):
    p = Parser(prog=PROG, description="Draw dda lines/blocks files or block-size histograms.",
               formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    p.add_argument("files", nargs="+", metavar="FILE.h5",
                   help="dda-lines or dda-blocks files (--kind compare/spectra: one dda compare/spectra CSV)")
    p.add_argument("-o", "--output", required=True, metavar="OUT", help="OUT.png, OUT.svg or OUT.pdf")
    p.add_argument("--kind", choices=["auto", "lines", "blocks", "histograms", "compare", "spectra", "sections",
                                      "contacts", "histories", "energy", "steps", "all"],
                   default="auto")
    p.add_argument("--labels", nargs="+", metavar="LABEL", help="one label per file")
    p.add_argument("--title", help="figure title")
    p.add_argument("--bins", type=int, default=30, help="histogram bins (default 30)")
    p.add_argument("--fraction", action="store_true",
                   help="histograms: fraction of each file's blocks instead of counts")
    p.add_argument("--no-names", action="store_true", help="do not write point names")
    p.add_argument("--amplitude-unit", metavar="UNIT", help="spectra: the unit of the Fourier amplitude")
    p.add_argument("--axes", nargs=2, metavar=("XLABEL", "YLABEL"),
                   help="2D maps: axis labels (default 'x (m)' 'y (m)'), e.g. a section's own axes")
    p.add_argument("--color", choices=["removability", "body", "layer"], default="removability",
                   help="3D blocks: colour bodies by block-theory mode (default), at random, or by bed")
    p.add_argument("--explode", type=float, default=0.0, metavar="F",
                   help="3D blocks: move bodies apart by F times their offset from the centre")
    p.add_argument("--view", type=float, nargs=2, default=[25.0, -60.0], metavar=("ELEV", "AZIM"),
                   help="3D: camera elevation and azimuth, degrees (default 25 -60)")
    r = p.add_argument_group("results files (dda-results, dda-results3d)")
    r.add_argument("--times", type=float, nargs="+", metavar="T",
                   help="blocks: draw the frames nearest these times, s (default: the last)")
    r.add_argument("--color-by", choices=["displacement", "velocity", "stress"], default="displacement",
                   help="blocks, sections: colour blocks by |u|, |v| or a stress component")
    r.add_argument("--component", choices=list(STRESS_CHOICES), default="mean",
                   help="--color-by stress: the component (default mean normal stress)")
    r.add_argument("--vectors", action="store_true", help="blocks: draw displacement vectors")
    r.add_argument("--look", nargs="+", metavar="DIR",
                   help="3D: lines of sight, TREND/PLUNGE or north, south, east, west, plan "
                        "(default north west plan)")
    r.add_argument("--section", nargs="+", metavar="AXIS=VALUE",
                   help="3D sections: planes x=..., y=... or z=... (m; default: through the middle)")
    a = p.parse_args(argv)

    if a.kind not in ("compare", "spectra") and any(file_format(f) in RESULTS_FORMATS for f in a.files):
        if len(a.files) != 1:
            fail(f"a results file is drawn on its own; got {len(a.files)} files")
        return plot_results(a)
    if a.kind in RESULTS_ONLY_KINDS:
        fail(f"--kind {a.kind} draws a results file (dda-results or dda-results3d)")
    ext = os.path.splitext(a.output)[1].lower()
    if ext not in (".png", ".svg", ".pdf"):
        fail(f"{a.output}: the output must end in .png, .svg or .pdf")
    folder = os.path.dirname(os.path.abspath(a.output))
    if not os.path.isdir(folder):
        fail(f"{a.output}: cannot write: the folder {folder} does not exist")
    if a.kind == "compare":  # one CSV; --labels names the DDA and the reference curves
        if len(a.files) != 1:
            fail(f"--kind compare draws one dda compare CSV, got {len(a.files)} files")
        fig = plot_compare(a.files[0], (a.labels or []) + ["DDA", "reference"][len(a.labels or []):])
        if a.title:
            fig.suptitle(a.title)
        save_atomically(fig, a.output)
        return 0
    if a.kind == "spectra":  # one CSV; --labels names the spectra
        if len(a.files) != 1:
            fail(f"--kind spectra draws one dda spectra CSV, got {len(a.files)} files")
        fig = plot_spectra(a.files[0], a.labels or [], a.amplitude_unit)
        if a.title:
            fig.suptitle(a.title)
        save_atomically(fig, a.output)
        return 0
    if a.labels is not None and len(a.labels) != len(a.files):
        fail(f"--labels gives {len(a.labels)} labels for {len(a.files)} files")
    if a.bins < 1:
        fail(f"--bins must be at least 1, got {a.bins}")
    # Without --labels a histogram legend names the files (it compares them);
    # a map's title says what it shows instead.
    labels = a.labels or (["blocks"] if len(a.files) == 1 else [os.path.basename(f) for f in a.files])

    formats = [file_format(f) for f in a.files]
    if any(fm in THREE_D for fm in formats):
        if not all(fm in THREE_D for fm in formats):
            fail("3D files (fractures, 3D blocks) cannot be drawn together with 2D lines or blocks files")
        if a.kind not in ("auto", "blocks"):
            fail(f"--kind {a.kind} is for 2D files; 3D files are drawn with --kind auto")
        fig = plot_3d(a.files, formats, a.labels or [None] * len(a.files), a)
        if a.title:
            fig.suptitle(a.title)
        save_atomically(fig, a.output)
        return 0
    models = [Model(f) for f in a.files]
    if a.kind == "histograms":
        fig = plot_histograms(models, labels, a.bins, a.fraction)
    else:
        fig = plot_maps(models, a.labels or [None] * len(models), a.kind, not a.no_names,
                        a.axes or ("x (m)", "y (m)"))
    if a.title:
        fig.suptitle(a.title)
    save_atomically(fig, a.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
