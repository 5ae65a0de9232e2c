"""Flat pictures of 3D blocks: orthographic views along a line of sight given
as trend/plunge, and axis-parallel sections. Both give ordinary 2D axes
whose labels say which model direction each axis is, so distances read off
a view or a section are real lengths in metres.

Line of sight: trend (degrees clockwise from north, y) and plunge (degrees
below the horizontal) of the direction the viewer looks: 0/0 looks north
(x east to the right, z up), 270/0 looks west, 0/90 looks straight down
(plan: x east to the right, y north up). Model axes: x east, y north, z up.
"""

import math

import numpy as np

NAMED_VIEWS = {"north": (0.0, 0.0), "west": (270.0, 0.0), "south": (180.0, 0.0),
               "east": (90.0, 0.0), "plan": (0.0, 90.0)}
AXIS_NAMES = {0: "x east", 1: "y north", 2: "z up"}


def parse_view(text):
    """'north', 'plan', ... or 'TREND/PLUNGE' -> (trend, plunge) in degrees."""
    if text in NAMED_VIEWS:
        return NAMED_VIEWS[text]
    parts = text.split("/")
    try:
        trend, plunge = float(parts[0]), float(parts[1])
        if len(parts) != 2 or not (-90 <= plunge <= 90) or not all(map(math.isfinite, (trend, plunge))):
            raise ValueError
    except (ValueError, IndexError):
        raise ValueError(f"--look {text}: give TREND/PLUNGE in degrees (plunge -90..90) or one of "
                         f"{', '.join(NAMED_VIEWS)}")
    return trend, plunge


def view_name(trend, plunge):
    for name, tp in NAMED_VIEWS.items():
        if abs(tp[0] - trend % 360) < 1e-9 and abs(tp[1] - plunge) < 1e-9:
            return "plan view (looking down)" if name == "plan" else f"looking {name}"
    return f"looking towards {trend % 360:03.0f}°, plunge {plunge:g}°"


class View:
    """Screen axes `right`, `up` and the line of sight `sight` (unit vectors)."""

    def __init__(self, trend, plunge):
        t, p = math.radians(trend), math.radians(plunge)
        self.trend, self.plunge = trend, plunge
        self.sight = np.array([math.sin(t) * math.cos(p), math.cos(t) * math.cos(p), -math.sin(p)])
        right = np.cross(self.sight, [0.0, 0.0, 1.0])
        if np.linalg.norm(right) < 1e-9:  # looking straight down or up: the trend is the screen's up
            right = np.array([math.cos(t), -math.sin(t), 0.0])
            if plunge < 0:
                right = -right
        self.right = right / np.linalg.norm(right)
        self.up = np.cross(self.right, self.sight)

    def project(self, points):
        p = np.asarray(points)
        return np.stack([p @ self.right, p @ self.up], axis=-1)

    def depth(self, points):
        return np.asarray(points) @ self.sight

    def axis_labels(self):
        return describe_direction(self.right), describe_direction(self.up)

    @property
    def title(self):
        return view_name(self.trend, self.plunge)


def describe_direction(v):
    """'x east (m)' for a model axis, else the direction's trend and plunge."""
    for axis in range(3):
        if abs(abs(v[axis]) - 1) < 1e-9:
            return f"{AXIS_NAMES[axis]} (m)" if v[axis] > 0 else f"{AXIS_NAMES[axis]}, reversed (m)"
    trend = math.degrees(math.atan2(v[0], v[1])) % 360
    plunge = -math.degrees(math.asin(max(-1.0, min(1.0, v[2]))))
    if abs(plunge) < 1e-9:
        return f"horizontal, towards {trend:03.0f}° (m)"
    if abs(abs(plunge) - 90) < 1e-9:
        return "z up (m)" if plunge < 0 else "z down (m)"
    slope = f"rising {-plunge:.0f}°" if plunge < 0 else f"plunging {plunge:.0f}°"
    return f"towards {trend:03.0f}°, {slope} (m)"


def view_polygons(r, vertices, view):
    """(polygons in screen coordinates, block of each), far faces first so
    near ones paint over them."""
    polys, blocks, depths = [], [], []
    for b in range(r.num_blocks):
        for face in r.faces(b, vertices):
            polys.append(view.project(face))
            blocks.append(b)
            depths.append(view.depth(face).mean())
    order = np.argsort(-np.asarray(depths), kind="stable")
    return [polys[i] for i in order], np.asarray(blocks, dtype=int)[order]


def parse_section(text, r):
    """'x=5', 'y=2.5' or 'z=1' -> (axis index, value): the value the user
    gave, in their coordinates, about the file's local origin as the
    vertices are."""
    try:
        name, value = text.split("=")
        axis = "xyz".index(name.strip())
        value = float(value)
        if not math.isfinite(value):
            raise ValueError
    except ValueError:
        raise ValueError(f"--section {text}: give AXIS=VALUE, e.g. y=5 (a plane normal to x, y or z, m)")
    return axis, value - r.origin[axis]


def default_sections(vertices):
    """Vertical sections through the middle of the model, across x and across y."""
    mid = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    return [(1, float(mid[1])), (0, float(mid[0]))]


def section_axes(axis):
    """The two model axes a section normal to `axis` is drawn in."""
    return {0: (1, 2), 1: (0, 2), 2: (0, 1)}[axis]


def section_polygons(r, vertices, axis, value):
    """Where the plane coordinate[axis] = value cuts each block: (polygons in
    the section's two axes, block of each). Blocks are convex, so the cut is
    the convex polygon through the points where the block's edges cross."""
    a, b = section_axes(axis)
    polys, blocks = [], []
    for k in range(r.num_blocks):
        cuts = []
        for j in range(r.face_offsets[k], r.face_offsets[k + 1]):
            idx = r.face_vertices[r.face_vertex_offsets[j]:r.face_vertex_offsets[j + 1]]
            face = vertices[r.offsets[k] + idx]
            d = face[:, axis] - value
            for i in range(len(face)):
                p, q, dp, dq = face[i], face[(i + 1) % len(face)], d[i], d[(i + 1) % len(face)]
                if dp == 0:
                    cuts.append(p)
                elif dp * dq < 0:
                    cuts.append(p + dp / (dp - dq) * (q - p))
        if len(cuts) < 3:
            continue
        pts = np.unique(np.round(np.array(cuts)[:, [a, b]], 12), axis=0)
        if len(pts) < 3:
            continue
        mid = pts.mean(axis=0)
        order = np.argsort(np.arctan2(pts[:, 1] - mid[1], pts[:, 0] - mid[0]))
        polys.append(pts[order])
        blocks.append(k)
    return polys, np.asarray(blocks, dtype=int)


def section_title(axis, value, origin=(0.0, 0.0, 0.0)):
    """`value` about the local origin; the title gives the user's coordinate."""
    return f"section {'xyz'[axis]} = {value + origin[axis]:.15g} m" if origin[axis] else \
        f"section {'xyz'[axis]} = {value:g} m"


def section_labels(axis):
    a, b = section_axes(axis)
    return f"{AXIS_NAMES[a]} (m)", f"{AXIS_NAMES[b]} (m)"
