#!/usr/bin/env bash
# Forward-solver speed on mechanically layered rock (not part of CI).
#
# Makes the tunnel_roof model (examples/tunnel_roof: log-normal beds of mean
# 1 m, cross joints with FSI 1.3, a 10 x 6 m opening, the report's Table 2
# rock, the same control settings) at three sizes, about 1k, 10k and 50k
# blocks, by widening and heightening the section, cuts it with `dda dl` and
# `dda dc`, and times STEPS steps of each from rest with bench_df (the
# gravity transient, the hardest part of the run: 10-15 solves a step).
# Prints blocks, contacts, solves per step (of the whole system + on contact
# clusters, docs/solver2d.md) and ms per step, the shares of contact
# search, contact geometry, assembly, solve, the contacts' state updates
# after each solve and the end of the accepted step, the mean step (dt_us,
# microseconds of model time: the step control sets it, and a shorter step
# costs less), the share of the contacts updated after a solve (updated_pct:
# after a trial solve only those of blocks that moved, see
# df/include/dda/df/2d/moved_blocks.hpp), the share of the block rows whose
# residual a trial solve formed afresh (refreshed_pct: the others it took
# over from the last solve, df/src/core/block_pcg.hpp), and the growth exponent
# of the cost between sizes, per step and per second of model time (the
# larger models take longer steps, and a longer step costs more).
#
#   bash bench/df_layered.sh [STEPS]          # default 30
#   bash bench/df_layered.sh STEPS REST       # also STEPS steps after REST s of model time
#
# With REST (model seconds, e.g. 1), each model is also run with `dda df`
# from rest to t = REST, printing the wall time that took (seconds per
# model second: what a user waits for), and then STEPS steps are timed
# from there (bench_df --resume): by then the transient has died out and
# the model rests on its contacts, which is most of a long run's steps.
# Running to 1 s takes about 20 s, 2.5 min and 30 min at the three sizes;
# REST_SIZES="41x27 130x85" leaves the largest out.
#   BUILD=/path/to/build bash bench/df_layered.sh   # another build directory (default build)
#   CLUSTERS=1 bash bench/df_layered.sh             # the timed steps with contact clusters
#                                                   # (control.contact_clusters, docs/solver2d.md; 0: without)
#
# How the cost grows. The step control picks a different dt for each size
# (the larger models take longer steps in the transient, and a longer step
# needs more iterates), so the per-step growth of the adaptive runs mixes
# size with step length. DT (seconds) holds every model's step at that
# value (its `dt`, which the control then does not exceed; the mean dt_us
# shows any cut), for the growth at equal steps; SIZES (width x height in
# m, 0.93 blocks per square metre) takes more sizes, e.g. up to 400k blocks
# (3.6 GB of memory and a minute and a half in all):
#   DT=0.0001 SIZES="41x27 130x85 290x190 410x270 580x380 820x540" bash bench/df_layered.sh 20
# After the table, the growth exponent fitted over all sizes (least squares
# of log cost against log blocks) and over those of 10k blocks and more.
#
# The same bench_df times any model `dda df` runs, e.g. a DDA-for-Windows
# pair: dda dl model.geo -o l.h5 && dda dc l.h5 -o b.h5 &&
#   build/bench/bench_df --blocks b.h5 --scenario model.ana --steps 100 --benchmark_filter=BM_Model
set -euo pipefail
cd "$(dirname "$0")/.."
steps="${1:-30}"
rest="${2:-}"
build="${BUILD:-build}"
[ -x "$build/bench/bench_df" ] && [ -x "$build/bin/dda" ] || bash scripts/build.sh
work="${TMPDIR:-/tmp}/dda_bench_layered"
rm -rf "$work" && mkdir -p "$work"
printf '%-7s %8s %9s %7s %12s %11s %13s %13s %10s %11s %11s %7s %12s %14s\n' size blocks contacts solves ms_per_step search_pct geometry_pct assembly_pct solve_pct update_pct accept_pct dt_us updated_pct refreshed_pct
prev_n="" prev_ms="" prev_dt=""
: > "$work/growth.txt"
# width x height (m) of the section: by default about 1k, 10k and 50k
# blocks (the 60 x 40 m example has 2221 blocks: 0.93 per square metre).
dt_line='s/^  dt: .*/&/'
[ -z "${DT:-}" ] || dt_line="s/^  dt: .*/  dt: $DT/"
for name in ${SIZES:-41x27 130x85 290x190}; do
  w=${name%x*} h=${name#*x}
  sed -e "s/box: \[0, 0, 60, 40\]/box: [0, 0, $w, $h]/" \
      -e "$dt_line" \
      -e "s/center: \[30, 13\]/center: [$((w / 2)), $((h / 3))]/" \
      -e "/^points:/,/^materials:/{/^  - /d}" \
      -e "s/^points:/points:\n  - {name: crown, kind: measurement, at: [$((w / 2)).1, $((h / 3 + 3)).6]}/" \
      -e "s/^  max_displacement_ratio: .*/  max_displacement_ratio: 0.0005\n  w0: 20/" \
      examples/tunnel_roof/tunnel_roof.yaml > "$work/$name.yaml"
  "$build/bin/dda" dl "$work/$name.yaml" -o "$work/$name.lines.h5" -q
  "$build/bin/dda" dc "$work/$name.lines.h5" -o "$work/$name.blocks.h5" -q
  "$build/bench/bench_df" --blocks "$work/$name.blocks.h5" --scenario "$work/$name.yaml" --steps "$steps" ${CLUSTERS:+--clusters "$CLUSTERS"} \
      --benchmark_filter=BM_Model --benchmark_format=json > "$work/$name.json" 2> "$work/$name.log"
  line=$(/usr/bin/python3 - "$work/$name.json" <<'PY'
import json, sys
text = open(sys.argv[1]).read()
b = json.loads(text[text.index("{"):])["benchmarks"][0]
print(int(b["blocks"]), int(b["contacts"]), "%.1f+%.1f" % (b["solves_per_step"], b["local_solves_per_step"]),
      round(b["ms_per_step"], 1),
      round(b["search_pct"], 1), round(b["geometry_pct"], 1), round(b["assembly_pct"], 1), round(b["solve_pct"], 1),
      round(b["update_pct"], 1), round(b["accept_pct"], 1), round(b["dt_us"], 1), round(b["updated_pct"], 1),
      round(b["refreshed_pct"], 1))
PY
)
  read -r n c s ms sp gp as so up ap dtu upd rf <<<"$line"
  printf '%-7s %8s %9s %7s %12s %11s %13s %13s %10s %11s %11s %7s %12s %14s\n' "$name" "$n" "$c" "$s" "$ms" "$sp" "$gp" "$as" "$so" "$up" "$ap" "$dtu" "$upd" "$rf"
  echo "$n $ms $dtu" >> "$work/growth.txt"
  if [ -n "$prev_n" ]; then
    /usr/bin/python3 -c "import math; g = math.log($n / $prev_n); print('        from %s to %s blocks the cost grows as N^%.2f per step, N^%.2f per model second' % ($prev_n, $n, math.log($ms / $prev_ms) / g, math.log(($ms / $dtu) / ($prev_ms / $prev_dt)) / g))"
  fi
  prev_n=$n prev_ms=$ms prev_dt=$dtu
done
/usr/bin/python3 - "$work/growth.txt" <<'PY'
import math, sys
rows = [tuple(map(float, line.split())) for line in open(sys.argv[1]) if line.strip()]
def slope(points):  # least squares of log y against log N
    xs = [math.log(n) for n, _ in points]; ys = [math.log(y) for _, y in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
for label, part in (("all sizes", rows), ("10k blocks and more", [r for r in rows if r[0] >= 9000])):
    if len(part) >= 3:
        print("fitted over %s (%d): N^%.2f per step, N^%.2f per model second" % (
            label, len(part), slope([(n, ms) for n, ms, _ in part]), slope([(n, ms / dt) for n, ms, dt in part])))
PY

[ -n "$rest" ] || exit 0
echo
echo "after ${rest} s of model time (the transient over):"
printf '%-7s %8s %12s %7s %12s %11s %13s %13s %10s %11s %11s %7s\n' size blocks wall_s_to_rest solves ms_per_step search_pct geometry_pct assembly_pct solve_pct update_pct accept_pct dt_us
for name in ${REST_SIZES:-41x27 130x85 290x190}; do
  sed -e "s/^  total_time: .*/  total_time: $rest/" "$work/$name.yaml" > "$work/$name.rest.yaml"
  start=$(date +%s.%N)
  "$build/bin/dda" df "$work/$name.rest.yaml" --blocks "$work/$name.blocks.h5" -o "$work/$name.rest.h5" \
      > "$work/$name.rest.log" 2>&1
  wall=$(/usr/bin/python3 -c "import time; print(round(time.time() - $start, 1))")
  "$build/bench/bench_df" --blocks "$work/$name.blocks.h5" --scenario "$work/$name.yaml" --resume "$work/$name.rest.h5" \
      --skip 0 --steps "$steps" --benchmark_filter=BM_Model --benchmark_format=json > "$work/$name.rest.json" 2>> "$work/$name.rest.log"
  line=$(/usr/bin/python3 - "$work/$name.rest.json" <<'PY'
import json, sys
text = open(sys.argv[1]).read()
b = json.loads(text[text.index("{"):])["benchmarks"][0]
print(int(b["blocks"]), round(b["solves_per_step"], 1), round(b["ms_per_step"], 1),
      round(b["search_pct"], 1), round(b["geometry_pct"], 1), round(b["assembly_pct"], 1), round(b["solve_pct"], 1),
      round(b["update_pct"], 1), round(b["accept_pct"], 1), round(b["dt_us"], 1))
PY
)
  read -r n s ms sp gp as so up ap dtu <<<"$line"
  printf '%-7s %8s %12s %7s %12s %11s %13s %13s %10s %11s %11s %7s\n' "$name" "$n" "$wall" "$s" "$ms" "$sp" "$gp" "$as" "$so" "$up" "$ap" "$dtu"
done
