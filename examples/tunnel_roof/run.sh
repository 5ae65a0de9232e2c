#!/usr/bin/env bash
# The tunnel-roof example, end to end (see README.md). Writes out/
# (OUT=... another folder). What it prints that README.md quotes is also
# saved (run.log, history.txt, steps.csv), so that
# scripts/check_readme_numbers.py can compare the README with the run.
# A run interrupted (Ctrl-C) continues with: dda df --resume out/results.h5
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../find_dda.sh"
dda="$(find_dda)"
out="${OUT:-$here/out}"
rm -rf "$out"
mkdir -p "$out/figures"
start=$(date +%s)
"$dda" run "$here/tunnel_roof.yaml" -o "$out" | tee "$out/run.log"
echo "dda run took $(( $(date +%s) - start )) s"
"$dda" history "$out/results.h5" | tee "$out/history.txt"
"$dda" history "$out/results.h5" --steps -o "$out/steps.csv"
"$dda" history "$out/results.h5" --csv > "$out/history.csv"
MPLBACKEND=Agg /usr/bin/python3 "$here/plot_tunnel_roof.py" "$out/results.h5" -o "$out/figures" | tee "$out/loosened_zone.json"
"$dda" plot "$out/results.h5" -o "$out/figures/results" -q
echo "figures in $out/figures; ParaView: $out/vtk/df.pvd"
