#!/usr/bin/python3
"""Writes the scenarios of examples/friction_instabilities: one spring-slider
(spring_slider.geo) per case, with its own friction law, spring stiffness
and load-point speed.

Usage: make_cases.py OUT_DIR CASE [CASE ...]
  CASE: name:law:k:vd:time:dt:start
  law:   rate_state, stribeck or slip_weakening (parameters in LAWS)
  k:     spring stiffness, N/m;  vd: load-point speed, m/s
  time:  run length, s;          dt: time step, s
  start: rest   - the slider at rest, the spring at START_MU W (below the
                  law's strength at rest), contacts settled first;
         steady - the slider sliding at vd, the spring at 1.001 times the
                  law's steady friction (a 0.1 % kick), the rate-and-state
                  contacts at their steady state (v_init = vd).
The slider is 1 m x 0.5 m of density 2000: m = 1000 kg and N = W = 9810 N
per metre of thickness. The spring is a bolt from the driver block to the
slider whose force at t = 0 is its pretension; a moving fixed point carries
the driver at vd from t = 0.
"""
import math
import os
import sys

GEO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "spring_slider.geo")
WEIGHT = 2000 * 0.5 * 9.81  # N per metre of thickness

LAWS = {
    # Dieterich-Ruina, aging law: k_c = W (b - a) / dc = 4.905e5 N/m.
    "rate_state": "{{name: rate_state, mu0: 0.6, a: 0.01, b: 0.015, dc: 1.0e-4, v0: 1.0e-6, v_init: {v_init:g}}}",
    # Stribeck with a viscous branch: unstable below V_cr = 0.01 ln 10 m/s.
    "stribeck": "{{name: stribeck, mu_s: 0.6, mu_k: 0.5, v_s: 0.01, mu_v: 1.0}}",
    # Linear slip weakening: k_c = W (mu_s - mu_d) / dc = 98 100 N/m.
    "slip_weakening": "{{name: slip_weakening, mu_s: 0.6, mu_d: 0.5, dc: 0.01}}",
}
START_MU = {"rate_state": 0.55, "stribeck": 0.59, "slip_weakening": 0.59}
V_INIT_AT_REST = 1.0e-4  # m/s: a contact healed for Dc / 1e-4 = 1 s


def steady_mu(law, vd):
    """The friction coefficient of steady sliding at vd (the laws above)."""
    if law == "rate_state":
        return 0.6 + (0.01 - 0.015) * math.log(vd / 1.0e-6)
    if law == "stribeck":
        return 0.5 + 0.1 * math.exp(-vd / 0.01) + 1.0 * vd
    raise ValueError("no steady sliding to start from for " + law)


TEMPLATE = """# {name}: spring-slider, {law} friction, k = {k:g} N/m, load point at {vd:g} m/s, from {start}
name: {name}
geometry: {{file: {geo}}}
points:
  - {{name: base_w, kind: fixed, at: [-1.0, -0.25]}}
  - {{name: base_m, kind: fixed, at: [0.5, -0.25]}}
  - {{name: base_e, kind: fixed, at: [2.0, -0.25]}}
  - {{name: driver, kind: fixed, at: [3.1, 0.1]}}
  - {{name: slider, kind: measurement, at: [0.5, 0.25]}}
materials:
  default: {{density: 2000, young: 1.0e10, poisson: 0.25, plane: stress}}
  zones:
    - {{polygon: [[0, 0], [1, 0], [1, 0.5], [0, 0.5]], initial_velocity: [{v_start:g}, 0, 0]}}
joints:
  default: {{friction_law: {friction}}}
loading:
  gravity: [0, -9.81]
fixed:
  points:
    - {{point: driver, displacement: [[0, 0, 0], [{t_end:g}, {u_end:.9g}, 0]]}}
bolts:
  - {{name: spring, from: [3.1, 0.1], to: [0.9, 0.1], stiffness: {k:.9g}, pretension: {pretension:.9g}}}
control:
  dt: {dt:g}
  total_time: {time:g}
  initial_equilibrium: {settle}
  output_interval: {out:g}
output: {{vtk: false, plots: false, report: false}}
"""


def scenario(name, law, k, vd, time, dt, start):
    steady = start == "steady"
    friction = LAWS[law].format(v_init=vd if steady else V_INIT_AT_REST)
    pretension = (1.001 * steady_mu(law, vd) if steady else START_MU[law]) * WEIGHT
    return TEMPLATE.format(name=name, law=law, k=k, vd=vd, start="steady sliding" if steady else "rest", geo=GEO,
                           friction=friction, t_end=time + 1, u_end=vd * (time + 1), pretension=pretension,
                           v_start=vd if steady else 0, settle="false" if steady else "true", dt=dt, time=time,
                           out=time / 100)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for case in sys.argv[2:]:
        name, law, k, vd, time, dt, start = case.split(":")
        if start not in ("rest", "steady"):
            sys.exit("make_cases.py: " + case + ": start must be rest or steady")
        with open(os.path.join(out, name + ".yaml"), "w") as f:
            f.write(scenario(name, law, float(k), float(vd), float(time), float(dt), start))


if __name__ == "__main__":
    main()
