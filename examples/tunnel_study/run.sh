#!/usr/bin/env bash
# The tunnel study example (see README.md): the seed report's Table 1
# matrix of joint trace length and bridge, 15 models x 5 seeds of a scaled
# tunnel, each DL -> DC -> DF. Writes out/. About 5 minutes on 2 cores.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../find_dda.sh"
dda="$(find_dda)"
export MPLBACKEND=Agg
out="${OUT:-$here/out}"   # OUT=... writes elsewhere
rm -rf "$out"
mkdir -p "$out"

echo "== the study: 15 joint models x 5 seeds"
"$dda" study "$here/study.yaml" -o "$out/study" | tee "$out/study.txt"

echo "== per joint model (per_model.json)"
/usr/bin/python3 "$here/per_model.py" "$out/study/summary.csv" -o "$out/per_model.json"
