"""The 2-block incline of the command-line tests, as a scenario on stdout.

A slab on a plane dipping 30 deg, with a 1 m x 1 m slider on a short joint
of its own (the set "interface", friction 20 deg): the slider slides with
s = g (sin 30 - cos 30 tan 20) t^2 / 2. Used by tests/tools/cli_cases.sh
(write_incline) and bench/study_overhead.sh.

    incline_scenario.py [TOTAL_TIME]     # model time of the forward run, s (default 1.0)
"""
import math
import sys

total_time = sys.argv[1] if len(sys.argv) > 1 else "1.0"
a = math.radians(30)


def r(x, y):
    return [round(math.cos(a) * x - math.sin(a) * y, 12), round(math.sin(a) * x + math.cos(a) * y, 12)]


poly = [r(*p) for p in [(0, -1), (8, -1), (8, 0), (7, 0), (7, 1), (6, 1), (6, 0), (0, 0)]]
print("name: incline\nseed: 3")
print("domain: {polygon: %s}" % poly)
print("lines:\n  - {set: interface, from: %s, to: %s}" % (r(6, 0), r(7, 0)))
print("points:")
for i, x in enumerate([0.5, 4.0, 7.5]):
    print("  - {name: base%d, kind: fixed, at: %s}" % (i + 1, r(x, -0.5)))
print("  - {name: slider, kind: measurement, at: %s}" % r(6.5, 0.5))
print("  - {name: slab, kind: measurement, at: %s}" % r(2.0, -0.5))
print("""materials:
  default: {density: 2000, young: 5.0e10, poisson: 0.25, plane: stress}
joints:
  default: {friction_deg: 45}
  interface: {friction_deg: 20}
control: {dt: 0.001, total_time: %s, output_interval: 0.25}
output: {vtk: true, plots: false}""" % total_time)
