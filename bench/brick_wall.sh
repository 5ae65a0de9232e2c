#!/usr/bin/env bash
# Solves per step on the running-bond brick wall of DDA-for-Windows files
# (not part of CI).
#
# bench/brick_wall.py writes each wall as a .geo/.ana pair (bricks 1 x 0.5 m
# on a base held by three fixed points, gravity with the old program's
# turn-on phase, fixed dt 1 ms, penalty 50 E, 100 open-close iterations
# allowed); `dda dl` and `dda dc` cut it, and bench_df times STEPS steps of
# the model `dda df` would run, from the start, on THREADS threads. Prints
# per size: blocks, contacts, global solves per step (the linear solves of
# the whole system: the count this benchmark is about), solves on contact
# clusters per step and their CG iterations (df/src/core/contact_clusters.hpp),
# PCG iterations per global solve, and ms per step (machine-dependent:
# compare runs of one session, interleaved).
#
#   bash bench/brick_wall.sh [STEPS]                 # default 200 steps; 101, 401, 1601 blocks
#   SIZES="101 401 1601 10001" bash bench/brick_wall.sh
#   THREADS=2 bash bench/brick_wall.sh               # default 1
#   CLUSTERS=0 bash bench/brick_wall.sh              # every iterate a global solve (control.contact_clusters: false; default 1, on)
#   BUILD=/path/to/build bash bench/brick_wall.sh
set -euo pipefail
cd "$(dirname "$0")/.."
steps="${1:-200}"
build="${BUILD:-build}"
[ -x "$build/bench/bench_df" ] && [ -x "$build/bin/dda" ] || bash scripts/build.sh
work="${TMPDIR:-/tmp}/dda_bench_brick_wall"
mkdir -p "$work"
printf '%7s %9s %14s %14s %9s %7s %12s\n' blocks contacts global_solves cluster_solves local_it pcg_it ms_per_step
for n in ${SIZES:-101 401 1601}; do
  stem=$(/usr/bin/python3 bench/brick_wall.py "$n" "$work" --steps "$steps")
  [ -f "$stem.blocks.h5" ] || {
    "$build/bin/dda" dl "$stem.geo" -o "$stem.lines.h5" -q
    "$build/bin/dda" dc "$stem.lines.h5" -o "$stem.blocks.h5" -q
  }
  OMP_NUM_THREADS="${THREADS:-1}" "$build/bench/bench_df" \
      --blocks "$stem.blocks.h5" --scenario "$stem.ana" --steps "$steps" --skip 0 --clusters "${CLUSTERS:-1}" \
      --benchmark_filter=BM_Model --benchmark_format=json > "$work/$n.json" 2> "$work/$n.log"
  /usr/bin/python3 - "$work/$n.json" <<'PY'
import json, sys
text = open(sys.argv[1]).read()
b = json.loads(text[text.index("{"):])["benchmarks"][0]
print("%7d %9d %14.2f %14.2f %9.1f %7.1f %12.2f" % (b["blocks"], b["contacts"], b["solves_per_step"],
      b["local_solves_per_step"], b["local_it"], b["pcg_it"], b["ms_per_step"]))
PY
done
