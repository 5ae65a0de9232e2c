#!/usr/bin/env bash
# What `dda study` adds to the cases it runs (docs/studies.md, "Overheads";
# not part of CI). Three measurements, each back to back in one session:
#
# 1. Pool overhead per case: N cases of a small scenario (the 2-block
#    incline of the CLI tests, tests/tools/incline_scenario.py, run for T s of
#    model time), run as N plain `dda run` one after another (printing to
#    a log, as a study's case does), and as `dda study -j 1` of the same N
#    cases (N seeds), three times each, interleaved. The overhead per case
#    is (study - plain) / N, and its share of a case.
# 2. MPI overhead: the same study under `mpirun -n 2` (rank 0 hands out,
#    rank 1 runs), against the plain runs; mpirun's own start-up included.
# 3. 10,000 analytical wedge cases: examples/probabilistic_wedge/study.yaml.
#
#   bash bench/study_overhead.sh [N] [T]     # default 20 cases of 20 s model time (about 1 s a case)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
dda="${DDA:-$root/build/bin/dda}"
n="${1:-20}"
total_time="${2:-20}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"

/usr/bin/python3 "$root/tests/tools/incline_scenario.py" "$total_time" > incline.yaml
cat > study.yaml <<YAML
scenario: incline.yaml
seeds: $n
measure:
  - {kind: point_displacement, point: slider, name: slide}
YAML

# Runs a shell command; prints its wall time and the CPU time (user +
# system) of everything it ran, in seconds. The CPU time is what the study
# adds in work; the wall time also holds the waits of a machine that other
# programs keep busy.
measure() {
  /usr/bin/python3 - "$1" <<'PY'
import resource, subprocess, sys, time
t = time.perf_counter()
subprocess.run(["bash", "-c", sys.argv[1]], check=True)
wall = time.perf_counter() - t
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{wall:.3f} {r.ru_utime + r.ru_stime:.3f}")
PY
}
for s in $(seq 1 "$n"); do sed "s/^seed: 3$/seed: $s/" incline.yaml > "case$s.yaml"; done
plain_cmd="for s in \$(seq 1 $n); do '$dda' run case\$s.yaml -o plain\$s --no-plots --no-vtk --no-report > plain\$s.log 2>&1; done"
study_cmd="rm -rf study_out; '$dda' study study.yaml -o study_out -j 1 --no-plots -q"
as_root=""
[ "$(id -u)" -eq 0 ] && as_root="--allow-run-as-root"
mpi_cmd="rm -rf mpi_out; mpirun -n 2 --oversubscribe $as_root '$dda' study study.yaml -o mpi_out --no-plots -q"

echo "== $n cases of the 2-block incline, $total_time s of model time each"
# Three passes of each, interleaved, so that a change in the machine's load
# falls on all alike; the means are compared.
runs=()
for pass in 1 2 3; do
  runs+=("plain $(measure "$plain_cmd")" "study $(measure "$study_cmd")")
  command -v mpirun > /dev/null && runs+=("mpi $(measure "$mpi_cmd")")
done
printf '%s\n' "${runs[@]}" | /usr/bin/python3 -c "
import sys
n = $n
runs = {}
for line in sys.stdin:
    kind, wall, cpu = line.split()
    runs.setdefault(kind, []).append((float(wall), float(cpu)))
mean = lambda xs: sum(xs) / len(xs)
pw, pc = mean([w for w, c in runs['plain']]), mean([c for w, c in runs['plain']])
print(f'plain dda run: {1000 * pw / n:.0f} ms wall, {1000 * pc / n:.0f} ms CPU a case')
for kind, what in (('study', 'dda study -j 1'), ('mpi', 'mpirun -n 2 dda study (start-up included)')):
    if kind not in runs:
        continue
    w, c = mean([w for w, c in runs[kind]]), mean([c for w, c in runs[kind]])
    print(f'{what}: {1000 * w / n:.0f} ms wall, {1000 * c / n:.0f} ms CPU a case; overhead '
          f'{1000 * (w - pw) / n:.1f} ms wall ({100 * (w - pw) / pw:.1f} %), '
          f'{1000 * (c - pc) / n:.1f} ms CPU ({100 * (c - pc) / pc:.1f} %) a case')
print('passes (wall, CPU s):', '; '.join(f'{k} ' + ' '.join(f'{w:.2f}/{c:.2f}' for w, c in v) for k, v in runs.items()))
"

echo "== 10,000 analytical wedge cases (examples/probabilistic_wedge)"
read -r wall cpu < <(measure "'$dda' study '$root/examples/probabilistic_wedge/study.yaml' -o wedge_out --no-plots -q")
echo "10,000 wedge cases: ${wall} s wall, ${cpu} s CPU (cores: $(nproc))"
