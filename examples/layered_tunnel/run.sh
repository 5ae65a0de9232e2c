#!/usr/bin/env bash
# The layered-tunnel example, end to end (see README.md). Writes out/
# (OUT=... another folder; scripts/check_examples.sh uses it).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../find_dda.sh"
dda="$(find_dda)"
out="${OUT:-$here/out}"
figs="$out/figures"
rm -rf "$out"
mkdir -p "$figs"

echo "== mechanically layered mass (FMML)"
"$dda" run "$here/layered.yaml" -o "$out/layered"
"$dda" stats "$out/layered/blocks.h5"

echo "== Shi-Goodman meshes: L = 5, 10, 15 m; bridge = L/5 ... L"
for L in 5 10 15; do
  files=("$out/layered/blocks.h5")
  labels=("layered (FMML)")
  for k in 1 2 3 4 5; do
    b=$(( L * k / 5 ))
    name="sg_L${L}_b${b}"
    sed -e "s/@LENGTH@/$L/g" -e "s/@BRIDGE@/$b/g" "$here/shi_goodman.template.yaml" > "$out/$name.yaml"
    "$dda" run "$out/$name.yaml" -o "$out/$name" --quiet
    echo "   $name: $(/usr/bin/python3 -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['blocks'], 'blocks, mean width', round(s['width']['mean'],3), 'm')" "$out/$name/stats.json")"
    files+=("$out/$name/blocks.h5")
    labels+=("bridge $b m")
  done
  # Figure 5 of the seed report: block width and area distributions per L.
  "$dda" plot "${files[@]}" --kind histograms --labels "${labels[@]}" \
      --title "L = $L m: Shi-Goodman meshes against the layered mesh" -o "$figs/histograms_L$L.png" --quiet
done

# Figure 6 of the seed report: mean block width against bridge / length.
MPLBACKEND=Agg /usr/bin/python3 "$here/plot_width_vs_bridge.py" "$out" -o "$figs/width_vs_bridge.png"

cp "$out/layered/figures/"*.png "$figs/" 2>/dev/null || true
echo "figures in $figs:"
ls "$figs"
