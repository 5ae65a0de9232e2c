#!/usr/bin/env bash
# Runs the benchmarks (not part of CI): block cutting of 1k, 10k and 100k
# random lines, and 3D cutting (three sets, 1k and 10k blocks; 1k discs).
# Prints lines/blocks and seconds per cut.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
build/bench/bench_cut --benchmark_counters_tabular=true "$@"
build/bench/bench_cut3d --benchmark_counters_tabular=true "$@"
