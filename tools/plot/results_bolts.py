"""Rock bolts in the block figures: where each bolt is at a frame, its force
and whether it has broken, and its drawing (intact: a solid line; broken: a
dashed line in another colour).

The results file keeps the bolts' ends only at the checkpoint (the last
step, /checkpoint/bolts) and their force and state at every step (/bolts).
An end rides with its block, and a DDA block moves affinely (translation,
rotation and constant strain, step after step), so the end at any frame is
the affine map that takes the block's checkpoint vertices to that frame's
vertices, applied to the end at the checkpoint. The block of an end is the
one it lies in (or nearest to, for an end on a block's face) at the
checkpoint.
"""

import numpy as np

from results_data import ResultsError

INTACT_STYLE = dict(color="black", linestyle="-", linewidth=1.6)
BROKEN_STYLE = dict(color="#d7191c", linestyle=(0, (3, 2)), linewidth=1.6)


class Bolts:
    """The bolts of a results file: names, ends at the checkpoint and the
    block each end rides with, and force and broken flag at every sample."""

    def __init__(self, names, ends, blocks, checkpoint_vertices, time, force, broken):
        self.names = names                      # (K)
        self.ends = ends                        # (K, 2, dim): anchor, head at the checkpoint, m
        self.blocks = blocks                    # (K, 2): block of the anchor, of the head
        self.checkpoint_vertices = checkpoint_vertices  # (V, dim)
        self.time = time                        # (S) sample times, s
        self.force = force                      # (S, K) axial force, tension positive
        self.broken = broken                    # (S, K) 1 once broken

    def __len__(self):
        return len(self.names)

    def sample_at(self, t):
        """The sample nearest to time t (frames fall on steps, samples are every step)."""
        return int(np.argmin(np.abs(self.time - t)))


def read_bolts(r, f):
    """The bolts of results file `f` (already read into `r`), or None for a
    run without bolts."""
    if "bolts/name" not in f or "checkpoint/bolts/anchor" not in f:
        return None
    d = r.dim
    names = r._strings("bolts/name")
    k = len(names)
    if k == 0:
        return None
    time = r._arr("bolts/time")
    s = len(time)
    try:
        force = r._arr("bolts/force").reshape(s, k)
        broken = r._arr("bolts/broken", int).reshape(s, k)
        anchor = r._arr("checkpoint/bolts/anchor").reshape(k, d)
        head = r._arr("checkpoint/bolts/head").reshape(k, d)
        verts = r._arr("checkpoint/blocks/vertices").reshape(-1, d)
    except ValueError:
        raise ResultsError(f"{r.path}: the /bolts and /checkpoint/bolts datasets do not match /bolts/name")
    if len(verts) != len(r.vertices0):
        raise ResultsError(f"{r.path}: /checkpoint/blocks/vertices does not match /model/blocks/vertices")
    ends = np.stack([anchor, head], axis=1)
    lo = np.minimum.reduceat(verts, r.offsets[:-1], axis=0)
    hi = np.maximum.reduceat(verts, r.offsets[:-1], axis=0)
    blocks = np.array([[block_of(r, verts, lo, hi, p) for p in pair] for pair in ends], dtype=int)
    return Bolts(names, ends, blocks, verts, time, force, broken)


# ---------------------------------------------------------------- geometry

def block_of(r, vertices, lo, hi, p):
    """The block `p` lies deepest in (or is nearest to) at `vertices`; only
    the blocks whose box (lo, hi) holds p are looked at, all if none does."""
    pad = 1e-9 * max(1.0, float(np.max(hi - lo)))
    near = np.flatnonzero(np.all((lo - pad <= p) & (p <= hi + pad), axis=1))
    best, best_depth = -1, np.inf
    for b in (near if len(near) else range(r.num_blocks)):
        depth = signed_distance_2d(r, vertices, b, p) if r.dim == 2 else signed_distance_3d(r, vertices, b, p)
        if depth < best_depth:
            best, best_depth = b, depth
    return best


def signed_distance_2d(r, vertices, b, p):
    """Distance from p to block b's outline, negative inside."""
    poly = vertices[r.offsets[b]:r.offsets[b + 1]]
    a, e = poly, np.roll(poly, -1, axis=0)
    ab = e - a
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300), 0, 1)
    dist = np.min(np.linalg.norm(a + t[:, None] * ab - p, axis=1))
    # even-odd rule: a ray towards +x crosses the outline an odd number of times from inside
    crosses = ((a[:, 1] > p[1]) != (e[:, 1] > p[1])) & (
        p[0] < a[:, 0] + (p[1] - a[:, 1]) * ab[:, 0] / np.where(ab[:, 1] == 0, 1e-300, ab[:, 1]))
    return -dist if np.count_nonzero(crosses) % 2 else dist


def signed_distance_3d(r, vertices, b, p):
    """Largest distance of p outside block b's face planes (blocks are convex;
    negative inside: how deep)."""
    verts = vertices[r.offsets[b]:r.offsets[b + 1]]
    out = -np.inf
    for j in range(r.face_offsets[b], r.face_offsets[b + 1]):
        loop = verts[r.face_vertices[r.face_vertex_offsets[j]:r.face_vertex_offsets[j + 1]]]
        n = np.cross(loop - loop.mean(axis=0), np.roll(loop, -1, axis=0) - loop.mean(axis=0)).sum(axis=0)
        norm = np.linalg.norm(n)
        if norm > 0:
            out = max(out, float(np.dot(n / norm, p - loop.mean(axis=0))))
    return out


def carried(r, bolts, frame_vertices, block, p):
    """Point p of `block` at the checkpoint, carried to `frame_vertices` by the
    block's affine motion (a least-squares fit: exact for DDA's motion)."""
    lo, hi = r.offsets[block], r.offsets[block + 1]
    x0 = bolts.checkpoint_vertices[lo:hi]
    x1 = frame_vertices[lo:hi]
    a = np.hstack([x0, np.ones((len(x0), 1))])
    m, *_ = np.linalg.lstsq(a, x1, rcond=None)
    return np.append(p, 1.0) @ m


def ends_at(r, bolts, frame):
    """(K, 2, dim): anchor and head of every bolt at frame `frame`."""
    verts = r.frame_vertices[frame]
    return np.array([[carried(r, bolts, verts, bolts.blocks[k, e], bolts.ends[k, e]) for e in range(2)]
                     for k in range(len(bolts))])


# ---------------------------------------------------------------- drawing

def draw_bolts(ax, r, frame, project=None):
    """Draws the bolts at `frame` on `ax` (3D: through `project`, a view's
    projection to the screen) and adds their legend; returns the number drawn."""
    bolts = r.bolts
    if not bolts:
        return 0
    ends = ends_at(r, bolts, frame)
    if project is not None:
        ends = project(ends)
    s = bolts.sample_at(r.frame_time[frame])
    broken = bolts.broken[s] != 0
    for k in range(len(bolts)):
        style = BROKEN_STYLE if broken[k] else INTACT_STYLE
        ax.plot(ends[k, :, 0], ends[k, :, 1], zorder=5, **style)
    handles = []
    if np.any(~broken):
        handles.append(ax.plot([], [], label=f"bolt ({np.count_nonzero(~broken)} intact)", **INTACT_STYLE)[0])
    if np.any(broken):
        handles.append(ax.plot([], [], label=f"bolt ({np.count_nonzero(broken)} broken)", **BROKEN_STYLE)[0])
    ax.legend(handles=handles, loc="upper right", fontsize=7, framealpha=0.8)
    return len(bolts)
