"""The shaking-table input of the seed report's Figure 18: a 2 Hz sinusoid
along y (north), the table's own acceleration, in g, sampled at 1 kHz.

    python3 make_record.py AMPLITUDE_G DURATION_S OUT.csv

The ramp-up (5 s) and the 2.5 Hz low-pass are applied by the scenario and
by `dda sliding3d` alike, so both solve the same input.
"""
import math
import sys

amplitude, duration, out = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
n = int(round(duration * 1000))
with open(out + ".tmp", "w") as f:
    f.write("t,ax,ay,az\n")
    for k in range(n + 1):
        t = k / 1000
        f.write(f"{t:.3f},0,{amplitude * math.sin(2 * math.pi * 2 * t):.9f},0\n")
import os
os.replace(out + ".tmp", out)
