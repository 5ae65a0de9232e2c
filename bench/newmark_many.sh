#!/usr/bin/env bash
# dda newmark over many records (not part of CI): RECORDS synthetic records
# of SAMPLES samples at 0.01 s (default 1000 x 4000, 40 s each), both
# polarities, the rigid and the coupled analysis, k_y = 0.1, Ts = 0.2 s, in
# one call over the folder, timed from the start of the call (reading,
# intensity measures, analyses, table). Prints the machine-independent count
# (records x samples x polarities x analyses, the sliding-analysis samples)
# and the wall time (machine-dependent; docs/analytical.md records a run).
#
# Records: values only (read with --record-dt 0.01), in g: a sum of 20 sines
# of 0.3 to 12 Hz with random phases under a Saragoni-Hart-like envelope
# t^2 exp(-t / 4), scaled to a PGA drawn in 0.1 .. 0.6 g (seeded, so every
# run analyses the same records).
#
#   bash bench/newmark_many.sh                # 1000 records x 4000 samples
#   RECORDS=200 SAMPLES=8000 bash bench/newmark_many.sh
#   BUILD=/path/to/build bash bench/newmark_many.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build="${BUILD:-build}"
records="${RECORDS:-1000}"
samples="${SAMPLES:-4000}"
[ -x "$build/bin/dda" ] || { echo "no $build/bin/dda: build the dda target first" >&2; exit 1; }
work="${TMPDIR:-/tmp}/dda_bench_newmark_many"
rm -rf "$work"
mkdir -p "$work/records"
/usr/bin/python3 - "$work/records" "$records" "$samples" <<'PY'
import math, random, sys
folder, count, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
rng = random.Random(30)
dt = 0.01
for k in range(count):
    sines = [(rng.uniform(0.3, 12.0), rng.uniform(0, 2 * math.pi), rng.uniform(0.2, 1.0)) for _ in range(20)]
    env = [(i * dt) ** 2 * math.exp(-i * dt / 4.0) for i in range(n)]
    a = [env[i] * sum(w * math.sin(2 * math.pi * f * i * dt + p) for f, p, w in sines) for i in range(n)]
    peak = max(abs(x) for x in a) or 1.0
    scale = rng.uniform(0.1, 0.6) / peak
    with open("%s/rec%04d.txt" % (folder, k), "w") as out:
        out.write("\n".join("%.6g" % (x * scale) for x in a) + "\n")
PY
start=$(date +%s.%N)
"$build/bin/dda" newmark --ky 0.1 --records "$work/records" --units g --record-dt 0.01 --method rigid,coupled \
  --ts 0.2 --polarity both -o "$work/table.csv" -q
end=$(date +%s.%N)
rows=$(($(wc -l < "$work/table.csv") - 1))
echo "records $records, samples $samples, rows $rows (records x polarities)"
echo "sliding-analysis samples: $((records * samples * 2 * 2)) (records x samples x 2 polarities x 2 analyses)"
/usr/bin/python3 -c "import sys; print('wall time: %.2f s' % (float(sys.argv[2]) - float(sys.argv[1])))" "$start" "$end"
