#!/usr/bin/env bash
# Sets everything up and runs the main example end to end: the layered rock
# mass over a tunnel, DL -> DC -> statistics -> figures, into
# examples/layered_tunnel/out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh dda   # the command alone; scripts/test.sh builds the rest
bash examples/layered_tunnel/run.sh
