#!/usr/bin/env bash
# Configures and builds the project in ./build (Release): everything, or
# only the targets named (scripts/example.sh builds `dda` alone, so that a
# first run does not wait for the tests and benchmarks).
#
#   bash scripts/build.sh          # all targets
#   bash scripts/build.sh dda      # the command only
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
if [ "$#" -gt 0 ]; then
  cmake --build build -j"$(nproc)" --target "$@"
else
  cmake --build build -j"$(nproc)"
fi
