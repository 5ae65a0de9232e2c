#!/usr/bin/env bash
# Runs the benchmarks (not part of CI): block cutting of 1k, 10k and 100k
# random lines. Prints lines, blocks and seconds per cut.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
build/bench/bench_cut --benchmark_counters_tabular=true "$@"
