#!/usr/bin/env bash
# The full bit-flip sweep (docs/reliability.md, "Damaged files"): 2,000
# random one-bit flips (fixed seed) in a small file of each kind, each read
# by `dda info` (results also by `dda history` and `dda df --resume`); fails
# on any crash, hang, internal error or second line of stderr. About 8
# minutes; ctest runs 300 flips a kind (cli.bitflip_sweep, about 2 minutes).
# Builds `dda` first if needed.
# Usage: bash scripts/bitflip_sweep.sh [FLIPS] [SEED]
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/bin/dda ] || { cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j1 --target dda; }
exec /usr/bin/python3 tests/tools/bitflip_sweep.py build/bin/dda . build/bitflip_sweep \
  --flips "${1:-2000}" --seed "${2:-27}"
