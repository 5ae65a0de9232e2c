#!/usr/bin/env bash
# 3D forward-solver speed on a jointed cube (not part of CI): about 100,
# 1k and 10k blocks cut by three persistent sets (bench/bench_df3d.cpp has
# the model), STEPS steps from rest each (default 4; the first includes
# CHOLMOD's analysis). Prints blocks, contacts, the start-up relaxation's
# global solves and time, solves and cluster solves per step, ms per step
# (first step and the later ones), PCG iterations per solve, the shares of contact detection,
# assembly and linear solve, and the growth exponent of the cost per step
# between sizes.
#
#   bash bench/df3d.sh [STEPS] [DT] [BENCHMARK FLAGS]   # defaults 4 and 0.002 s
#   bash bench/df3d.sh 4 0.002 --benchmark_filter='/(37|90)/'   # 100 and 1k only
#   BUILD=/path/to/build bash bench/df3d.sh   # default: build (made by scripts/build.sh)
#
# PCG (control.solver auto, from 80 free blocks) solves the 1k and 10k
# cubes; --solver cholmod times the direct solver instead (hours at 10k).
set -euo pipefail
cd "$(dirname "$0")/.."
steps="${1:-4}"
dt="${2:-0.002}"
build="${BUILD:-build}"
[ -x "$build/bench/bench_df3d" ] || bash scripts/build.sh
json="${TMPDIR:-/tmp}/dda_bench_df3d.json"
"$build/bench/bench_df3d" --steps "$steps" --dt "$dt" --benchmark_format=json "${@:3}" > "$json"
/usr/bin/python3 - "$json" "$steps" "$dt" <<'PY'
import json, math, sys
runs = [b for b in json.load(open(sys.argv[1]))["benchmarks"] if "error_occurred" not in b]
print(f"jointed cube, {sys.argv[2]} steps of dt = {sys.argv[3]} s from rest, {int(runs[0]['threads']) if runs else 0} threads")
head = ("blocks", "contacts", "closed", "start_solves", "ms_start", "solves/step", "cluster/step", "pcg_it", "ms_first", "ms_later", "ms/step", "detect%", "assembly%",
        "solve%")
print(" ".join(f"{h:>11}" for h in head))
prev = None
for b in runs:
    n, ms = b["blocks"], b["real_time"]  # real_time: ms per benchmark iteration = per step
    row = (int(n), int(b["contacts"]), int(b["closed"]), int(b.get("start_solves", 0)), round(b.get("ms_start", 0), 1), round(b["solves_per_step"], 1),
           round(b.get("cluster_solves_per_step", 0), 1),
           round(b.get("pcg_iterations", 0), 1), round(b["ms_first"], 1),
           round(b["ms_later"], 1), round(ms, 1), round(b["detect_pct"], 1), round(b["assembly_pct"], 1),
           round(b["solve_pct"], 1))
    print(" ".join(f"{v:>11}" for v in row))
    if prev:
        print(f"{'':>11} cost per step grows as N^{math.log(ms / prev[1]) / math.log(n / prev[0]):.2f} "
              f"from {int(prev[0])} to {int(n)} blocks")
    prev = (n, ms)
PY
