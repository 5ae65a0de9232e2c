#!/usr/bin/python3
"""Writes the slab cases of examples/friction_instabilities: a slab of NB
blocks bonded into one body, pressed onto a fixed base and dragged at one
end through a spring, with linear slip weakening on the slab-base interface
(Baillet's stick-slip-separation setting in DDA's terms).

Usage: make_slab.py OUT_DIR
Writes OUT_DIR/slab.geo and OUT_DIR/NAME.yaml for each case of CASES.

The numbers (SLAB, CASES) are read by analyse_slab.py, which imports this
file; tests/df/slab_model.hpp builds the same model for the ctest.
"""
import os
import sys

# The slab: L x H, NB blocks of L / NB, E and rho of a soft rock, on a
# rigid-enough base. The interface: slip weakening from mu_s to mu_d over
# Dc. The surcharge sigma (a point load on each block's centroid) dominates
# the slab's weight (rho g H = 1962 Pa). The spring is a bolt from a driver
# block, which a moving fixed point carries at vd, to the slab's right end,
# low (at y = H / 5) so that its pull tips the end block little.
SLAB = {
    "L": 1.0, "H": 0.1, "NB": 20, "E": 1.0e9, "nu": 0.25, "rho": 2000.0,
    "sigma": 1.0e5, "mu_s": 0.6, "mu_d": 0.5, "dc": 1.0e-4, "vd": 0.01,
    "start_mu": 0.3,  # the spring's pull at t = 0, over sigma L
}

# name: (k / k_c, run length s, dt s, changes to SLAB). The flexible slab's
# axial stiffness E' H / L (E' = E / (1 - nu^2)) is about k_c, so the pull
# concentrates at its pulled end; the stiff one (E 100 times larger) should
# slide as the rigid spring-slider.
CASES = {
    "slab_flexible_half": (0.5, 0.3, 1e-5, {}),
    "slab_flexible_twice": (2.0, 0.3, 1e-5, {}),
    "slab_stiff_half": (0.5, 0.15, 1e-5, {"E": 1.0e11}),
    "slab_stiff_twice": (2.0, 0.15, 1e-5, {"E": 1.0e11}),
}


def case_numbers(name):
    """SLAB with the case's changes."""
    s = dict(SLAB)
    s.update(CASES[name][3])
    return s


def critical_stiffness(s=SLAB):
    """k_c = sigma L (mu_s - mu_d) / Dc: the spring below which a rigid slab slips dynamically."""
    return s["sigma"] * s["L"] * (s["mu_s"] - s["mu_d"]) / s["dc"]


def geometry(s=SLAB):
    L, H, nb = s["L"], s["H"], s["NB"]
    lines = [
        # base [-0.5, L + 0.5] x [-0.2, 0], type 1: its top is the interface
        (1, -0.5, -0.2, L + 0.5, -0.2), (1, L + 0.5, -0.2, L + 0.5, 0), (1, L + 0.5, 0, -0.5, 0),
        (1, -0.5, 0, -0.5, -0.2),
        # slab outline (free faces), type 2
        (2, 0, 0, 0, H), (2, 0, H, L, H), (2, L, H, L, 0),
        # driver [L + 0.8, L + 0.9] x [0, 0.1], type 4
        (4, L + 0.8, 0, L + 0.9, 0), (4, L + 0.9, 0, L + 0.9, 0.1), (4, L + 0.9, 0.1, L + 0.8, 0.1),
        (4, L + 0.8, 0.1, L + 0.8, 0),
    ]
    # the cuts between the slab's blocks, type 3: bonded
    lines += [(3, L * i / nb, 0, L * i / nb, H) for i in range(1, nb)]
    body = "\n".join('      <Joint type="%d"> %.9g %.9g %.9g %.9g </Joint>' % line for line in lines)
    return ("<?xml version=\"1.0\" standalone=\"no\"?>\n"
            "<!-- The slab of examples/friction_instabilities (make_slab.py writes it). -->\n"
            "<!DOCTYPE DDA SYSTEM \"geometry.dtd\">\n"
            "<Berkeley:DDA xmlns:Berkeley=\"http://www.tsoft.com/~bdoolin/dda\">\n<Berkeley:Geometry>\n"
            "   <Jointlist>\n" + body + "\n   </Jointlist>\n</Berkeley:Geometry>\n</Berkeley:DDA>\n")


def scenario(name, k_over_kc, time, dt, s):
    L, H, nb = s["L"], s["H"], s["NB"]
    w = L / nb
    k = k_over_kc * critical_stiffness(s)
    pull = s["start_mu"] * s["sigma"] * L
    points = ["  - {name: base_w, kind: fixed, at: [-0.25, -0.1]}",
              "  - {name: base_m, kind: fixed, at: [%.9g, -0.1]}" % (L / 2),
              "  - {name: base_e, kind: fixed, at: [%.9g, -0.1]}" % (L + 0.25),
              "  - {name: driver, kind: fixed, at: [%.9g, 0.05]}" % (L + 0.85)]
    loads = []
    for i in range(nb):
        x0 = i * w
        points.append("  - {name: p%02d, kind: load, at: [%.9g, %.9g]}" % (i, x0 + w / 2, H / 2))
        loads.append("    - {point: p%02d, force: [0, %.9g]}" % (i, -s["sigma"] * w))
    return "\n".join([
        "# %s: a slab of %d bonded blocks pressed on a plane (sigma = %g Pa) and dragged through a spring"
        " of %g k_c at %g m/s; slip weakening on the interface" % (name, nb, s["sigma"], k_over_kc, s["vd"]),
        "name: %s" % name,
        "geometry: {file: slab.geo}",
        "points:", *points,
        "materials:",
        "  default: {density: %g, young: %g, poisson: %g, plane: strain}" % (s["rho"], s["E"], s["nu"]),
        "joints:",
        "  default: {friction_deg: 30}",
        "  type1: {friction_law: {name: slip_weakening, mu_s: %g, mu_d: %g, dc: %g}}" % (s["mu_s"], s["mu_d"], s["dc"]),
        # far above the stresses of the run: the slab stays one body
        "  type3: {friction_deg: 45, cohesion: 1.0e9, tensile_strength: 1.0e9}",
        "loading:",
        "  gravity: [0, -9.81]",
        "  point_loads:", *loads,
        "fixed:",
        "  points:",
        "    - {point: driver, displacement: [[0, 0, 0], [%g, %.9g, 0]]}" % (time + 1, s["vd"] * (time + 1)),
        "bolts:",
        "  - {name: spring, from: [%.9g, 0.05], to: [%.9g, %.9g], stiffness: %.9g, pretension: %.9g}"
        % (L + 0.85, L - w / 2, H / 5, k, pull),
        "control:",
        "  dt: %g" % dt,
        "  total_time: %g" % time,
        "  initial_equilibrium: true",
        # Every step a frame: analyse_slab.py follows the bottom corners
        # (block vertices) through the events. About 100 MB a run of 0.15 s.
        "  output_interval: %g" % dt,
        "output: {vtk: false, plots: false, report: false}",
        ""])


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "slab.geo"), "w") as f:
        f.write(geometry())
    for name, (k_over_kc, time, dt, _) in CASES.items():
        with open(os.path.join(out, name + ".yaml"), "w") as f:
            f.write(scenario(name, k_over_kc, time, dt, case_numbers(name)))


if __name__ == "__main__":
    main()
