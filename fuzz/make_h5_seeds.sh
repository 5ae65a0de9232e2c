#!/usr/bin/env bash
# Makes the seed files of the HDF5 fuzz targets (fuzz/corpus/h5_*/), small
# files of each kind written by `dda` itself: the 2D scenario of the bit-flip
# sweep (tests/tools/bitflip_sweep.py) and the 3D incline of the CLI tests
# (tests/data/df3_incline.yaml), each run stopped after two steps so that
# the results hold a checkpoint. Run again when the layout of a file changes.
# Usage: bash fuzz/make_h5_seeds.sh DDA_BINARY
set -euo pipefail
dda=$(realpath "$1")
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
/usr/bin/python3 - "$src" <<'PY'
import sys
sys.path.insert(0, sys.argv[1] + "/tests/tools")
import bitflip_sweep
open("s2.yaml", "w").write(bitflip_sweep.SCENARIO_2D)
s3 = open(sys.argv[1] + "/tests/data/df3_incline.yaml").read()
s3 = s3.replace("total_time: 1, output_interval: 0.25", "total_time: 0.004, output_interval: 0.002")
open("s3.yaml", "w").write(s3.replace("vtk: true", "vtk: false"))
PY
"$dda" dl s2.yaml -o lines.h5 -q
"$dda" dc lines.h5 -o blocks.h5 -q
"$dda" df s2.yaml --blocks blocks.h5 -o results.h5 --stop-at-step 2 -q
"$dda" dl s3.yaml -o fractures.h5 -q
"$dda" dc fractures.h5 -o blocks3d.h5 -q
"$dda" df s3.yaml --blocks blocks3d.h5 -o results3d.h5 --stop-at-step 2 -q
for kind in lines blocks results fractures blocks3d results3d; do
  mkdir -p "$src/fuzz/corpus/h5_$kind"
  cp "$kind.h5" "$src/fuzz/corpus/h5_$kind/seed.h5"
done
