#!/usr/bin/env bash
# The wedge back-analysis example, end to end (see README.md). Writes out/.
# Exits non-zero if the wedge's yield acceleration or a back-fitted friction
# angle is off (check_backanalysis.py).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../find_dda.sh"
dda="$(find_dda)"
py=/usr/bin/python3
export MPLBACKEND=Agg
out="${OUT:-$here/out}"   # OUT=... writes elsewhere (the ctest run does)
figs="$out/figures"
rm -rf "$out"
mkdir -p "$figs"

# The V4 wedge of the shaking-table test (docs/validation.md V4; x east, y north, z up).
planes=(--plane 51.4/065.8 --plane 51.4/295.2)
# Shaking table: 2 Hz sinusoid along north-south, 0.22 g, linear ramp over 5 s.
amplitude=0.22 freq=2 ramp=5 duration=25
# The measurement: friction stepping 30 -> 28 -> 26 deg (friction_true.csv),
# sampled at 100 Hz (every 100th step of dt 1e-4 s), Gaussian noise 0.1 mm.
segments=10,18 noise=1e-4 seed=2026
# Expected values and tolerances of the check.
expected_yield=0.2074   # g, docs/validation.md V4: phi = 30 deg, horizontal shaking along +y
yield_tol=0.0005        # g; the table gives 4 digits, dda wedge 0.20742 g
phi_tol=0.2             # deg; recovered angles are within 0.001 deg (README)

echo "== 1. synthetic shaking-table record: $freq Hz, $amplitude g along y (north), $ramp s ramp, $duration s"
"$py" "$here/make_record.py" --amplitude "$amplitude" --freq "$freq" --duration "$duration" --dt 0.001 \
    -o "$out/table_raw.csv"
"$dda" record "$out/table_raw.csv" --units g --axis y --ramp "$ramp" -o "$out/table.csv"
record=(--record "$out/table.csv" --units m/s2)

echo "== 2. limit equilibrium: FS and yield acceleration (shaking along +y)"
"$dda" wedge "${planes[@]}" --phi 30 --azimuth 0 --json > "$out/wedge.json"
"$dda" wedge "${planes[@]}" --phi 30 --azimuth 0
for phi in 28 26; do
  "$dda" wedge "${planes[@]}" --phi "$phi" --azimuth 0 --json > "$out/wedge_phi$phi.json"
done
"$py" - "$out" <<'PY'
import json, sys
for name, phi in (("wedge.json", 30), ("wedge_phi28.json", 28), ("wedge_phi26.json", 26)):
    w = json.load(open(f"{sys.argv[1]}/{name}"))
    print(f"   phi = {phi} deg: FS = {w['fs']:.4f}, yield acceleration along +y = {w['yield_acceleration_g']:.4f} g")
PY

echo "== 3. the synthetic measurement (degrading friction) and the constant-friction solution"
"$dda" sliding3d "${planes[@]}" --friction-table "$here/friction_true.csv" "${record[@]}" --every 100 \
    -o "$out/sliding_degrading.csv" --json > "$out/sliding_degrading.json"
"$py" "$here/make_measurement.py" "$out/sliding_degrading.csv" "$out/sliding_degrading.json" \
    --noise "$noise" --seed "$seed" -o "$out/measured.csv"
"$dda" sliding3d "${planes[@]}" --phi 30 "${record[@]}" --every 100 \
    -o "$out/sliding_phi30.csv" --json > "$out/sliding_phi30.json"
"$py" - "$out" <<'PY'
import json, sys
for name, what in (("sliding_degrading.json", "degrading friction (noise-free)"), ("sliding_phi30.json", "constant phi = 30 deg")):
    s = json.load(open(f"{sys.argv[1]}/{name}"))
    print(f"   {what}: {1000 * s['final_displacement_along_reference']:.2f} mm down the line at {s['final_time']:g} s, "
          f"max speed {1000 * s['max_speed']:.2f} mm/s, {s['final_mode']}")
PY

echo "== 4. back-analysis: three friction segments, mu against ln v"
"$dda" backfit --measured "$out/measured.csv" "${planes[@]}" --segments "$segments" "${record[@]}" \
    --dt 2e-4 --v-ref 0.001 -o "$out/backfit.json"
# The back-fitted model as a history: the fitted angles as a friction table.
"$py" - "$out/backfit.json" "$out/friction_backfit.csv" <<'PY'
import json, sys
segs = json.load(open(sys.argv[1]))["segments"]
with open(sys.argv[2], "w") as f:
    f.write("t,phi\n")
    for s in segs:
        f.write(f"{s['t0']!r},{s['phi_deg']!r}\n{s['t1']!r},{s['phi_deg']!r}\n")
PY
"$dda" sliding3d "${planes[@]}" --friction-table "$out/friction_backfit.csv" "${record[@]}" --every 100 \
    -o "$out/sliding_backfit.csv" --json > "$out/sliding_backfit.json"

echo "== 5. figures"
"$py" "$here/plot_backanalysis.py" "$out" --friction-table "$here/friction_true.csv" --freq "$freq" -o "$figs"
ls "$figs"

echo "== 6. check"
"$py" "$here/check_backanalysis.py" --wedge "$out/wedge.json" --backfit "$out/backfit.json" \
    --friction-table "$here/friction_true.csv" --expected-yield "$expected_yield" --yield-tol "$yield_tol" \
    --phi-tol "$phi_tol" --noise "$noise"
