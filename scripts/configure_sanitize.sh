#!/usr/bin/env bash
# Configures build-sanitize once: clang with AddressSanitizer and
# UndefinedBehaviorSanitizer in every library and test, and the libFuzzer
# targets (cmake/DdaSanitizers.cmake). Shared by scripts/sanitize.sh and
# scripts/fuzz.sh, so the libraries are compiled once for both.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build-sanitize/CMakeCache.txt ] && exit 0
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DDDA_FUZZ=ON -DDDA_BUILD_BENCHMARKS=OFF >/dev/null
