#!/usr/bin/env bash
# The tunnel-roof example, end to end (see README.md). Writes out/.
# A run interrupted (Ctrl-C) continues with: dda df --resume out/results.h5
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
dda="${DDA:-$here/../../build/bin/dda}"
out="$here/out"
rm -rf "$out"
mkdir -p "$out/figures"
start=$(date +%s)
"$dda" run "$here/tunnel_roof.yaml" -o "$out"
echo "dda run took $(( $(date +%s) - start )) s"
"$dda" history "$out/results.h5"
"$dda" history "$out/results.h5" --csv > "$out/history.csv"
MPLBACKEND=Agg /usr/bin/python3 "$here/plot_tunnel_roof.py" "$out/results.h5" -o "$out/figures" | tee "$out/loosened_zone.json"
echo "figures in $out/figures; ParaView: $out/vtk/df.pvd"
