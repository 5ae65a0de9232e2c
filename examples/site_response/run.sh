#!/usr/bin/env bash
# The site-response example, end to end (see README.md). Writes out/.
# Exits non-zero if the plain's receiver does not move with the outcrop
# motion of the input (check_site_response in plot_site_response.py).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../find_dda.sh"
dda="$(find_dda)"
py=/usr/bin/python3
export MPLBACKEND=Agg
out="${OUT:-$here/out}"
rm -rf "$out"
mkdir -p "$out/figures"

echo "== 1. input: 24 s of band-limited white noise (the outcrop motion of the base rock)"
"$py" "$here/make_input.py" "$out/input_noise.csv"
sed "s|record: input_noise.csv|record: $out/input_noise.csv|" "$here/site_response.yaml" > "$out/site_response.yaml"
# The outcrop motion as the solver sees it (the scenario's filter, ramp and
# baseline correction), integrated to velocity: the reference of the check.
"$dda" record "$out/input_noise.csv" --units m/s2 --highpass 0.3 --lowpass 8 --order 4 --ramp 0.5 \
    --integrate --baseline 3 -o "$out/outcrop.csv" -q

echo "== 2. DL -> DC -> DF (about a minute)"
start=$(date +%s)
"$dda" run "$out/site_response.yaml" -o "$out"
echo "dda run took $(( $(date +%s) - start )) s"
"$dda" history "$out/results.h5"

echo "== 3. spectra"
band=(--fmin 0.3 --fmax 8)
"$dda" spectra "$out/results.h5" --point crest --reference base "${band[@]}" -o "$out/ssr_crest.csv" \
    --plot "$out/figures/ssr_crest.png" --json > "$out/ssr_crest.json"
"$dda" spectra "$out/results.h5" --point edge --reference base "${band[@]}" -o "$out/ssr_edge.csv" --json \
    > "$out/ssr_edge.json"
"$dda" spectra "$out/results.h5" --point crest --hv "${band[@]}" -o "$out/hv_crest.csv" \
    --plot "$out/figures/hv_crest.png" --json > "$out/hv_crest.json"
"$dda" spectra "$out/results.h5" --point base --hv "${band[@]}" -o "$out/hv_base.csv" --json > "$out/hv_base.json"
"$dda" spectra "$out/results.h5" --point base "${band[@]}" -o "$out/spectrum_base.csv" -q
"$dda" spectra "$out/outcrop.csv" --column vx "${band[@]}" -o "$out/spectrum_outcrop.csv" -q
"$dda" history "$out/results.h5" --csv --acceleration -o "$out/history.csv"

echo "== 4. figures and check"
# The summary it prints (peaks, the check's median) is saved for
# scripts/check_readme_numbers.py.
"$py" "$here/plot_site_response.py" "$out" -o "$out/figures" | tee "$out/summary.json"
echo "figures in $out/figures; ParaView: $out/vtk/df.pvd"
