"""Pictures of the blocks of a results file: the deformed blocks at chosen
times coloured by a per-block quantity (2D: the model plane; 3D: views from
chosen directions, and sections), and the contacts of the last step (force
chains whose line width is proportional to the force, and the contact
states).
"""

import numpy as np
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.colors import Normalize
from matplotlib.lines import Line2D

import results_views3d as v3
from plot_io import label_user_coordinates
from results_bolts import draw_bolts
from results_quantities import block_quantity, readable_unit, shared_scale

STATE_STYLE = {0: ("0.55", "open"), 1: ("#e66101", "sliding"), 2: ("#2c7bb6", "locked")}
BLOCK_GREY = "0.88"
MAX_ARROWS = 400


def time_label(r, frame):
    """What a frame is, in words, including when the run did not finish."""
    t = r.frame_time[frame]
    text = f"t = {t:g} s"
    if frame == 0:
        text += " (start of the run)"
    elif frame == len(r.frame_time) - 1:
        text += " (end of the run)" if r.complete else " (last frame saved)"
    if not r.complete:
        text += f"; run incomplete, stopped at t = {r.end_time:g} s"
    return text


def frames_for(r, times):
    """Frame indices for the requested times (nearest frame); the last frame
    by default."""
    if not times:
        return [len(r.frame_time) - 1]
    return [r.frame_index(t) for t in times]


def edge_width(count):
    return 0.4 if count < 3000 else (0.2 if count < 30000 else 0.08)


def finish_plane(ax, points, xlabel, ylabel, title):
    ax.set_aspect("equal")
    if len(points):
        lo, hi = points.min(axis=0), points.max(axis=0)
        pad = 0.04 * max(hi[0] - lo[0], hi[1] - lo[1], 1e-9)
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)


def coloured_polygons(ax, polys, values, quantity, limits):
    """Polygons filled by value on the quantity's colour map."""
    pc = PolyCollection(polys, array=values, cmap=quantity.cmap, norm=Normalize(*limits),
                        edgecolors="0.15", linewidths=edge_width(len(polys)), zorder=2)
    ax.add_collection(pc)
    return pc


def draw_vectors(ax, origins, vectors, extent):
    """Displacement arrows, enlarged so that the longest is a tenth of the
    picture; returns the words for the title that say by how much."""
    length = np.linalg.norm(vectors, axis=1)
    if len(length) == 0 or not np.any(length > 0):
        return ""
    top = float(length.max())
    enlarge = 0.1 * extent / top
    every = max(1, len(origins) // MAX_ARROWS)  # a readable number of arrows
    origins, vectors = origins[::every], vectors[::every]
    ax.quiver(origins[:, 0], origins[:, 1], vectors[:, 0] * enlarge, vectors[:, 1] * enlarge, color="black",
              angles="xy", scale_units="xy", scale=1, width=0.003, zorder=6)
    factor, unit = readable_unit([top], "m")
    which = "" if every == 1 else f" (every {every}th block)"
    return f"\narrows{which}: displacement, longest {top * factor:.3g} {unit}, drawn {enlarge:.3g}× enlarged"


def plane_extent(points):
    return float(np.max(np.ptp(points, axis=0))) if len(points) else 1.0


def deformed_2d(r, frames, color_by, component, vectors):
    quantities = [block_quantity(r, k, color_by, component) for k in frames]
    factor, label, limits = shared_scale(quantities)
    fig, axes = plt.subplots(1, len(frames), figsize=(6.2 * len(frames) + 1, 5.2), squeeze=False)
    for ax, k, q in zip(axes.flat, frames, quantities):
        values = q.scaled_by(factor)
        verts = r.frame_vertices[k]
        pc = coloured_polygons(ax, r.polygons(verts), values, q, limits)
        arrows = ""
        if vectors:
            arrows = draw_vectors(ax, r.block_means(verts), r.block_means(verts) - r.block_means(r.vertices0),
                                  plane_extent(verts))
        draw_bolts(ax, r, k)
        finish_plane(ax, verts, "x (m)", "y (m)", time_label(r, k) + arrows)
        label_user_coordinates((ax.xaxis, ax.yaxis), r.origin)
        fig.colorbar(pc, ax=ax, label=label, shrink=0.85)
    fig.suptitle(f"Deformed blocks coloured by {quantities[0].label}", fontsize=11)
    fig.tight_layout()
    return fig


def deformed_3d(r, frames, color_by, component, vectors, looks):
    """One row per frame, one column per view direction."""
    quantities = [block_quantity(r, k, color_by, component) for k in frames]
    factor, label, limits = shared_scale(quantities)
    views = [v3.View(*tp) for tp in looks]
    fig, axes = plt.subplots(len(frames), len(views), figsize=(5.0 * len(views) + 1, 4.6 * len(frames)),
                             squeeze=False, layout="constrained")
    for row, (k, q) in enumerate(zip(frames, quantities)):
        values = q.scaled_by(factor)
        verts = r.frame_vertices[k]
        for col, view in enumerate(views):
            ax = axes[row, col]
            polys, blocks = v3.view_polygons(r, verts, view)
            pc = coloured_polygons(ax, polys, values[blocks], q, limits)
            screen = np.vstack(polys) if polys else np.zeros((0, 2))
            arrows = ""
            if vectors:
                means = r.block_means(verts)
                du = means - r.block_means(r.vertices0)
                arrows = draw_vectors(ax, view.project(means), view.project(du), plane_extent(screen))
            draw_bolts(ax, r, k, view.project)  # on top of the blocks, seen through them
            xlabel, ylabel = view.axis_labels()
            finish_plane(ax, screen, xlabel, ylabel, f"{view.title}\n{time_label(r, k)}{arrows}")
            label_user_coordinates((ax.xaxis, ax.yaxis), view.project(r.origin))
        fig.colorbar(pc, ax=list(axes[row]), label=label, shrink=0.85)
    fig.suptitle(f"Deformed blocks coloured by {quantities[0].label}", fontsize=11)
    return fig


def sections_3d(r, frame, color_by, component, sections):
    q = block_quantity(r, frame, color_by, component)
    values, label = q.scaled()
    limits = q.norm_limits(values)
    verts = r.frame_vertices[frame]
    sections = sections or v3.default_sections(verts)
    fig, axes = plt.subplots(1, len(sections), figsize=(5.4 * len(sections) + 1, 4.8), squeeze=False,
                             layout="constrained")
    pc = None
    for ax, (axis, value) in zip(axes.flat, sections):
        polys, blocks = v3.section_polygons(r, verts, axis, value)
        xlabel, ylabel = v3.section_labels(axis)
        if polys:
            pc = coloured_polygons(ax, polys, values[blocks], q, limits)
        else:
            ax.text(0.5, 0.5, "the plane cuts no block", ha="center", va="center", transform=ax.transAxes)
        finish_plane(ax, np.vstack(polys) if polys else np.zeros((0, 2)), xlabel, ylabel,
                     v3.section_title(axis, value, r.origin))
        label_user_coordinates((ax.xaxis, ax.yaxis), [r.origin[a] for a in v3.section_axes(axis)])
    if pc is not None:
        fig.colorbar(pc, ax=list(axes.flat), label=label, shrink=0.85)
    fig.suptitle(f"Sections through the blocks, {time_label(r, frame)}", fontsize=11)
    return fig


# ------------------------------------------------------------------ contacts


def no_contacts_note(r):
    """Why there is nothing to draw, or None when there are contacts."""
    if r.contacts is None:
        return f"{r.path} holds no contacts (no /checkpoint/contacts); only the blocks are drawn"
    if len(r.contacts) == 0:
        return f"{r.path}: no contacts at the last step (t = {r.contacts.time:g} s); only the blocks are drawn"
    return None


def contacts_figure(r, look):
    """Normal forces, shear forces and contact states of the last step (the
    only contacts a results file keeps). 3D: seen along `look`."""
    c = r.contacts
    verts = r.contact_vertices if c is not None else r.frame_vertices[-1]
    if r.dim == 2:
        project, blocks = (lambda p: p), r.polygons(verts)
        xlabel, ylabel, where = "x (m)", "y (m)", ""
    else:
        view = v3.View(*look)
        project = view.project
        blocks, _ = v3.view_polygons(r, verts, view)
        xlabel, ylabel = view.axis_labels()
        where = f", {view.title}"
    force_unit = "N/m" if r.dim == 2 else "N"
    fig, axes = plt.subplots(1, 3, figsize=(17, 5.4))
    note = no_contacts_note(r)
    when = f"t = {c.time:g} s" if c is not None else time_label(r, len(r.frame_time) - 1)
    for ax, title in zip(axes, ("normal force", "shear force", "contact state")):
        ax.add_collection(PolyCollection(blocks, facecolors=BLOCK_GREY, edgecolors="0.5",
                                         linewidths=edge_width(len(blocks)), zorder=1))
        finish_plane(ax, np.vstack(blocks) if len(blocks) else np.zeros((0, 2)), xlabel, ylabel,
                     f"{title}{where}")
        label_user_coordinates((ax.xaxis, ax.yaxis), project(np.asarray(r.origin)))
        if note:
            ax.text(0.5, 0.5, note.split(": ", 1)[-1] if ": " in note else note, ha="center", va="center",
                    wrap=True, fontsize=8, transform=ax.transAxes,
                    bbox={"fc": "white", "ec": "0.5"})
    if note is None:
        centres = project(r.block_means(verts))
        for ax, force, colour, name in ((axes[0], c.normal, "black", "normal"),
                                        (axes[1], c.shear, "#b2182b", "shear")):
            force_chains(ax, centres, c, np.abs(force), colour, force_unit, name)
        points = project(c.point)
        size = 14 if len(c) < 2000 else 5
        for state in (2, 0, 1):  # the few sliding contacts on top of the many locked ones
            colour, name = STATE_STYLE[state]
            sel = c.state == state
            axes[2].scatter(points[sel, 0], points[sel, 1], s=size, c=colour, zorder=5 + state % 2,
                            label=f"{name} ({int(sel.sum())})", edgecolors="none")
        axes[2].legend(fontsize=7, loc="upper right", title="state", title_fontsize=7)
    fig.suptitle(f"Contacts at the last step, {when}" + ("" if r.complete else " (run incomplete)")
                 + (f": {len(c)} contacts" if c is not None else ""), fontsize=11)
    fig.tight_layout()
    return fig, note


def force_chains(ax, centres, c, force, colour, unit, name):
    """A line between the two blocks' centres for each touching pair, width
    proportional to the sum of the pair's contact forces."""
    pairs = {}
    for a, b, f in zip(c.block_a, c.block_b, force):
        key = (min(a, b), max(a, b))
        pairs[key] = pairs.get(key, 0.0) + f
    keys = [k for k, f in pairs.items() if f > 0 and k[0] != k[1]]
    if not keys:
        ax.text(0.5, 0.05, f"no {name} force", ha="center", transform=ax.transAxes, fontsize=8)
        return
    total = np.array([pairs[k] for k in keys])
    top = float(total.max())
    widths = 0.3 + 4.7 * total / top
    segs = [[centres[a], centres[b]] for a, b in keys]
    ax.add_collection(LineCollection(segs, linewidths=widths, colors=colour, zorder=4, capstyle="round"))
    factor, shown = readable_unit([top], unit)
    handles = [Line2D([], [], color=colour, lw=0.3 + 4.7 * share, label=f"{share * top * factor:.3g} {shown}")
               for share in (1.0, 0.5, 0.1)]
    ax.legend(handles=handles, fontsize=7, loc="upper right", title=f"{name} force per block pair",
              title_fontsize=7)
