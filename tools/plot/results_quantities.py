"""The per-block quantities the results figures colour blocks by, with their
units and colour maps, and the choice of a readable unit (mm or m, kPa or
MPa) for a range of values.

Colour maps: viridis (perceptually uniform) for magnitudes, which are never
negative; RdBu_r, centred on zero, for signed stresses (tension positive,
red; compression blue).
"""

import numpy as np

SEQUENTIAL = "viridis"
DIVERGING = "RdBu_r"

# Stress components as stored per block (docs/formats.md), and the mean.
STRESS_2D = ("sxx", "syy", "sxy")
STRESS_3D = ("sxx", "syy", "szz", "syz", "szx", "sxy")
STRESS_CHOICES = ("mean",) + STRESS_3D


def readable_unit(values, unit):
    """(factor, unit label) that shows `values` (in m, m/s or Pa) with
    reasonable digits: mm below 0.1 m, kPa/MPa for stresses."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    top = float(np.max(np.abs(v))) if len(v) else 0.0
    if unit in ("m", "m/s"):
        if 0 < top < 0.1:
            return 1000.0, "mm" + unit[1:]
        return 1.0, unit
    if unit == "Pa":
        if top >= 1e6:
            return 1e-6, "MPa"
        if top >= 1e3:
            return 1e-3, "kPa"
        return 1.0, "Pa"
    if unit in ("N", "N/m"):
        if top >= 1e6:
            return 1e-6, "M" + unit
        if top >= 1e3:
            return 1e-3, "k" + unit
        return 1.0, unit
    if unit == "J" or unit == "J/m":
        if top >= 1e6:
            return 1e-6, "M" + unit
        if top >= 1e3:
            return 1e-3, "k" + unit
        return 1.0, unit
    return 1.0, unit


class Quantity:
    """One value per block with what it is: `values` in SI, `unit`, `label`
    (what the colour bar says) and whether it is signed."""

    def __init__(self, values, unit, label, signed):
        self.values, self.unit, self.label, self.signed = values, unit, label, signed

    def scaled(self):
        factor, unit = readable_unit(self.values, self.unit)
        return self.values * factor, f"{self.label} ({unit})"

    def scaled_by(self, factor):
        return self.values * factor

    def norm_limits(self, scaled_values):
        """Colour limits: 0..max for a magnitude, symmetric about 0 when signed."""
        v = scaled_values[np.isfinite(scaled_values)]
        if len(v) == 0:
            return 0.0, 1.0
        if self.signed:
            top = float(np.max(np.abs(v))) or 1.0
            return -top, top
        top = float(np.max(v))
        return 0.0, top if top > 0 else 1.0

    @property
    def cmap(self):
        return DIVERGING if self.signed else SEQUENTIAL


def block_quantity(r, frame, color_by, component):
    """The quantity `color_by` (displacement, velocity, stress) of every block
    at frame `frame` of results `r`."""
    d = r.dim
    if color_by == "displacement":
        u = r.block_means(r.frame_vertices[frame]) - r.block_means(r.vertices0)
        return Quantity(np.linalg.norm(u, axis=1), "m", "block displacement |u|", False)
    if color_by == "velocity":
        v = r.frame_velocity[frame][:, :d]
        return Quantity(np.linalg.norm(v, axis=1), "m/s", "block velocity |v|", False)
    names = STRESS_2D if d == 2 else STRESS_3D
    s = r.frame_stress[frame]
    if component == "mean":
        values = s[:, :d].mean(axis=1)
        label = "mean normal stress " + ("(sxx + syy)/2" if d == 2 else "(sxx + syy + szz)/3")
    else:
        if component not in names:
            raise ValueError(f"--component {component} is not a {d}D stress component (one of mean, "
                             f"{', '.join(names)})")
        values = s[:, names.index(component)]
        label = f"block stress {component}"
    return Quantity(values, "Pa", label + ", tension +", True)


def shared_scale(quantities):
    """(factor, colour-bar label, colour limits) common to several frames of
    one quantity, so that a colour means the same value in every panel."""
    q = quantities[0]
    everything = np.concatenate([x.values for x in quantities])
    factor, unit = readable_unit(everything, q.unit)
    return factor, f"{q.label} ({unit})", q.norm_limits(everything * factor)
