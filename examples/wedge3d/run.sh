#!/usr/bin/env bash
# The V4 wedge in a jointed slope: DL and DC in 3D, block theory, the 2D
# section along the wedge's axis, figures, and the check of the wedge's
# volume and sliding direction (check.py; exits non-zero if they are off).
# What the run prints that README.md quotes is also saved (wedge.txt,
# check.txt) for scripts/check_readme_numbers.py.
# Environment: DDA (the program; default dda on PATH, else build/bin/dda), OUT (output folder;
# default examples/wedge3d/out).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../find_dda.sh"
DDA="$(find_dda)"
OUT="${OUT:-$here/out}"
"$DDA" run "$here/wedge3d.yaml" -o "$OUT"
"$DDA" wedge --plane 51.4/65.8 --plane 51.4/295.2 --phi 30 --azimuth 0 | tee "$OUT/wedge.txt"
"$DDA" plot "$OUT/blocks3d.h5" -o "$OUT/figures/wedge_view.png" --view 25 70 --explode 0.3 --title "V4 wedge: block theory"
# The section's own axes (docs/scenario.md, trace_planes): u along the strike
# (north here), v up the dip from the plane's point (z - 5 m).
"$DDA" plot "$OUT/sections/axis.blocks.h5" -o "$OUT/figures/axis_section.png" \
  --title "Blocks of the vertical section x = 0 along the wedge axis" --axes "u = y, north (m)" "v = z - 5 m, up (m)"
/usr/bin/python3 "$here/check.py" "$OUT" | tee "$OUT/check.txt"
