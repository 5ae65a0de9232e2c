#!/usr/bin/env bash
# The probabilistic wedge example (see README.md). Writes out/. Exits
# non-zero if the study's mean FS or probability of failure is not that of
# an independent plain Monte Carlo within the sampling error (check_mc.py).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../find_dda.sh"
dda="$(find_dda)"
py=/usr/bin/python3
export MPLBACKEND=Agg
out="${OUT:-$here/out}"   # OUT=... writes elsewhere (the ctest run does)
rm -rf "$out"
mkdir -p "$out"

echo "== 1. the study: 10,000 wedges (Fisher planes, normal phi)"
"$dda" study "$here/study.yaml" -o "$out/study" | tee "$out/study.txt"

echo "== 2. check against an independent Monte Carlo"
"$py" "$here/check_mc.py" "$out/study" -o "$out/mc.json"
