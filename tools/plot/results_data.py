"""What the results figures need from a dda results file, 2D (`dda-results`)
or 3D (`dda-results3d`); the layout is in docs/formats.md ("Results file",
"3D results file"). Everything is read once, into numpy arrays, so that the
drawing modules never touch HDF5.

A problem with the file is a `ResultsError` whose text is one sentence
naming the file and the dataset; the callers turn it into their one-line
message and exit status.
"""

import numpy as np

from plot_io import origin_of

RESULTS_FORMATS = ("dda-results", "dda-results3d")
STATE_NAMES = ("open", "sliding", "locked")  # contact state codes 0, 1, 2


class ResultsError(Exception):
    pass


def text(value):
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    if isinstance(value, np.ndarray) and value.shape == ():
        return text(value[()])
    return str(value)


class Contacts:
    """The contacts of the last step (the results file keeps no others):
    where each acts, the two blocks, its state and its forces."""

    def __init__(self, point, block_a, block_b, state, normal, shear, time):
        self.point = point        # (C, dim) contact point, m
        self.block_a = block_a    # (C) block of the vertex (or first edge)
        self.block_b = block_b    # (C) block of the edge / face (or second edge)
        self.state = state        # (C) 0 open, 1 sliding, 2 locked
        self.normal = normal      # (C) normal force, N (2D: N per m of thickness)
        self.shear = shear        # (C) magnitude of the shear force, same unit
        self.time = time          # model time of the step they belong to, s

    def __len__(self):
        return len(self.state)


class Results:
    """A results file in memory. `dim` is 2 or 3; frames hold the block
    vertices at the output times; per-block values are per frame."""

    def __init__(self, path, f):
        self.path = path
        self.format = text(f.attrs.get("format", ""))
        if self.format not in RESULTS_FORMATS:
            raise ResultsError(f"{path}: is not a dda results file (format '{self.format}')")
        self.dim = 3 if self.format == "dda-results3d" else 2
        self.origin = origin_of(f, self.dim)  # positions are about it (docs/formats.md)
        self._f = f
        self.attrs = {k: text(f.attrs[k]) for k in f.attrs if k != "scenario"}
        self.scenario_text = text(f.attrs.get("scenario", ""))
        self.complete = int(f.attrs.get("complete", 0)) == 1
        self.end_time = float(f.attrs.get("time", 0.0))
        self._read_model()
        self._read_frames()
        self._read_series()
        self._read_steps()
        self._read_energy()
        self.contacts = self._read_contacts()
        from results_bolts import read_bolts  # here: results_bolts uses this module's ResultsError
        self.bolts = read_bolts(self, f)
        del self._f

    # ------------------------------------------------------------ helpers

    def _arr(self, name, dtype=float, required=True, tail=()):
        if name not in self._f:
            if required:
                raise ResultsError(f"{self.path}: has no /{name}")
            return np.zeros((0,) + tail, dtype=dtype)
        return np.asarray(self._f[name][()], dtype=dtype)

    def _strings(self, name):
        return [text(s) for s in self._f[name][()]] if name in self._f else []

    # ------------------------------------------------------------ parts

    def _read_model(self):
        d = self.dim
        self.vertices0 = self._arr("model/blocks/vertices").reshape(-1, d)
        if d == 2:
            self.offsets = self._arr("model/blocks/offsets", np.int64)
            if len(self.offsets) < 1 or self.offsets[0] != 0 or self.offsets[-1] != len(self.vertices0):
                raise ResultsError(f"{self.path}: /model/blocks/offsets does not match /model/blocks/vertices")
            self.num_blocks = len(self.offsets) - 1
        else:
            self.offsets = self._arr("model/blocks/vertex_offsets", np.int64)
            self.face_offsets = self._arr("model/blocks/face_offsets", np.int64)
            self.face_vertices = self._arr("model/faces/vertices", np.int64)
            self.face_vertex_offsets = self._arr("model/faces/offsets", np.int64)
            self.face_set = self._arr("model/faces/set", int)
            self.num_blocks = len(self.offsets) - 1
            if len(self.face_offsets) != self.num_blocks + 1 or self.offsets[-1] != len(self.vertices0):
                raise ResultsError(f"{self.path}: /model/blocks offsets do not match the vertices")
        self.fixed = self._arr("fixed", int, required=False)
        self.sizes = self._block_sizes()

    def _block_sizes(self):
        """Area (2D, m²) or the extent's volume proxy (3D: the stored volume)."""
        if self.dim == 3:
            return self._arr("model/blocks/volume", required=False)
        areas = []
        for poly in self.polygons(self.vertices0):
            x, y = poly[:, 0], poly[:, 1]
            areas.append(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))
        return np.array(areas)

    def _read_frames(self):
        d = self.dim
        self.frame_time = self._arr("frames/time")
        self.frame_vertices = self._arr("frames/vertices").reshape(len(self.frame_time), -1, d)
        self.frame_velocity = self._arr("frames/velocity").reshape(len(self.frame_time), self.num_blocks, -1)
        self.frame_stress = self._arr("frames/stress").reshape(len(self.frame_time), self.num_blocks, -1)
        if len(self.frame_time) == 0:
            raise ResultsError(f"{self.path}: has no frames (/frames/time is empty)")
        if self.frame_vertices.shape[1] != len(self.vertices0):
            raise ResultsError(f"{self.path}: /frames/vertices does not match /model/blocks/vertices")

    def _read_series(self):
        self.point_names = self._strings("points/name")
        self.series_time = self._arr("series/time")
        p, d = len(self.point_names), self.dim
        self.displacement = self._arr("series/displacement", required=p > 0).reshape(len(self.series_time), p, d)
        self.velocity = self._arr("series/velocity", required=p > 0).reshape(len(self.series_time), p, d)

    def _read_steps(self):
        self.step_time = self._arr("steps/time")
        self.step_dt = self._arr("steps/dt")
        self.step_iterations = self._arr("steps/iterations", int)
        self.step_cuts = self._arr("steps/dt_cuts", int, required=False)
        self.step_converged = self._arr("steps/converged", int, required=False)
        self.step_states = {s: self._arr(f"steps/{s}", int, required=False) for s in STATE_NAMES}

    def _read_energy(self):
        """The energy ledger (none in 3D files written before the 3D ledger)."""
        self.energy = {}
        if "energy/time" not in self._f:
            return
        for name in self._f["energy"]:
            self.energy[name] = self._arr(f"energy/{name}")

    def _read_contacts(self):
        if "checkpoint/contacts" not in self._f:
            return None
        time = float(self._f["checkpoint"].attrs.get("time", self.end_time))
        verts = self._arr("checkpoint/blocks/vertices", required=False).reshape(-1, self.dim)
        if len(verts) != len(self.vertices0):
            verts = self.frame_vertices[-1]
        self.contact_vertices = verts
        c = "checkpoint/contacts/"
        state = self._arr(c + "state", int)
        normal = self._arr(c + "normal_force")
        if self.dim == 2:
            block_a = self._arr(c + "vertex_block", int)
            block_b = self._arr(c + "edge_block", int)
            vertex = self._arr(c + "vertex", int)
            shear = np.abs(self._arr(c + "shear_force"))
            if np.any((block_a < 0) | (block_a >= self.num_blocks)) or np.any(
                    (block_b < 0) | (block_b >= self.num_blocks)):
                raise ResultsError(f"{self.path}: /checkpoint/contacts names a block the model does not have")
            start, count = self.offsets[block_a], np.diff(self.offsets)[block_a]
            if np.any((vertex < 0) | (vertex >= count)):
                raise ResultsError(f"{self.path}: /checkpoint/contacts/vertex is outside its block")
            point = verts[start + vertex] if len(state) else np.zeros((0, 2))
        else:
            block_a = self._arr(c + "i", int)
            block_b = self._arr(c + "j", int)
            point = self._arr(c + "point_now", tail=(3,)).reshape(-1, 3)
            shear = np.linalg.norm(self._arr(c + "shear_force").reshape(-1, 2), axis=1)
        n = len(state)
        if not (len(normal) == len(shear) == len(block_a) == len(block_b) == len(point) == n):
            raise ResultsError(f"{self.path}: the /checkpoint/contacts datasets differ in length")
        return Contacts(point, block_a, block_b, state, normal, shear, time)

    # ------------------------------------------------------------ geometry

    def polygons(self, vertices):
        """2D: the block polygons of one set of vertices (V, 2)."""
        return np.split(vertices, self.offsets[1:-1]) if self.num_blocks else []

    def block_means(self, vertices):
        """Mean of each block's vertices (B, dim): where a block is drawn from."""
        counts = np.diff(self.offsets)
        return np.add.reduceat(vertices, self.offsets[:-1], axis=0) / counts[:, None]

    def faces(self, block, vertices):
        """3D: the outer faces of one block as vertex arrays (inner faces of a
        body, set -3, are hidden)."""
        verts = vertices[self.offsets[block]:self.offsets[block + 1]]
        out = []
        for j in range(self.face_offsets[block], self.face_offsets[block + 1]):
            if self.face_set[j] == -3:
                continue
            idx = self.face_vertices[self.face_vertex_offsets[j]:self.face_vertex_offsets[j + 1]]
            out.append(verts[idx])
        return out

    def frame_index(self, t):
        """The frame nearest to time t."""
        return int(np.argmin(np.abs(self.frame_time - t)))


def read_results(path, h5py):
    """Results of `path`; ResultsError for anything wrong with it."""
    try:
        with h5py.File(path, "r") as f:
            return Results(path, f)
    except ResultsError:
        raise
    except (OSError, KeyError, ValueError, TypeError, IndexError) as exc:
        raise ResultsError(f"{path}: cannot read it as a dda results file ({exc})")
