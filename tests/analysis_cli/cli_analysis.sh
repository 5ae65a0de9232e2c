#!/usr/bin/env bash
# Command-line tests of the analytical subcommands (newmark, sliding3d, wedge,
# backfit, record), one function per case; expected numbers from
# /work/shared/validation/CASES.md (V3, V4, V5) as noted in each case.
# Usage: cli_analysis.sh DDA_BINARY CASE WORKDIR SOURCE_DIR
set -uo pipefail
DDA="$1"; CASE="$2"; WORK="$3"; SRC="$4"
DATA="$SRC/tests/data"
rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK" || exit 1

fail() { echo "FAIL [$CASE]: $*" >&2; exit 1; }

# expect_error CODE PATTERN -- command...: exit CODE, exactly one line on
# stderr, matching PATTERN (grep -E).
expect_error() {
  local code="$1" pattern="$2"; shift 3
  "$@" >out.txt 2>err.txt; local rc=$?
  [ "$rc" -eq "$code" ] || fail "exit $rc, expected $code; stderr: $(cat err.txt)"
  [ "$(wc -l < err.txt)" -eq 1 ] || fail "expected one line on stderr, got: $(cat err.txt)"
  grep -qE -- "$pattern" err.txt || fail "stderr '$(cat err.txt)' does not match '$pattern'"
}

json_get() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2], {'d': d}))" "$@"; }

# near VALUE EXPECTED TOL WHAT: |VALUE - EXPECTED| <= TOL
near() {
  /usr/bin/python3 -c "import sys; v,e,t=map(float,sys.argv[1:4]); sys.exit(0 if abs(v-e)<=t else 1)" "$1" "$2" "$3" \
    || fail "$4 = $1, expected $2 +- $3"
}

# Last CSV row, column by header name.
last_col() { /usr/bin/python3 -c "
import csv,sys
rows=list(csv.DictReader(open(sys.argv[1])))
print(rows[-1][sys.argv[2]])" "$1" "$2"; }

case_help() {
  for sub in newmark sliding3d wedge backfit record compare; do
    "$DDA" $sub --help > h.txt 2>&1 || fail "dda $sub --help exited non-zero"
    grep -q "Usage" h.txt || fail "dda $sub --help prints no usage"
  done
  "$DDA" sliding3d --help | grep -q "ground" || fail "sliding3d --help does not explain ground/body input"
  "$DDA" newmark --help | grep -q "tan(phi - dip)" || fail "newmark --help does not give the yield formula"
}

# CASES.md V4: planes 51.4/065.8, 51.4/295.2.
case_wedge_v4() {
  "$DDA" wedge --plane 51.4/065.8 --plane 51.4/295.2 --phi 30 --azimuth 0 --json > w30.json || fail "wedge phi 30"
  near "$(json_get w30.json "d['fs']")" 1.5663 5e-5 "FS (phi 30)"
  near "$(json_get w30.json "d['yield_acceleration_g']")" 0.2074 5e-5 "yield acceleration (phi 30)"
  near "$(json_get w30.json "d['trend']")" 0.5 0.005 "trend"
  near "$(json_get w30.json "d['plunge']")" 27.63 0.005 "plunge"
  near "$(json_get w30.json "d['n1']")" 0.629 5e-4 "N1/W"
  near "$(json_get w30.json "d['n2']")" 0.629 5e-4 "N2/W"
  near "$(json_get w30.json "d['critical_friction_deg']")" 20.23 0.005 "phi at FS = 1"
  near "$(json_get w30.json "d['wedge_factor']")" 1.42013 1e-4 "K"
  [ "$(json_get w30.json "d['mode']")" = "double-face" ] || fail "mode"
  "$DDA" wedge --plane 51.4/065.8 --plane 51.4/295.2 --phi 36 --azimuth 0 --json > w36.json || fail "wedge phi 36"
  near "$(json_get w36.json "d['fs']")" 1.9710 5e-5 "FS (phi 36)"
  near "$(json_get w36.json "d['yield_acceleration_g']")" 0.3301 5e-5 "yield acceleration (phi 36)"
  # The same direction as a vector.
  "$DDA" wedge --plane 51.4/065.8 --plane 51.4/295.2 --phi 36 --direction 0,1,0 --json > wv.json || fail "--direction"
  near "$(json_get wv.json "d['yield_acceleration_g']")" 0.3301 5e-5 "yield acceleration (--direction)"
}

# CASES.md V5: Hoek & Bray planes 45/105, 70/235.
case_wedge_v5() {
  "$DDA" wedge --plane 45/105 --plane 70/235 --phi 20,30 --json > a.json || fail "wedge V5"
  near "$(json_get a.json "d['trend']")" 157.73 0.005 "trend"
  near "$(json_get a.json "d['plunge']")" 31.20 0.005 "plunge"
  near "$(json_get a.json "d['fs']")" 1.1066 5e-5 "FS (20, 30)"
  near "$(json_get a.json "d['n1']")" 0.7979 5e-5 "N_A/W"
  near "$(json_get a.json "d['n2']")" 0.4898 5e-5 "N_B/W"
  "$DDA" wedge --plane 45/105 --plane 70/235 --phi 30 --json > b.json || fail "wedge V5 30/30"
  near "$(json_get b.json "d['fs']")" 1.4353 5e-5 "FS (30, 30)"
}

# CASES.md V3: plane 20/090, phi 30, body acceleration 0.5 g sin(10 t) along x;
# |D| = 1.239 m after 2 pi s (within 1%).
case_newmark_v3() {
  "$DDA" newmark --dip 20 --dip-direction 90 --phi 30 --sine 0.5 --omega 10 --axis x --input body \
    --duration 6.283185307179586 --dt 1e-4 -o nm.csv --json > nm.json || fail "newmark"
  near "$(json_get nm.json "d['yield_acceleration_g']")" 0.17633 5e-6 "yield acceleration"
  near "$(json_get nm.json "d['final_displacement']")" 1.239 0.01239 "final displacement"
  near "$(last_col nm.csv s)" 1.239 0.01239 "CSV last s"
  near "$(last_col nm.csv t)" 6.283185307179586 1e-9 "CSV last t"
  # As ground acceleration the sign flips: ground -0.5 g sin(10t) along x is the same input.
  "$DDA" newmark --dip 20 --phi 30 --sine -0.5 --omega 10 --duration 6.283185307179586 --json > g.json || fail "ground"
  near "$(json_get g.json "d['final_displacement']")" "$(json_get nm.json "d['final_displacement']")" 1e-12 "ground vs body"
}

# CASES.md V3 with the 3D solution: D = (1.165, 0, -0.424), |D| = 1.239 m.
case_sliding3d_v3() {
  "$DDA" sliding3d --plane 20/090 --phi 30 --sine 0.5 --omega 10 --axis x --input body \
    --duration 6.283185307179586 --dt 1e-4 --every 100 -o s3.csv --json > s3.json || fail "sliding3d"
  near "$(last_col s3.csv ux)" 1.165 0.01165 "ux"
  near "$(last_col s3.csv uy)" 0 1e-6 "uy"
  near "$(last_col s3.csv uz)" -0.424 0.00424 "uz"
  near "$(json_get s3.json "d['final_displacement_magnitude']")" 1.239 0.01239 "|D|"
  head -1 s3.csv | grep -q '^t,ux,uy,uz,vx,vy,vz,N1,N2$' || fail "CSV header $(head -1 s3.csv)"
}

# CASES.md V4, phi 10 under gravity: a = 2.3731 m/s^2 along the line, so
# s(2 s) = 2 a = 4.7462 m; N1 = N2 = 0.629 W.
case_sliding3d_v4() {
  "$DDA" sliding3d --plane 51.4/065.8 --plane 51.4/295.2 --phi 10 --duration 2 --dt 1e-3 -o w.csv --json > w.json \
    || fail "sliding3d wedge"
  near "$(json_get w.json "d['final_displacement_along_reference']")" 4.7462 5e-4 "s(2 s)"
  near "$(json_get w.json "d['reference_trend']")" 0.5 0.005 "trend"
  near "$(json_get w.json "d['reference_plunge']")" 27.63 0.005 "plunge"
  near "$(last_col w.csv N1)" 0.629 5e-4 "N1/W"
  near "$(last_col w.csv N2)" 0.629 5e-4 "N2/W"
}

# A record file as input: the 2 Hz, 0.25 g record along +y read as body
# acceleration drives the V4 wedge (phi 30, yield 0.2074 g along +y) down the
# line. Without --units the CSV is refused.
case_sliding3d_record() {
  "$DDA" sliding3d --plane 51.4/065.8 --plane 51.4/295.2 --phi 30 --record "$DATA/rec_sine2hz.csv" --units g \
    --input body --dt 1e-3 --json > r.json || fail "record input"
  /usr/bin/python3 -c "import json,sys; d=json.load(open('r.json')); sys.exit(0 if d['final_displacement_along_reference']>1e-3 else 1)" \
    || fail "no sliding above yield"
  expect_error 1 "rec_sine2hz.csv: .*units" -- "$DDA" sliding3d --plane 20/090 --phi 30 --record "$DATA/rec_sine2hz.csv"
}

# Back-analysis: a synthetic history from sliding3d with phi 30 then 28
# (friction table) is fitted back within 0.1 degree.
case_backfit_segments() {
  printf 't,phi\n0,30\n5,30\n5,28\n10,28\n' > table.csv
  "$DDA" sliding3d --plane 51.4/065.8 --plane 51.4/295.2 --friction-table table.csv \
    --record "$DATA/rec_sine2hz.csv" --units g --input body --dt 1e-4 --every 100 -o truth.csv -q || fail "truth"
  /usr/bin/python3 -c "
import csv
rows=list(csv.DictReader(open('truth.csv')))
with open('measured.csv','w') as f:
    f.write('t,ux,uy,uz\n')
    for r in rows[1:]: f.write(f\"{r['t']},{r['ux']},{r['uy']},{r['uz']}\n\")"
  "$DDA" backfit --measured measured.csv --plane 51.4/065.8 --plane 51.4/295.2 --segments 5 --phi-range 20,40 \
    --record "$DATA/rec_sine2hz.csv" --units g --input body --dt 5e-4 --json -o fit.json > out.json || fail "backfit"
  near "$(json_get fit.json "d['segments'][0]['phi_deg']")" 30 0.1 "segment 1 phi"
  near "$(json_get fit.json "d['segments'][1]['phi_deg']")" 28 0.1 "segment 2 phi"
  cmp -s fit.json out.json || fail "--json and -o differ"
}

case_record_process() {
  "$DDA" record "$DATA/rec_small.at2" --json > at2.json || fail "record at2"
  [ "$(json_get at2.json "d['samples']")" = 401 ] || fail "AT2 samples"
  near "$(json_get at2.json "d['peak_acceleration'][0]")" 0.981 1e-6 "AT2 peak (0.1 g)"
  "$DDA" record "$DATA/rec_sine2hz.csv" --units g --axis y --lowpass 1 --order 4 --integrate -o proc.csv --json > p.json \
    || fail "record filter"
  # 2 Hz through a 1 Hz zero-phase order-4 low-pass: gain 1/(1 + (tan(2pi/200)/tan(pi/200))^8) = 0.0039.
  near "$(json_get p.json "d['peak_acceleration'][1]")" "$(/usr/bin/python3 -c "import math; print(0.25*9.81/(1+(math.tan(2*math.pi/200)/math.tan(math.pi/200))**8))")" 0.003 "filtered peak"
  head -1 proc.csv | grep -q '^t,ax,ay,az,vx,vy,vz,dx,dy,dz$' || fail "integrated CSV header"
}

case_bad_records() {
  expect_error 1 "rec_nonmonotonic.csv, line 4: .*times must increase" -- \
    "$DDA" record "$DATA/rec_nonmonotonic.csv" --units g
  expect_error 1 "rec_nan.csv, line 3, column 2: .*not a finite number" -- "$DDA" record "$DATA/rec_nan.csv" --units g
  expect_error 1 "rec_empty.csv: no samples" -- "$DDA" record "$DATA/rec_empty.csv" --units g
  expect_error 1 "rec_columns.csv, line 3: 2 columns" -- "$DDA" record "$DATA/rec_columns.csv" --units g
  expect_error 1 "--units: unknown acceleration units 'gal'" -- "$DDA" record "$DATA/rec_sine2hz.csv" --units gal
  expect_error 1 "rec_small.at2: .*declares units of g" -- "$DDA" record "$DATA/rec_small.at2" --units m/s2
  expect_error 1 "nothere.csv: file not found" -- "$DDA" record nothere.csv --units g
  expect_error 1 "Nyquist" -- "$DDA" record "$DATA/rec_sine2hz.csv" --units g --lowpass 150
  # Same errors through the analysis commands.
  expect_error 1 "rec_nan.csv, line 3" -- "$DDA" newmark --dip 20 --phi 30 --record "$DATA/rec_nan.csv" --units g
}

case_bad_arguments() {
  expect_error 1 "--plane: '95/010' has a dip outside" -- "$DDA" wedge --plane 95/010 --plane 40/200 --phi 30
  expect_error 1 "--plane: a wedge needs exactly two planes" -- "$DDA" wedge --plane 45/105 --phi 30
  expect_error 1 "parallel" -- "$DDA" wedge --plane 45/105 --plane 45/105 --phi 30
  expect_error 1 "--sine: give its frequency" -- "$DDA" sliding3d --plane 20/090 --phi 30 --sine 0.5 --duration 1
  expect_error 1 "--duration" -- "$DDA" sliding3d --plane 20/090 --phi 30
  expect_error 1 "exactly one of --phi" -- "$DDA" sliding3d --plane 20/090 --duration 1
  expect_error 1 "--input: 'sideways'" -- "$DDA" newmark --dip 20 --phi 30 --sine 0.5 --freq 1 --duration 1 --input sideways
}

# The V3 block on its 20-degree plane as a scenario (DL -> DC -> DF) under
# loading.earthquake, a ground record a_g = -0.5 g sin(10 t) along x.
# write_v3_scenario MODE_ENTRY: writes v3_ground.csv and v3.yaml here.
write_v3_scenario() {
  /usr/bin/python3 - "$1" <<'PY'
import math, sys
a = math.radians(20)
def r(x, y):  # slope frame (x down the plane) -> model
    return [round(x * math.cos(a) + y * math.sin(a), 9), round(-x * math.sin(a) + y * math.cos(a), 9)]
with open("v3_ground.csv", "w") as f:
    f.write("t,ax,ay\n")
    for i in range(6295):
        t = i * 1e-3
        f.write(f"{t:.3f},{-0.5 * 9.81 * math.sin(10 * t):.12g},0\n")
poly = [r(0, -1), r(10, -1), r(10, 0), r(2.5, 0), r(2.5, 1), r(1.5, 1), r(1.5, 0), r(0, 0)]
pts = [("base1", "fixed", r(0.5, -0.5)), ("base2", "fixed", r(5, -0.5)), ("base3", "fixed", r(9.5, -0.5)),
       ("ground", "measurement", r(5, -0.5)), ("slider", "measurement", r(2, 0.5))]
y = f"name: v3\ndomain: {{polygon: {poly}}}\nlines:\n  - {{set: plane, from: {r(1.5, 0)}, to: {r(2.5, 0)}}}\npoints:\n"
y += "".join(f"  - {{name: {n}, kind: {k}, at: {p}}}\n" for n, k, p in pts)
y += ("materials:\n  default: {density: 2000, young: 5e10, poisson: 0.25, plane: stress}\n"
      "joints:\n  default: {friction_deg: 30}\n"
      f"loading:\n  gravity: [0, -9.81]\n  earthquake: {sys.argv[1]}\n"
      "control: {dt: 0.001, total_time: 6.283185307179586, initial_equilibrium: true}\n"
      "output: {vtk: false, plots: false}\n")
open("v3.yaml", "w").write(y)
PY
}

# dda compare on V3 run through `dda run` in both earthquake modes, against
# dda newmark on the same record (1.2381 m). The modes must agree within
# 1 %. Against Newmark this DC-cut model is 4.5 % short (measured; the
# hand-built model of tests/df/test_v3_earthquake.cpp is within 0.02 %):
# DC leaves a flat vertex on the plane's top where the joint under the
# block ends, and the block's first slip stops on it (a contact-detection
# matter, not the input); the bound below is 6 %.
case_compare_v3() {
  write_v3_scenario "{record: v3_ground.csv, units: m/s2, mode: loading}"
  "$DDA" -q run v3.yaml -o load || fail "dda run (loading mode)"
  write_v3_scenario "{record: v3_ground.csv, units: m/s2, mode: displacement, baseline: 0}"
  "$DDA" -q run v3.yaml -o disp || fail "dda run (displacement mode)"
  "$DDA" newmark --dip 20 --phi 30 --record v3_ground.csv --units m/s2 --duration 6.283185307179586 -o nm.csv \
    || fail "newmark"
  "$DDA" compare load/results.h5 --point slider --dip 20 --reference nm.csv --json -o load.csv > load.json \
    || fail "compare (loading)"
  "$DDA" compare disp/results.h5 --point slider --relative-to ground --dip 20 --reference nm.csv --json \
    --plot disp.png > disp.json || fail "compare (displacement)"
  [ -s disp.png ] || fail "no figure"
  head -1 load.csv | grep -q '^t,dda,reference,difference,relative_error$' || fail "CSV header $(head -1 load.csv)"
  near "$(json_get load.json "d['final_reference']")" 1.2381 1e-4 "Newmark reference"
  near "$(json_get load.json "d['final_time']")" 6.283185307179586 1e-9 "final time"
  near "$(last_col load.csv relative_error)" "$(json_get load.json "d['final_relative_error']")" 1e-12 "CSV vs JSON"
  near "$(json_get load.json "d['final_relative_error']")" 0 0.06 "loading mode vs Newmark"
  near "$(json_get disp.json "d['final_relative_error']")" 0 0.06 "displacement mode vs Newmark"
  near "$(json_get disp.json "d['final_dda']")" "$(json_get load.json "d['final_dda']")" \
    "$(/usr/bin/python3 -c "print(0.01 * 1.2381)")" "displacement vs loading mode"
  # Without --relative-to the displacement mode's slider includes the ground's 3 m drift.
  "$DDA" compare disp/results.h5 --point slider --dip 20 --reference nm.csv --json > abs.json || fail "compare abs"
  /usr/bin/python3 -c "import sys; sys.exit(0 if abs($(json_get abs.json "d['final_relative_error']")) > 0.5 else 1)" \
    || fail "--relative-to made no difference"
  # The 3D solution projected on the plane's downslope direction (ux, uy, uz columns).
  "$DDA" sliding3d --plane 20/090 --phi 30 --record v3_ground.csv --units m/s2 --duration 6.283185307179586 \
    -o s3.csv || fail "sliding3d"
  "$DDA" compare load/results.h5 --point slider --dip 20 --reference s3.csv --json > s3.json || fail "compare 3D"
  near "$(json_get s3.json "d['final_reference']")" 1.2379 2e-4 "sliding3d along the plane"
  expect_error 1 "has no measurement point 'nope'" -- "$DDA" compare load/results.h5 --point nope --dip 20 --reference nm.csv
  expect_error 1 "--dip or --direction" -- "$DDA" compare load/results.h5 --point slider --reference nm.csv
  expect_error 1 "has no column 'q'" -- "$DDA" compare load/results.h5 --point slider --dip 20 --reference nm.csv --column q
  "$DDA" compare --help | grep -q "Sign conventions" || fail "--help has no sign conventions"
}

# Earthquake input errors through `dda run`: one line naming the scenario
# file, line and key, and the record file and line; exit status 1.
case_earthquake_errors() {
  write_v3_scenario "{record: v3_ground.csv, units: m/s2}"
  printf 't,ax,ay\n0,0,0\n0.2,1,0\n0.1,1,0\n' > back.csv
  sed 's/record: v3_ground.csv/record: back.csv/' v3.yaml > back.yaml
  expect_error 1 "back.yaml:[0-9]+: loading.earthquake.record cannot be used: .*back.csv, line 4: time 0.1 s is not greater" \
    -- "$DDA" run back.yaml -o o1
  sed 's/units: m\/s2}/units: furlongs}/' v3.yaml > units.yaml
  expect_error 1 "units.yaml:[0-9]+: loading.earthquake.units must be g or m/s2" -- "$DDA" run units.yaml -o o2
  sed 's/units: m\/s2}/units: g, mode: displacement, foundation: [top]}/' v3.yaml > found.yaml
  expect_error 1 "found.yaml:[0-9]+: loading.earthquake.foundation\[0\] names side top, which fixed.boundary does not hold" \
    -- "$DDA" run found.yaml -o o3
}

declare -F "case_$CASE" > /dev/null || fail "no such case"
"case_$CASE"
echo "PASS [$CASE]"
