#!/usr/bin/env python3
"""A running-bond brick wall as a DDA-for-Windows model pair (.geo, .ana).

    python3 bench/brick_wall.py BLOCKS OUTDIR [--steps N]

BLOCKS is the block count including the base: 101, 401, 1601, 10001 give
walls of 10 x 10, 20 x 20, 40 x 40 and 100 x 100 bricks (1 m x 0.5 m,
every other row shifted by half a brick) standing on a base block held by
three fixed points. The analysis: gravity, fixed dt 1 ms (the minimum step
is the maximum, so the step is never cut), penalty 50 E, 100 open-close
iterations allowed, friction 35 degrees on every joint. The bricks start
exactly touching, so the first steps are the wall settling into its
contact springs; after that it stands at rest.

Writes OUTDIR/wall_BLOCKS.geo and OUTDIR/wall_BLOCKS.ana.
"""
import argparse
import math
import os


def geometry(n):
    lines = []
    width = n * 1.0
    # Base: 1 m deep, one brick wider than the wall on either side.
    x0, x1 = -1.5, width + 1.5
    for a, b in [((x0, -1), (x1, -1)), ((x1, -1), (x1, 0)), ((x1, 0), (x0, 0)), ((x0, 0), (x0, -1))]:
        lines.append((1, a, b))
    for r in range(n):
        y0, y1 = 0.5 * r, 0.5 * (r + 1)
        shift = 0.5 * (r % 2)
        for c in range(n):
            a, b = c + shift, c + 1 + shift
            lines += [(2, (a, y0), (b, y0)), (2, (b, y0), (b, y1)), (2, (b, y1), (a, y1)), (2, (a, y1), (a, y0))]
    fixed = [(x0 + 0.5, -0.5), (0.5 * width, -0.5), (x1 - 0.5, -0.5)]
    top = (0.5 * n + 0.25 * ((n - 1) % 2), 0.5 * n - 0.25)
    return lines, fixed, top


def write_geo(path, n):
    lines, fixed, top = geometry(n)
    with open(path, "w") as f:
        f.write('<?xml version="1.0" standalone="no"?>\n<!DOCTYPE DDA SYSTEM "geometry.dtd">\n')
        f.write('<Berkeley:DDA xmlns:Berkeley="http://www.tsoft.com/~bdoolin/dda">\n<Berkeley:Geometry>\n')
        f.write('   <Berkeley:Edgenodedist distance="0.001"/>\n   <Jointlist>\n')
        for t, a, b in lines:
            f.write(f'      <Joint type="{t}"> {a[0]:g} {a[1]:g} {b[0]:g} {b[1]:g} </Joint>\n')
        f.write('   </Jointlist>\n   <Fixedpointlist>\n')
        for p in fixed:
            f.write(f'      <Point> {p[0]:g} {p[1]:g} </Point>\n')
        f.write('   </Fixedpointlist>\n   <Measuredpointlist>\n')
        f.write(f'      <Point> {top[0]:g} {top[1]:g} </Point>\n')
        f.write('   </Measuredpointlist>\n</Berkeley:Geometry>\n</Berkeley:DDA>\n')


def write_ana(path, steps):
    with open(path, "w") as f:
        f.write(f"""<?xml version="1.0" standalone="no"?>
<!DOCTYPE DDA SYSTEM "analysis.dtd">
<Berkeley:DDA xmlns:Berkeley="http://www.tsoft.com/~bdoolin/dda">
<Analysis type="dynamic">
  <Analysistype type="dynamic"/>
  <Rotation type="exact"/>
  <Gravity flag="yes"/>
  <Autotimestep flag="no"/>
  <Autopenalty flag="no" pfactor="50.0"/>
  <Planestrain flag="no"/>
  <Numtimesteps timesteps="{steps}"/>
  <Maxtimestep maxtimestep="0.001"/>
  <Mintimestep mintimestep="0.001"/>
  <OCLimit maxopenclose="100"/>
  <Maxdisplacement maxdisplacement="0.01"/>
  <Saveinterval step="10"/>
  <Blockmaterial type="1">
    <Unitmass> 2600 </Unitmass>
    <Unitweight> 25506 </Unitweight>
    <Youngsmod> 5.0e9 </Youngsmod>
    <Poissonratio> 0.25 </Poissonratio>
    <Damping> 0.0 </Damping>
    <Istress> 0 0 0 </Istress>
    <Ivelocity> 0 0 0 </Ivelocity>
    <Istrain> 0 0 0 </Istrain>
  </Blockmaterial>
  <Jointproperties type="1">
    <Friction> 35.0 </Friction>
    <Cohesion> 0.0 </Cohesion>
    <Tensile> 0.0 </Tensile>
  </Jointproperties>
  <Jointproperties type="2">
    <Friction> 35.0 </Friction>
    <Cohesion> 0.0 </Cohesion>
    <Tensile> 0.0 </Tensile>
  </Jointproperties>
</Analysis>
</Berkeley:DDA>
""")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("blocks", type=int)
    p.add_argument("outdir")
    p.add_argument("--steps", type=int, default=200)
    a = p.parse_args()
    n = math.isqrt(a.blocks - 1)
    if n < 1 or n * n + 1 != a.blocks:
        p.error(f"BLOCKS must be a square plus one (101, 401, 1601, 10001), not {a.blocks}")
    os.makedirs(a.outdir, exist_ok=True)
    stem = os.path.join(a.outdir, f"wall_{a.blocks}")
    write_geo(stem + ".geo", n)
    write_ana(stem + ".ana", a.steps)
    print(stem)


if __name__ == "__main__":
    main()
