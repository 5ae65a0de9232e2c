"""3D pictures for dda_plot.py: fractures files and 3D blocks files
(docs/formats.md, "3D HDF5 files"), drawn as shaded polygons in a 3D view.

The panel's title says what is drawn (blocks and bodies, or fractures by
set); --labels replaces it. A blocks file is drawn by rock body, coloured by its block-theory mode
(--color removability, the default: grey not exposed, tan tapered, khaki
removable but held by gravity, red falls, orange slides on one face, purple
slides on two faces), by body (random colours) or by bed (--color layer).
--explode F moves every body away from the model's centre by F times its
centroid's offset, to open the view into a jointed mass. A fractures file
is drawn as its discs (48-gons), polygons and persistent planes (clipped to
the domain box), coloured by joint set, in the outline of the domain.
--view ELEV AZIM sets the camera (degrees; default 25 -60).
"""

import math

import numpy as np
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

from plot_io import label_user_coordinates, origin_of

MODE_COLOURS = {
    0: ((0.80, 0.80, 0.80), "not exposed"),
    1: ((0.82, 0.71, 0.55), "tapered"),
    2: ((0.94, 0.90, 0.55), "removable, held by gravity"),
    3: ((0.84, 0.15, 0.16), "falls"),
    4: ((1.00, 0.50, 0.05), "slides on one face"),
    5: ((0.58, 0.40, 0.74), "slides on two faces"),
}
MAX_FACES = 60000  # beyond this only faces on the outside of the model are drawn


def read_blocks3d(f, arr):
    m = {}
    m["vertices"] = arr("blocks/vertices", (3,)).reshape(-1, 3)
    m["voff"] = arr("blocks/vertex_offsets", dtype=np.int64)
    m["foff"] = arr("blocks/face_offsets", dtype=np.int64)
    m["fv"] = arr("faces/vertices", dtype=np.int64)
    m["fvoff"] = arr("faces/offsets", dtype=np.int64)
    m["fset"] = arr("faces/set", dtype=int)
    m["centroid"] = arr("blocks/centroid", (3,)).reshape(-1, 3)
    m["volume"] = arr("blocks/volume")
    m["body"] = arr("blocks/body", dtype=int)
    m["layer"] = arr("blocks/layer", dtype=int)
    m["mode"] = arr("bodies/removability", dtype=int)
    m["box"] = arr("domain/box", (3,)).reshape(-1, 3)
    m["origin"] = origin_of(f, 3)
    nb = len(m["voff"]) - 1
    if nb < 0 or len(m["foff"]) != nb + 1 or len(m["body"]) != nb:
        raise ValueError("/blocks offsets do not match")
    return m


def read_fractures(f, arr):
    m = {}
    m["shape"] = arr("fractures/shape", dtype=int)
    m["normal"] = arr("fractures/normal", (3,)).reshape(-1, 3)
    m["centre"] = arr("fractures/centre", (3,)).reshape(-1, 3)
    m["radius"] = arr("fractures/radius")
    m["vertices"] = arr("fractures/vertices", (3,)).reshape(-1, 3)
    m["offsets"] = arr("fractures/offsets", dtype=np.int64)
    m["set"] = arr("fractures/set", dtype=int)
    m["box"] = arr("domain/box", (3,)).reshape(-1, 3)
    m["origin"] = origin_of(f, 3)
    return m


def describe(m, fmt, set_names):
    """A panel title that says what is drawn, not which file it came from."""
    if fmt == "dda-fractures":
        n = len(m["shape"])
        return f"{n} fractures in {len(set_names)} set{'s' if len(set_names) != 1 else ''}"
    nb = len(m["voff"]) - 1
    bodies = len(set(int(b) for b in m["body"] if b >= 0))
    return f"{nb} blocks in {bodies} rock bod{'ies' if bodies != 1 else 'y'}"


def plane_basis(n):
    any_axis = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    e1 = np.cross(n, any_axis)
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(n, e1)


def plane_in_box(n, c, box):
    """The polygon where the plane through c with normal n cuts the box."""
    lo, hi = box
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
    d = corners @ n - c @ n
    pts = []
    for i in range(8):
        for j in range(i + 1, 8):
            if bin(i ^ j).count("1") != 1:
                continue  # not an edge of the box
            if d[i] * d[j] < 0:
                t = d[i] / (d[i] - d[j])
                pts.append(corners[i] + t * (corners[j] - corners[i]))
            elif d[i] == 0:
                pts.append(corners[i])
    if len(pts) < 3:
        return None
    pts = np.array(pts)
    e1, e2 = plane_basis(n)
    mid = pts.mean(axis=0)
    ang = np.arctan2((pts - mid) @ e2, (pts - mid) @ e1)
    return pts[np.argsort(ang)]


def box_edges(box):
    lo, hi = box
    c = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
    return [(c[i], c[j]) for i in range(8) for j in range(i + 1, 8) if bin(i ^ j).count("1") == 1]


def finish_axes(ax, pts, view, title, origin=(0.0, 0.0, 0.0)):
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    # Zoomed out a little: at full size the axis labels fall outside the
    # picture for many camera angles (the z label first).
    ax.set_box_aspect(tuple(np.maximum(hi - lo, 1e-9)), zoom=0.8)
    ax.view_init(elev=view[0], azim=view[1])
    ax.set_xlabel("x east (m)")
    ax.set_ylabel("y north (m)")
    ax.zaxis.set_rotate_label(False)  # upright: matplotlib turns it upside down for some camera angles
    ax.set_zlabel("z up\n(m)", labelpad=6)
    ax.set_title(title, fontsize=10)
    label_user_coordinates((ax.xaxis, ax.yaxis, ax.zaxis), origin)


def draw_blocks3d(ax, m, color, explode, view, title):
    nb = len(m["voff"]) - 1
    rng = np.random.default_rng(12345)
    nbody = int(m["body"].max()) + 1 if nb else 0
    body_rgb = 0.55 * np.array([rng.uniform(0.2, 1.0, 3) for _ in range(max(nbody, 1))]) + 0.45
    centre = m["centroid"].mean(axis=0) if nb else np.zeros(3)
    # Body centroids, for the exploded view.
    bc = np.zeros((max(nbody, 1), 3))
    bv = np.zeros(max(nbody, 1))
    for i in range(nb):
        b = m["body"][i]
        if b >= 0:
            bc[b] += m["volume"][i] * m["centroid"][i]
            bv[b] += m["volume"][i]
    bc /= np.maximum(bv, 1e-300)[:, None]
    outside_only = len(m["fset"]) > MAX_FACES
    polys, colours = [], []
    for i in range(nb):
        verts = m["vertices"][m["voff"][i]:m["voff"][i + 1]]
        b = m["body"][i]
        shift = explode * (bc[b] - centre) if b >= 0 else 0
        if color == "removability" and b >= 0 and b < len(m["mode"]):
            rgb = MODE_COLOURS.get(int(m["mode"][b]), MODE_COLOURS[0])[0]
        elif color == "layer":
            rgb = (0.85, 0.74, 0.56) if m["layer"][i] % 2 == 0 else (0.62, 0.72, 0.80)
        else:
            rgb = body_rgb[b] if b >= 0 else (0.8, 0.8, 0.8)
        for j in range(m["foff"][i], m["foff"][i + 1]):
            s = m["fset"][j]
            if s == -3 or (outside_only and s >= 0):
                continue  # faces inside a body, or hidden inside the mass
            polys.append(verts[m["fv"][m["fvoff"][j]:m["fvoff"][j + 1]]] + shift)
            colours.append(rgb)
    if polys:
        lw = 0.3 if len(polys) < 20000 else 0.1
        ax.add_collection3d(Poly3DCollection(polys, facecolors=colours, edgecolors="black", linewidths=lw))
    pts = np.vstack(polys) if polys else (m["box"] if len(m["box"]) == 2 else np.zeros((2, 3)))
    finish_axes(ax, pts, view, title, m["origin"])
    if color == "removability" and len(m["mode"]):
        from matplotlib.patches import Patch
        present = sorted(set(int(x) for x in m["mode"]))
        ax.legend(handles=[Patch(color=MODE_COLOURS[k][0], label=f"{MODE_COLOURS[k][1]} ({int(np.sum(m['mode'] == k))})")
                           for k in present if k in MODE_COLOURS], fontsize=7, loc="upper left")


def draw_fractures(ax, m, set_names, colours, view, title):
    polys, cols = [], []
    box = m["box"] if len(m["box"]) == 2 and np.all(m["box"][1] > m["box"][0]) else None
    for i in range(len(m["shape"])):
        n, c = m["normal"][i], m["centre"][i]
        if m["shape"][i] == 1:
            e1, e2 = plane_basis(n)
            t = np.linspace(0, 2 * math.pi, 48, endpoint=False)
            poly = c + m["radius"][i] * (np.outer(np.cos(t), e1) + np.outer(np.sin(t), e2))
        elif m["shape"][i] == 2:
            poly = m["vertices"][m["offsets"][i]:m["offsets"][i + 1]]
        else:
            poly = plane_in_box(n, c, box) if box is not None else None
        if poly is None or len(poly) < 3:
            continue
        polys.append(poly)
        s = m["set"][i]
        cols.append(colours[s % len(colours)] if s >= 0 else (0.3, 0.3, 0.3, 1))
    if polys:
        ax.add_collection3d(Poly3DCollection(polys, facecolors=cols, edgecolors="none", alpha=0.75))
    if box is not None:
        ax.add_collection3d(Line3DCollection(box_edges(box), colors="black", linewidths=0.8))
    pts = np.vstack([p for p in polys] + ([box] if box is not None else [])) if (polys or box is not None) \
        else np.zeros((2, 3))
    if box is not None:
        pts = box  # the domain frames the view; discs may reach beyond it
    finish_axes(ax, pts, view, title, m["origin"])
    from matplotlib.patches import Patch
    used = sorted(set(int(s) for s in m["set"] if s >= 0))
    ax.legend(handles=[Patch(color=colours[s % len(colours)], label=set_names[s] if s < len(set_names) else f"set {s}")
                       for s in used], fontsize=7, loc="upper left")
