#!/usr/bin/env bash
# Command-line tests of the `dda` program, one function per case.
# Usage: cli_cases.sh DDA_BINARY CASE WORKDIR SOURCE_DIR
set -uo pipefail
DDA="$1"; CASE="$2"; WORK="$3"; SRC="$4"
rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK" || exit 1

fail() { echo "FAIL [$CASE]: $*" >&2; exit 1; }

# expect_error CODE PATTERN -- command...: the command must exit with CODE,
# print exactly one line on stderr, and that line must match PATTERN (grep -E).
expect_error() {
  local code="$1" pattern="$2"; shift 3
  "$@" >out.txt 2>err.txt; local rc=$?
  [ "$rc" -eq "$code" ] || fail "exit $rc, expected $code; stderr: $(cat err.txt)"
  [ "$(wc -l < err.txt)" -eq 1 ] || fail "expected one line on stderr, got: $(cat err.txt)"
  grep -qE "$pattern" err.txt || fail "stderr '$(cat err.txt)' does not match '$pattern'"
}

# A command-line usage error: exit status 2 (CLI11 prints the problem and a hint).
expect_usage_error() {
  "$@" >out.txt 2>err.txt; local rc=$?
  [ "$rc" -eq 2 ] || fail "exit $rc, expected 2 for a usage error; stderr: $(cat err.txt)"
}

# A small scenario: 20 x 10 m box, two through-going joint sets, a tunnel.
write_scenario() {
  cat > scenario.yaml <<'YAML'
name: cli_test
seed: 7
domain:
  box: [0, 0, 20, 10]
joint_sets:
  - {name: J1, dip: 30, mean_length: 6, mean_bridge: 1, mean_spacing: 1.5, randomness: 0.3}
  - {name: J2, dip: 120, mean_length: 5, mean_bridge: 2, mean_spacing: 2, randomness: 0.3}
excavations:
  - {shape: rectangle, center: [10, 4], width: 4, height: 3}
points:
  - {name: roof, kind: measurement, at: [10.05, 6.3]}
output: {vtk: true, plots: false}
YAML
}

json_get() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2], {'d': d}))" "$@"; }

case_version() {
  "$DDA" --version | grep -qE '^dda [0-9]+\.[0-9]+\.[0-9]+' || fail "--version"
}

case_help_everywhere() {
  for sub in "" dl dc df run stats plot info history; do
    "$DDA" $sub --help > h.txt 2>&1 || fail "dda $sub --help exited non-zero"
    grep -q "Usage" h.txt || fail "dda $sub --help prints no usage"
  done
  expect_usage_error "$DDA" frobnicate
}

case_dl_dc_stats_chain() {
  write_scenario
  "$DDA" dl scenario.yaml -o lines.h5 --vtk lines.vtu --report dl.json -q || fail "dl"
  "$DDA" dc lines.h5 -o blocks.h5 --vtk blocks.vtu --report dc.json -q || fail "dc"
  "$DDA" stats blocks.h5 --json > stats.json || fail "stats"
  # Blocks tile the box minus the tunnel: 20*10 - 4*3 = 188 m^2.
  total=$(json_get stats.json "d['total_area']")
  /usr/bin/python3 -c "import sys; t=float(sys.argv[1]); sys.exit(0 if abs(t-188.0) < 1e-9*188 else 1)" "$total" \
    || fail "total area $total, expected 188"
  [ -s lines.vtu ] && [ -s blocks.vtu ] || fail "vtu files missing"
  ls -a | grep -q '\.tmp' && fail "temporary files left behind"
  true
}

case_run_writes_everything() {
  write_scenario
  "$DDA" run scenario.yaml -o out -q || fail "run"
  for f in lines.h5 blocks.h5 dl_report.json dc_report.json stats.json vtk/lines.vtu vtk/blocks.vtu vtk/model.pvd; do
    [ -s "out/$f" ] || fail "out/$f missing"
  done
}

case_stats_json_keys() {
  write_scenario
  "$DDA" run scenario.yaml -o out -q --no-vtk || fail "run"
  "$DDA" stats out/blocks.h5 --json > s.json || fail "stats"
  for k in blocks total_area area width; do
    json_get s.json "'$k' in d" | grep -q True || fail "key $k missing"
  done
  json_get s.json "sum(d['area']['histogram']['counts']) == d['blocks']" | grep -q True || fail "histogram counts"
  "$DDA" stats out/blocks.h5 | grep -q "blocks:" || fail "plain stats output"
}

case_info_describes_files() {
  write_scenario
  "$DDA" run scenario.yaml -o out -q --no-vtk || fail "run"
  "$DDA" info out/lines.h5 | grep -q "dda-lines" || fail "info lines"
  "$DDA" info out/blocks.h5 | grep -q "seed: *7" || fail "info seed"
  "$DDA" info out/blocks.h5 --scenario | grep -q "name: cli_test" || fail "scenario text not stored"
}

case_geo_import_round_trip() {
  # A DDA-for-Windows geometry: a 2 x 1 box split by one vertical joint.
  "$DDA" dl "$SRC/tests/data/dl_two_blocks.geo" -o lines.h5 -q || fail "geo import"
  "$DDA" dc lines.h5 -o blocks.h5 -q || fail "dc of imported geometry"
  "$DDA" stats blocks.h5 --json > s.json || fail "stats"
  [ "$(json_get s.json "d['blocks']")" = "2" ] || fail "expected 2 blocks, got $(json_get s.json "d['blocks']")"
  json_get s.json "abs(d['total_area'] - 2.0) < 1e-12" | grep -q True || fail "total area"
}

case_csv_traces() {
  # Three horizontal and two vertical through-going traces in a 4 x 4 box:
  # (3+1)(2+1) = 12 blocks.
  printf 'x1,y1,x2,y2,set\n0,1,4,1,h\n0,2,4,2,h\n0,3,4,3,h\n1,0,1,4,v\n2.5,0,2.5,4,v\n' > t.csv
  printf 'domain: {box: [0, 0, 4, 4]}\ntraces:\n  - {file: t.csv}\n' > s.yaml
  "$DDA" run s.yaml -o out -q --no-vtk --no-plots || fail "run"
  [ "$(json_get out/stats.json "d['blocks']")" = "12" ] || fail "expected 12 blocks"
}

case_bad_scenario_key() {
  write_scenario
  sed -i 's/mean_length: 6/mean_lenght: 6/' scenario.yaml
  expect_error 1 "scenario.yaml:6: .*joint_sets\[0\]\.mean_lenght.*mean_length" -- "$DDA" dl scenario.yaml -o l.h5
  [ ! -e l.h5 ] || fail "an output was written despite the error"
}

case_bad_scenario_range() {
  write_scenario
  sed -i 's/mean_spacing: 1.5/mean_spacing: -1.5/' scenario.yaml
  expect_error 1 "scenario.yaml:6: joint_sets\[0\]\.mean_spacing must be > 0, got -1.5" -- "$DDA" run scenario.yaml -o out
}

case_bad_scenario_type() {
  write_scenario
  sed -i 's/dip: 30/dip: steep/' scenario.yaml
  expect_error 1 "scenario.yaml:6: joint_sets\[0\]\.dip must be a number, got 'steep'" -- "$DDA" dl scenario.yaml -o l.h5
}

case_missing_required_key() {
  printf 'name: x\njoint_sets: []\n' > s.yaml
  expect_error 1 "s.yaml:1: domain is required" -- "$DDA" dl s.yaml -o l.h5
}

case_missing_input_file() {
  expect_error 1 "nope.yaml: no such file" -- "$DDA" run nope.yaml -o out
  expect_error 1 "nope.h5" -- "$DDA" dc nope.h5 -o b.h5
}

case_wrong_file_kind() {
  write_scenario
  "$DDA" run scenario.yaml -o out -q --no-vtk || fail "run"
  expect_error 1 "out/blocks.h5: .*dda-blocks.*dda-lines" -- "$DDA" dc out/blocks.h5 -o b.h5
  echo "not hdf5" > junk.h5
  expect_error 1 "junk.h5" -- "$DDA" stats junk.h5
}

case_unwritable_output() {
  write_scenario
  expect_error 1 "no_such_dir/lines.h5" -- "$DDA" dl scenario.yaml -o no_such_dir/lines.h5
}

case_plot_png() {
  write_scenario
  "$DDA" run scenario.yaml -o out -q --no-vtk --no-plots || fail "run"
  "$DDA" plot out/blocks.h5 -o blocks.png -q || fail "plot blocks"
  "$DDA" plot out/lines.h5 -o lines.svg -q || fail "plot lines"
  "$DDA" plot out/blocks.h5 out/blocks.h5 --kind histograms --labels a b -o h.png -q || fail "plot histograms"
  head -c 8 blocks.png | od -An -c | grep -q "P   N   G" || fail "blocks.png is not a PNG"
  grep -q "<svg" lines.svg || fail "lines.svg is not an SVG"
  [ -s h.png ] || fail "histogram figure missing"
}

case_plot_bad_input() {
  echo "x" > junk.h5
  expect_error 1 "junk.h5" -- "$DDA" plot junk.h5 -o x.png
  write_scenario
  "$DDA" run scenario.yaml -o out -q --no-vtk --no-plots || fail "run"
  expect_error 1 "labels" -- "$DDA" plot out/blocks.h5 --labels a b -o x.png
}

case_deterministic_seed() {
  write_scenario
  "$DDA" dl scenario.yaml -o a.h5 -q && "$DDA" dl scenario.yaml -o b.h5 -q || fail "dl"
  "$DDA" dc a.h5 -o ba.h5 -q && "$DDA" dc b.h5 -o bb.h5 -q || fail "dc"
  "$DDA" stats ba.h5 --json | grep -v created > sa.json; "$DDA" stats bb.h5 --json | grep -v created > sb.json
  cmp -s sa.json sb.json || fail "same seed gave different blocks"
  sed -i 's/seed: 7/seed: 8/' scenario.yaml
  "$DDA" dl scenario.yaml -o c.h5 -q && "$DDA" dc c.h5 -o bc.h5 -q || fail "dl seed 8"
  "$DDA" stats bc.h5 --json > sc.json
  cmp -s sa.json sc.json && fail "different seeds gave identical blocks"
  true
}

case_sliver_override() {
  write_scenario
  "$DDA" run scenario.yaml -o plain -q --no-vtk --no-plots || fail "run"
  "$DDA" run scenario.yaml -o merged -q --no-vtk --no-plots --min-area 0.05 --slivers merge || fail "run with filter"
  n0=$(json_get plain/stats.json "d['blocks']"); n1=$(json_get merged/stats.json "d['blocks']")
  small=$(json_get plain/stats.json "d['area']['min'] < 0.05")
  [ "$small" = "True" ] || fail "test scenario has no block below 0.05 m^2; the case tests nothing"
  [ "$n1" -lt "$n0" ] || fail "merging slivers did not reduce the block count ($n0 -> $n1)"
  json_get merged/stats.json "abs(d['total_area'] - 188.0) < 1e-9 * 188" | grep -q True || fail "area not conserved"
  expect_usage_error "$DDA" run scenario.yaml -o x --slivers squash
}

# DF: a 1 m block on a 30-degree incline (an 8 x 1 m slab held by three
# fixed points), phi = 20 degrees, 1 s under gravity. Built in the slope
# frame and rotated; a second measurement point rides in the slab.
write_incline() {
  /usr/bin/python3 "$SRC/tests/tools/incline_scenario.py" > incline.yaml || fail "write the incline scenario"
}

# The incline scenario and its blocks file (blocks.h5), cut by dl and dc.
incline_blocks() {
  write_incline
  "$DDA" dl incline.yaml -o lines.h5 -q && "$DDA" dc lines.h5 -o blocks.h5 -q || fail "dl, dc"
}

case_unbounded_text_inputs() {
  # A text input that is not text ends in one sentence, quickly: /dev/zero
  # has no line ends and no end (it was read for ever), and a binary file
  # read as lines is one huge line (docs/reliability.md, "Bounded reads").
  cat > s.yaml <<'YAML'
name: zero
seed: 1
domain: {polygon: [[0, 0], [10, 0], [10, 10], [0, 10]]}
traces:
  - {file: /dev/zero, set: mapped}
YAML
  expect_error 1 "^dda: s.yaml:5: traces\\[0\\].file names a trace file with an error: /dev/zero:1: is longer than 1 MiB, so this is not a trace file\\.$" -- \
    timeout 20 "$DDA" dl s.yaml -o l.h5
  expect_error 1 "^dda: /dev/zero:1: is longer than 1 MiB, so this is not a scenario file\\.$" -- timeout 20 "$DDA" dl /dev/zero -o l.h5
  head -c 3000000 /dev/urandom | tr -d '\n' > noise.csv
  expect_error 1 "noise.csv:1: is longer than 1 MiB, so this is not a record file\\.$" -- \
    timeout 20 "$DDA" spectra noise.csv --units g
  [ ! -e l.h5 ] || fail "an output was written"
}

case_dc_star_keeps_its_rock() {
  # Ten joints through one point of a 10 m box, their ends written to 12
  # decimals, so that they cross within 1e-10 m of the centre, not at one
  # point. Their crossings are merged into one point (dc/src/near_crossings.cpp)
  # and the cut keeps all the rock: 20 sectors, 100 m^2, nothing dropped and
  # no warning. (Before the merge the exact faces there were no simple
  # polygons once rounded, and two faces, 13.1 m^2, were dropped with a
  # warning: the warning stays, for any face that is still dropped.)
  /usr/bin/python3 - > star.yaml <<'PY'
import math
print("name: star\nseed: 1\ndomain: {polygon: [[0, 0], [10, 0], [10, 10], [0, 10]]}\nlines:")
for k in range(10):
    c, s = math.cos(math.pi * k / 10), math.sin(math.pi * k / 10)
    print("  - {set: s, from: [%.12f, %.12f], to: [%.12f, %.12f]}" % (5 - 8 * c, 5 - 8 * s, 5 + 8 * c, 5 + 8 * s))
PY
  "$DDA" dl star.yaml -o l.h5 -q || fail "dl"
  "$DDA" dc l.h5 -o b.h5 --report r.json > out.txt 2> err.txt || fail "dc: $(cat err.txt)"
  grep -q "^20 blocks (total area 100 m^2)" out.txt || fail "not 20 blocks of 100 m^2: $(cat out.txt)"
  [ ! -s err.txt ] || fail "the cut warned: $(cat err.txt)"
  /usr/bin/python3 - r.json <<'PY' || fail "report"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["degenerate_blocks"] == 0, r["degenerate_blocks"]
assert r["near_crossings"]["merged"] == 1 and r["near_crossings"]["segments_rerouted"] == 10, r["near_crossings"]
PY
}

case_geometry_errors_name_their_file() {
  # A 1e300 m box (whose area is no finite number) is refused where it is
  # read, naming the scenario; before, it was cut into a blocks file its own
  # reader refused. (A 10 m box at 1e12, refused until local origins, now
  # runs: case local_origin_2d.)
  # refused NAME POLYGON PATTERN: dda dl refuses NAME.yaml, a domain alone.
  refused() {
    printf 'name: %s\ndomain: {polygon: %s}\n' "$1" "$2" > "$1.yaml"
    expect_error 1 "$3" -- "$DDA" dl "$1.yaml" -o l.h5 -q
  }
  refused huge "[[0, 0], [1e300, 0], [1e300, 1e300], [0, 1e300]]" \
    "^dda: huge\.yaml: has coordinates up to 1e\+300 m, beyond the 1e\+15 m any model may reach \(coordinates are metres; doubles there are more than 0\.1 m apart\)\.$"
  refused nan "[[0, 0], [.nan, 0], [10, 10], [0, 10]]" "^dda: nan\.yaml:2: domain\.polygon\[1\]\[0\] must be a finite number, got '\.nan'\.$"
  [ ! -e l.h5 ] || fail "a lines file was written"
  # A measurement point inside the tunnel: the cutter finds it in no block,
  # and says which file it came from (the lines file for dc, the scenario
  # for run).
  cat > inside.yaml <<'YAML'
name: inside
domain: {box: [0, 0, 20, 10]}
excavations:
  - {shape: rectangle, center: [10, 4], width: 4, height: 3}
points:
  - {name: crown, kind: measurement, at: [10, 4]}
YAML
  "$DDA" dl inside.yaml -o li.h5 -q || fail "dl inside.yaml"
  expect_error 1 "^dda: li\.h5: the measurement point 'crown' at \(10, 4\) lies in no block: it is inside an excavation\.$" -- \
    "$DDA" dc li.h5 -o b.h5 -q
  expect_error 1 "^dda: inside\.yaml: the measurement point 'crown' at \(10, 4\) lies in no block" -- \
    "$DDA" run inside.yaml -o run -q
  # The same model at 1e12 is cut about a local origin, and the sentence
  # gives the point where the user put it.
  sed -e 's/box: \[0, 0, 20, 10\]/box: [1e12, 1e12, 1000000000020, 1000000000010]/' \
      -e 's/\[10, 4\]/[1000000000010, 1000000000004]/' inside.yaml > far.yaml
  expect_error 1 "^dda: far\.yaml: the measurement point 'crown' at \(1000000000010, 1000000000004\) lies in no block" -- \
    "$DDA" run far.yaml -o far -q
}

# ------------------------------------------------------ local origins
# docs/reliability.md, "Coordinates far from the origin": a model far from
# the origin for its size is cut and run about a local origin near its
# centre, and every position a user reads back is in their coordinates.

# The origin `dda info FILE` reports ("local origin: (x, y[, z]) m ..."),
# as space-separated numbers; nothing for a file without one.
origin_of() {
  "$DDA" info "$1" | sed -n 's/^local origin: *(\(.*\)) m.*/\1/p' | tr -d ','
}

# write_moved_incline SX SY OX OY > FILE: the incline of
# tests/tools/incline_scenario.py (0.5 s of it) moved by (SX, SY) and then
# written about (OX, OY): each coordinate is fl(fl(r + S) - O), as a user
# far away would write it (fl(r + S)) and then seen from O.
write_moved_incline() {
  /usr/bin/python3 - "$@" <<'PY'
import math, sys
sx, sy, ox, oy = map(float, sys.argv[1:5])
a = math.radians(30)
def r(x, y):
    u = round(math.cos(a) * x - math.sin(a) * y, 12) + sx
    v = round(math.sin(a) * x + math.cos(a) * y, 12) + sy
    return "[%r, %r]" % (u - ox, v - oy)
poly = ", ".join(r(*p) for p in [(0, -1), (8, -1), (8, 0), (7, 0), (7, 1), (6, 1), (6, 0), (0, 0)])
print("name: incline\nseed: 3\ndomain: {polygon: [%s]}" % poly)
print("lines:\n  - {set: interface, from: %s, to: %s}\npoints:" % (r(6, 0), r(7, 0)))
for i, x in enumerate([0.5, 4.0, 7.5]):
    print("  - {name: base%d, kind: fixed, at: %s}" % (i + 1, r(x, -0.5)))
print("  - {name: slider, kind: measurement, at: %s}" % r(6.5, 0.5))
print("""materials:
  default: {density: 2000, young: 5.0e10, poisson: 0.25, plane: stress}
joints:
  default: {friction_deg: 45}
  interface: {friction_deg: 20}
control: {dt: 0.001, total_time: 0.5, output_interval: 0.25}
output: {vtk: true, plots: false}""")
PY
}

# Compares the runs far/ and near/ of one model, the first far from the
# origin, the second its local coordinates (ORIGIN: the far model's origin,
# space-separated): the same history to the last bit, but for positions,
# which are the near ones plus the origin (in doubles); the first VTK frame's
# points likewise. POINT names a measurement point that must have moved,
# AXES the model's axes (xy or xyz).
same_run_about_origin() {
  "$DDA" history far/results.h5 --csv > far.csv && "$DDA" history near/results.h5 --csv > near.csv \
    || fail "history"
  /usr/bin/python3 - "$1" "$2" "$3" <<'PY' || fail "the far run is not the near run moved by the origin"
import csv, re, sys
point, axes, origin = sys.argv[1], sys.argv[2], [float(v) for v in sys.argv[3].split()]
far, near = list(csv.DictReader(open("far.csv"))), list(csv.DictReader(open("near.csv")))
assert len(far) == len(near) > 2 and far[0].keys() == near[0].keys()
for f, n in zip(far, near):
    for key in f:
        c = key.split(".")[-1]
        if key != "t" and c in axes:                   # a position: near + origin, in doubles
            assert float(f[key]) == float(n[key]) + origin[axes.index(c)], (key, f[key], n[key])
        else:                                          # time, displacement, velocity, stress: identical
            assert f[key] == n[key], (key, f[key], n[key])
u = [float(far[-1][point + ".u" + c]) for c in axes]
print("%d rows identical; %s moved by %s m; its position %s" % (len(far), point, u, [far[-1][point + "." + c] for c in axes]))
assert max(abs(v) for v in u) > 1e-3   # something happened to compare
def points(path):
    text = open(path).read()
    block = re.search(r'Name="Points"[^>]*>([^<]*)<', text).group(1)
    return [float(v) for v in block.split()]
pf, pn = points("far/vtk/df_blocks_00000.vtu"), points("near/vtk/df_blocks_00000.vtu")
assert len(pf) == len(pn) > 0
for i, (a, b) in enumerate(zip(pf, pn)):
    o = origin[i % 3] if i % 3 < len(origin) else 0.0
    assert a == (b + o if o else b), (i, a, b)
print("first VTK frame: %d points at the near ones plus the origin" % (len(pf) // 3))
PY
}

# slider_starts_where_put SCENARIO AXES: in far.csv, the slider's first
# position less its first displacement (the start-up relaxation's) is the
# `at` of SCENARIO, the user's coordinate, within one spacing of doubles
# there (the position is rounded once when the origin is added, the
# difference once more, each by at most half a spacing).
slider_starts_where_put() {
  /usr/bin/python3 - "$1" "$2" <<'PY' || fail "the slider does not start where $1 put it"
import csv, math, re, sys
at = re.search(r"name: slider, kind: measurement, at: \[([^]]*)\]", open(sys.argv[1]).read()).group(1)
at = [float(v) for v in at.split(",")]
first = next(csv.DictReader(open("far.csv")))
for k, c in enumerate(sys.argv[2]):
    start = float(first["slider." + c]) - float(first["slider.u" + c])
    print("slider.%s starts at %r, the scenario put it at %r (spacing %g)" % (c, start, at[k], math.ulp(at[k])))
    assert abs(start - at[k]) <= math.ulp(at[k]), (c, start, at[k])
PY
}

case_local_origin_2d() {
  # The issue's 10 m box at x, y = 1e12 (said to have "no area", then
  # refused), with a line and a trace across it: its lines and blocks are
  # about the origin 1e12 + 8 (the centre rounded to a multiple of 8,
  # coordinate_range.hpp), it is cut into four blocks and keeps its 100 m^2
  # to the last bit: its corners less the origin are exact.
  cat > box.yaml <<'YAML'
name: box
domain: {polygon: [[1e12, 1e12], [1000000000010, 1e12], [1000000000010, 1000000000010], [1e12, 1000000000010]]}
lines:
  - {from: [1e12, 1000000000005], to: [1000000000010, 1000000000005]}
traces:
  - {file: t.csv}
YAML
  # and a mapped trace (CSV) across it, from below the box to above it (clipped there).
  printf 'x1,y1,x2,y2,set\n1000000000004,999999999999,1000000000004,1000000000011,mapped\n' > t.csv
  "$DDA" dl box.yaml -o l.h5 -q && "$DDA" dc l.h5 -o b.h5 -q || fail "dl, dc of the box at 1e12"
  [ "$(origin_of l.h5)" = "1000000000008 1000000000008" ] || fail "lines origin '$(origin_of l.h5)'"
  [ "$(origin_of b.h5)" = "1000000000008 1000000000008" ] || fail "blocks origin '$(origin_of b.h5)'"
  "$DDA" stats b.h5 --json > s.json || fail "stats"
  /usr/bin/python3 -c "import json; s = json.load(open('s.json')); assert s['blocks'] == 4 and s['total_area'] == 100, s" \
    || fail "the box is not four blocks of 100 m^2 in all: $(cat s.json)"
  # Its map is drawn about the origin, the ticks labelled in the user's coordinates.
  "$DDA" plot b.h5 -o b.svg -q && grep -q 1000000000004 b.svg || fail "plot of the box at 1e12"
  # The incline at (1e12, 1e12) against the same model at its local
  # coordinates near the origin: the same cut and run, bit for bit (the
  # local geometry is the same doubles), with the far positions the near
  # ones plus the origin. The slide itself is checked against
  # g (sin 30 - cos 30 tan 20) t^2 / 2 by case df_incline_analytic.
  write_moved_incline 1e12 1e12 0 0 > far.yaml
  "$DDA" run far.yaml -o far -q || fail "run far.yaml"
  origin="$(origin_of far/results.h5)"
  [ -n "$origin" ] || fail "the far run has no local origin"
  write_moved_incline 1e12 1e12 $origin > near.yaml
  "$DDA" run near.yaml -o near -q || fail "run near.yaml"
  [ -z "$(origin_of near/results.h5)" ] || fail "the near model was moved"
  same_run_about_origin slider xy "$origin"
  slider_starts_where_put far.yaml xy
  # A DDA-for-Windows model (.geo and .ana, no domain: the origin comes
  # from all of it) moved to (5e9, 3e9): x in [5e9, 5e9 + 4] about 5e9 + 2
  # rounded to a multiple of 4, y in [3e9, 3e9 + 2] about 3e9 + 1 rounded
  # to a multiple of 2; run again at its local coordinates.
  mkdir -p geo && cd geo || fail "geo folder"
  moved_geo() {  # moved_geo OX OY: df_pushblock.geo moved by (5e9, 3e9), written about (OX, OY)
    /usr/bin/python3 - "$@" "$SRC/tests/data/df_pushblock.geo" <<'PY'
import re, sys
o = [float(sys.argv[1]), float(sys.argv[2])]
s = (5e9, 3e9)
def moved(m):
    v = m.group(2).split()
    return m.group(1) + " " + " ".join(repr((float(x) + s[i % 2]) - o[i % 2]) for i, x in enumerate(v)) + " " + m.group(3)
print(re.sub(r'(<(?:Joint type="[0-9]+"|Point)>)([^<]*)(</)', moved, open(sys.argv[3]).read()), end="")
PY
  }
  cp "$SRC/tests/data/df_pushblock.ana" . && mkdir -p far near || fail "copy the .ana"
  moved_geo 0 0 > far.geo
  "$DDA" dl far.geo -o far/l.h5 -q && "$DDA" dc far/l.h5 -o far/b.h5 -q &&
    "$DDA" df df_pushblock.ana --blocks far/b.h5 -o far/results.h5 --vtk far/vtk -q || fail "far .geo"
  origin="$(origin_of far/results.h5)"
  [ "$origin" = "5000000004 3000000002" ] || fail ".geo origin '$origin'"
  moved_geo $origin > near.geo
  "$DDA" dl near.geo -o near/l.h5 -q && "$DDA" dc near/l.h5 -o near/b.h5 -q &&
    "$DDA" df df_pushblock.ana --blocks near/b.h5 -o near/results.h5 --vtk near/vtk -q || fail "near .geo"
  same_run_about_origin measured_1 xy "$origin"
}

case_local_origin_3d() {
  # The 3D incline of tests/data/df3_incline.yaml (a block sliding on a
  # plane dipping 20 deg, the rock around it excavated by half-spaces, the
  # base held `below` a level) moved to (3e9, -2e9, 1e9), 0.5 s of it,
  # against the same model at its local coordinates near the origin: every
  # position of the scenario (box, plane, half-spaces' points, points, the
  # `below` level) moves with the model, and the run is the same to the
  # last bit. The slide itself is checked against g t^2 / 2 (sin a - cos a
  # tan phi) by case df3_incline_run_resume_history.
  moved() {  # moved SX SY SZ OX OY OZ: the fixture with every position p written as fl(fl(p + S) - O)
    /usr/bin/python3 - "$@" "$SRC/tests/data/df3_incline.yaml" <<'PY'
import re, sys
s = [float(v) for v in sys.argv[1:4]]
o = [float(v) for v in sys.argv[4:7]]
def at(p):  # a position [x, y, z]
    return "[%s]" % ", ".join(repr((float(v) + s[k]) - o[k]) for k, v in enumerate(p))
text = open(sys.argv[7]).read()
text = re.sub(r"box: \[([^]]*)\]", lambda m: "box: [%s, %s]" % (at(m.group(1).split(",")[:3])[1:-1],
                                                              at(m.group(1).split(",")[3:])[1:-1]), text)
text = re.sub(r"(point|at): \[([^]]*)\]", lambda m: m.group(1) + ": " + at(m.group(2).split(",")), text)
text = re.sub(r"below: ([0-9.]+)", lambda m: "below: %r" % ((float(m.group(1)) + s[2]) - o[2]), text)
text = text.replace("total_time: 1,", "total_time: 0.5,")
print(text)
PY
  }
  moved 3e9 -2e9 1e9 0 0 0 > far.yaml
  "$DDA" run far.yaml -o far -q || fail "run far.yaml"
  origin="$(origin_of far/results.h5)"
  # x: [3e9, 3e9 + 10] about 3e9 + 5 rounded to a multiple of 8; y likewise;
  # z: [1e9, 1e9 + 6] about 1e9 + 3 rounded to a multiple of 4.
  [ "$origin" = "3000000008 -1999999992 1000000004" ] || fail "origin '$origin'"
  [ "$(origin_of far/blocks3d.h5)" = "$origin" ] || fail "blocks3d origin '$(origin_of far/blocks3d.h5)'"
  moved 3e9 -2e9 1e9 $origin > near.yaml
  "$DDA" run near.yaml -o near -q || fail "run near.yaml"
  [ -z "$(origin_of near/results.h5)" ] || fail "the near model was moved"
  same_run_about_origin slider xyz "$origin"
  slider_starts_where_put far.yaml xyz
}

# The incline's slider moved less than 1e-4 m from t = 0 to 1 s or later
# (HISTORY: `dda history --csv --point slider`).
slider_stayed() {
  /usr/bin/python3 - "$1" <<'PY' || fail "the slider moved"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
first, last = rows[0], rows[-1]
moved = math.hypot(float(last["slider.ux"]) - float(first["slider.ux"]), float(last["slider.uy"]) - float(first["slider.uy"]))
print("slider moved %.3e m between t = %s and %s s" % (moved, first["t"], last["t"]))
assert float(first["t"]) == 0 and float(last["t"]) >= 1 - 1e-9 and moved < 1e-4, moved
PY
}

case_df_incline_analytic() {
  write_incline
  "$DDA" run incline.yaml -o out -q || fail "run"
  for f in results.h5 vtk/df.pvd vtk/df_blocks_00000.vtu vtk/df_contacts_00004.vtu; do
    [ -s "out/$f" ] || fail "out/$f missing"
  done
  [ "$(grep -c '<DataSet' out/vtk/df.pvd)" -eq 10 ] || fail "expected 5 frames x (blocks, contacts) in df.pvd"
  "$DDA" history out/results.h5 --csv --point slider > h.csv || fail "history"
  /usr/bin/python3 - <<'PY' || fail "displacement at t = 1 s is not within 2 % of g(sin30 - cos30 tan20)/2"
import csv, math
rows = list(csv.DictReader(open("h.csv")))
last = rows[-1]
assert abs(float(last["t"]) - 1.0) < 1e-9, last["t"]
s = math.hypot(float(last["slider.ux"]), float(last["slider.uy"]))
a = math.radians(30)
expected = 9.81 * (math.sin(a) - math.cos(a) * math.tan(math.radians(20))) / 2
print("s(1 s) = %.6f m, expected %.6f m, error %.3f %%" % (s, expected, 100 * abs(s - expected) / expected))
assert abs(s - expected) <= 0.02 * expected
PY
  ls -a out | grep -q '\.tmp' && fail "temporary files left behind"
  true
}

# Joint water: the incline's slider (phi 20) under a water table at
# z = 3.65, 0.4 m above the middle of its base (z 3 .. 3.5), through
# `dda run`. The water pushes it off the slab with U = gamma_w L d and grows
# as it slides down (its base drops by s sin 30): from rest
# s(t) = a0 / k (cosh(sqrt(k) t) - 1), a0 = g sin a - (g cos a - U0 / m) tan phi,
# k = gamma_w L sin a tan phi / m (tests/df/test_water.cpp). Within 2 %, as
# the dry case. Resumed, the run repeats itself; its energy balances. A bad
# water section is one sentence naming file, line, key.
case_df_water_incline() {
  write_incline
  printf 'water: {level: 3.65}\n' >> incline.yaml
  "$DDA" run incline.yaml -o out -q --no-vtk --no-plots || fail "run"
  "$DDA" history out/results.h5 --csv --point slider > h.csv || fail "history"
  /usr/bin/python3 - <<'PY' || fail "the slide under water is not within 2 % of the effective-stress balance"
import csv, math
last = list(csv.DictReader(open("h.csv")))[-1]
s = math.hypot(float(last["slider.ux"]), float(last["slider.uy"]))
a, mu, m, gw = math.radians(30), math.tan(math.radians(20)), 2000.0, 9810.0
a0 = 9.81 * math.sin(a) - (9.81 * math.cos(a) - gw * 0.4 / m) * mu
k = gw * math.sin(a) * mu / m
expected = a0 / k * (math.cosh(math.sqrt(k) * float(last["t"])) - 1)
print("s(1 s) = %.6f m under water, expected %.6f m, error %.3f %%" % (s, expected, 100 * abs(s - expected) / expected))
assert abs(s - expected) <= 0.02 * expected
PY
  # The water's loads come from the geometry alone: a resumed run repeats the
  # uninterrupted one, and their work is in the energy ledger (no warning of
  # energy created from nothing).
  "$DDA" df incline.yaml --blocks out/blocks.h5 -o part.h5 --stop-at-step 300 -q || fail "df --stop-at-step"
  "$DDA" df --resume part.h5 -q || fail "resume"
  "$DDA" history out/results.h5 --csv > a.csv && "$DDA" history part.h5 --csv > b.csv || fail "history"
  cmp -s a.csv b.csv || fail "the resumed run under water differs from the uninterrupted one"
  "$DDA" info out/results.h5 | grep -q "created energy" && fail "dda info warns of created energy under water"
  sed 's/water: {level: 3.65}/water: {level: 3.65, unit_weight: -9810}/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: water.unit_weight must be > 0, got -9810\.$" -- "$DDA" df s.yaml --blocks out/blocks.h5 -o r.h5
  sed 's/  interface: {friction_deg: 20}/  interface: {friction_deg: 20, saturation: 2}/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: joints.interface.saturation must be in \[0, 1\], got 2\.$" -- \
    "$DDA" df s.yaml --blocks out/blocks.h5 -o r.h5
  sed 's/water: {level: 3.65}/water: 3.65/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: water must be a mapping" -- "$DDA" run s.yaml -o out2 -q
  [ ! -e r.h5 ] || fail "a results file was written despite the errors"
  true
}

case_df_resume_reproduces() {
  write_incline
  "$DDA" run incline.yaml -o out -q --no-vtk || fail "run"
  "$DDA" df incline.yaml --blocks out/blocks.h5 -o part.h5 --stop-at-step 300 -q || fail "df --stop-at-step"
  json=$("$DDA" history part.h5 --csv | wc -l)
  [ "$json" -eq 302 ] || fail "a run stopped at step 300 should hold 301 samples, got $((json - 1))"
  "$DDA" info part.h5 | grep -q "300 steps .* incomplete" || fail "dda info on a stopped run: $("$DDA" info part.h5)"
  "$DDA" df --resume part.h5 -q || fail "resume"
  "$DDA" history out/results.h5 --csv > a.csv && "$DDA" history part.h5 --csv > b.csv || fail "history"
  cmp -s a.csv b.csv || fail "the resumed run differs from the uninterrupted one"
  "$DDA" history out/results.h5 --steps > a.csv && "$DDA" history part.h5 --steps > b.csv || fail "history --steps"
  cmp -s a.csv b.csv || fail "the resumed run's step statistics differ"
  "$DDA" df --resume part.h5 | grep -q "already complete" || fail "resuming a complete run"
  "$DDA" info out/results.h5 | grep -q "dda-results (scenario), 2 blocks, .* complete" || fail "dda info on a results file: $("$DDA" info out/results.h5)"
  # The energy balance: a sound run's line, and the warning for a run that
  # created energy (its residual made -50 J at record 100, t = 0.1 s, where
  # the run had moved 89 J).
  "$DDA" info out/results.h5 | grep -q "^energy: .*at t = 1 s, work done .* residual" || fail "dda info: no energy line"
  "$DDA" info out/results.h5 | grep -q "created energy" && fail "dda info warns of created energy on a sound run"
  cp out/results.h5 poked.h5
  /usr/bin/python3 -c "import h5py; f = h5py.File('poked.h5', 'r+'); f['energy/residual'][100] = -50.0" || fail "h5py"
  "$DDA" info poked.h5 | grep -q "^warning: .*the run created energy: at t = 0.1 s its energy residual was -50 J" ||
    fail "dda info shows no warning for created energy: $("$DDA" info poked.h5)"
}

# check_progress_lines FILE time|steps TOTAL: the lines `dda df` prints on
# a non-terminal (here a file) are each
#   DF: P %  step N[/STEPS]  t = T[/TOTAL] s  dt = DT s  S solves/step  E elapsed  ETA L
# (or "step N under way for E" in place of the solves when no step ended
# since the last line), with steps and times that only grow, a step no
# longer than the scenario's dt (1e-4 s), at least one solve a step, and
# the percentage of t / TOTAL or N / STEPS.
check_progress_lines() {
  /usr/bin/python3 - "$@" <<'PY'
import re, sys
lines = [l.rstrip("\n") for l in open(sys.argv[1]) if l.startswith("DF: ") and "%" in l]
assert len(lines) >= 2, "fewer than two progress lines: %r" % lines
by_steps, total = sys.argv[2] == "steps", sys.argv[3]
of_steps, of_time = ("/" + total, "") if by_steps else ("", "/" + total)
dur = r"(?:\d+h\d\dm|\d+m\d\ds|\d+s)"
pat = re.compile(r"DF: (\d+) %%  step (\d+)%s  t = ([0-9.e+-]+)%s s  dt = ([0-9.e+-]+) s  "
                 r"(?:(\d+\.\d) solves/step|step (\d+)%s under way for %s)  %s elapsed  ETA (?:%s|\?)$"
                 % (of_steps, of_time, of_steps, dur, dur, dur))
last_step, last_t, paced = -1, -1.0, 0
for l in lines:
    m = pat.match(l)
    assert m, "progress line %r does not match %s" % (l, pat.pattern)
    pct, step, t, dt, solves, running = m.groups()
    step, t, dt = int(step), float(t), float(dt)
    assert step >= last_step and t >= last_t, "steps or times go back: %r" % l
    done = step / float(total) if by_steps else t / float(total)
    assert abs(int(pct) - 100 * done) <= 1, "percentage %s for %r" % (pct, l)
    if step > 0: assert 0 < dt <= 1e-4 * (1 + 1e-9), "dt %g in %r" % (dt, l)
    if solves is not None:
        assert float(solves) >= 1, "fewer than one solve a step: %r" % l
        paced += 1
    else:
        assert int(running) == step + 1, l
    last_step, last_t = step, t
assert paced >= 1, "no line reports solves per step: %r" % lines
print("%d progress lines, the last: %s" % (len(lines), lines[-1]))
PY
}

case_df_progress_lines() {
  incline_blocks
  # 10 000 steps of 0.1 ms, output going to files (not a terminal): with
  # DDA_PROGRESS_SECONDS=0.01 a progress line every 0.02 s on stderr.
  sed 's/dt: 0.001,/dt: 0.0001,/' incline.yaml > fine.yaml
  DDA_PROGRESS_SECONDS=0.01 OMP_NUM_THREADS=2 "$DDA" df fine.yaml --blocks blocks.h5 -o r.h5 > out.txt 2> err.txt ||
    fail "df: $(cat err.txt)"
  # The run says its threads first: 2 blocks run on one thread, whatever OMP_NUM_THREADS says.
  [ "$(head -1 out.txt)" = "DF: 2 blocks on 1 thread" ] || fail "first line '$(head -1 out.txt)'"
  grep -qE "^DF: [0-9]+ steps to t = 1 s" out.txt || fail "no closing line: $(cat out.txt)"
  check_progress_lines err.txt time 1 || fail "progress lines: $(cat err.txt)"
  # A run to a step count says it as step N/STEPS.
  sed 's/dt: 0.001, total_time: 1.0, output_interval: 0.25/dt: 0.0001, steps: 10000/' incline.yaml > steps.yaml
  DDA_PROGRESS_SECONDS=0.01 "$DDA" df steps.yaml --blocks blocks.h5 -o s.h5 2> err.txt > /dev/null || fail "df steps"
  check_progress_lines err.txt steps 10000 || fail "progress lines of a run by steps: $(cat err.txt)"
  # -q: nothing but errors, progress included.
  DDA_PROGRESS_SECONDS=0.01 "$DDA" df fine.yaml --blocks blocks.h5 -o q.h5 -q > out.txt 2> err.txt || fail "df -q"
  [ ! -s out.txt ] && [ ! -s err.txt ] || fail "-q printed: $(cat out.txt err.txt)"
  # 3D: the same lines, the same one thread for two blocks.
  sed 's/dt: 0.001,/dt: 0.0001,/' "$SRC/tests/data/df3_incline.yaml" > fine3.yaml
  "$DDA" dl fine3.yaml -o fractures.h5 -q && "$DDA" dc fractures.h5 -o blocks3d.h5 -q || fail "dl, dc 3D"
  DDA_PROGRESS_SECONDS=0.01 OMP_NUM_THREADS=2 "$DDA" df fine3.yaml --blocks blocks3d.h5 -o r3.h5 > out.txt 2> err.txt ||
    fail "df 3D: $(cat err.txt)"
  [ "$(head -1 out.txt)" = "DF: 2 blocks on 1 thread" ] || fail "3D first line '$(head -1 out.txt)'"
  check_progress_lines err.txt time 1 || fail "3D progress lines: $(cat err.txt)"
}

case_df_start_lines() {
  # What the run says before its first step, checked by hand: the incline's
  # E is 50 GPa and the default penalty 50 E, so pn = ps = 2.5e12 N/m; a
  # dynamic parameter of 0.99 caps a free fall at g dt / (1 - 0.99) =
  # 9.81 * 0.001 / 0.01 = 0.981 m/s; the slab and slider start relaxed.
  incline_blocks
  sed 's/dt: 0.001, total_time: 1.0/dt: 0.001, dynamic: 0.99, total_time: 0.01/' incline.yaml > s.yaml
  "$DDA" df s.yaml --blocks blocks.h5 -o r.h5 > out.txt 2> err.txt || fail "df: $(cat err.txt)"
  grep -q "^DF: contact springs pn 2.5e+12 N/m, ps 2.5e+12 N/m (per m of thickness); dt 0.001 s; up to 6 open-close iterations a step, contact clusters on$" out.txt \
    || fail "no contact-springs line: $(cat out.txt)"
  grep -q "caps a free fall at g dt / (1 - dynamic) = 0.981 m/s at dt 0.001 s" out.txt || fail "no dynamic note: $(cat out.txt)"
  grep -qE "^DF: initial equilibrium: [0-9]+ static solves with the contacts stuck" out.txt || fail "no start-up line: $(cat out.txt)"
  # A long relaxation says it is getting somewhere, every progress interval
  # (here every solve), on stderr; -q silences it.
  DDA_PROGRESS_SECONDS=1e-9 "$DDA" df s.yaml --blocks blocks.h5 -o p.h5 > out.txt 2> err.txt || fail "df: $(cat err.txt)"
  grep -qE "^DF: relaxing: 1 static solves with the contacts stuck so far, the last moved a vertex [0-9.e+-]+ m$" err.txt \
    || fail "no relaxation progress line: $(cat err.txt)"
  DDA_PROGRESS_SECONDS=1e-9 "$DDA" df s.yaml --blocks blocks.h5 -o q.h5 -q > out.txt 2> err.txt || fail "df -q"
  [ ! -s out.txt ] && [ ! -s err.txt ] || fail "-q printed: $(cat out.txt err.txt)"
  # Loads switched on at t = 0: no relaxation to report; dynamic 1: no note.
  sed 's/dt: 0.001, total_time: 1.0/dt: 0.001, initial_equilibrium: false, total_time: 0.01/' incline.yaml > f.yaml
  "$DDA" df f.yaml --blocks blocks.h5 -o f.h5 > out.txt 2> err.txt || fail "df f.yaml: $(cat err.txt)"
  ! grep -q "initial equilibrium\|dynamic" out.txt || fail "f.yaml said: $(cat out.txt)"
}

case_df_damping() {
  # control.damping: the run states what it gives, checked by hand: 5 % of
  # critical at 4 Hz is beta = 0.05 / (pi 4) = 0.00397887 s, and
  # stiffness-proportional damping gives 2.5 % at 2 Hz and 10 % at 8 Hz.
  incline_blocks
  sed 's/dt: 0.001, total_time: 1.0/dt: 0.001, damping: {ratio: 0.05, frequency: 4}, total_time: 0.01/' \
    incline.yaml > s.yaml
  "$DDA" df s.yaml --blocks blocks.h5 -o r.h5 > out.txt 2> err.txt || fail "df: $(cat err.txt)"
  grep -q "^DF: viscous damping 5 % of critical at 4 Hz on the blocks' deformation (beta = 0.00397887 s; 2.5 % at 2 Hz, 10 % at 8 Hz); rigid motion and the contact springs are not damped$" out.txt \
    || fail "no damping line: $(cat out.txt)"
  # Without it, nothing is said.
  sed 's/dt: 0.001, total_time: 1.0/dt: 0.001, total_time: 0.01/' incline.yaml > n.yaml
  "$DDA" df n.yaml --blocks blocks.h5 -o n.h5 > out.txt 2> err.txt || fail "df n.yaml: $(cat err.txt)"
  ! grep -q "viscous damping" out.txt || fail "n.yaml said: $(cat out.txt)"
  # Bad input: a ratio in per cent, a missing frequency, an unknown key.
  sed 's/damping: {ratio: 0.05,/damping: {ratio: 5,/' s.yaml > b1.yaml
  expect_error 1 "b1.yaml:[0-9]+: control.damping.ratio must be in \[0, 1\), got 5\.$" -- \
    "$DDA" df b1.yaml --blocks blocks.h5 -o b.h5
  sed 's/damping: {ratio: 0.05, frequency: 4}/damping: {ratio: 0.05}/' s.yaml > b2.yaml
  expect_error 1 "b2.yaml:[0-9]+: required key 'control.damping.frequency' is missing\\.$" -- "$DDA" df b2.yaml --blocks blocks.h5 -o b.h5
  sed 's/frequency: 4}/frequency: 4, mass: 0.1}/' s.yaml > b3.yaml
  expect_error 1 "b3.yaml:[0-9]+: unknown key 'control.damping.mass'; allowed keys here are ratio, frequency\\.$" -- "$DDA" df b3.yaml --blocks blocks.h5 -o b.h5
  # 3D reads the same key and says the same line.
  sed 's/control: {dt: 0.001, total_time: 1,/control: {dt: 0.001, total_time: 0.01, damping: {ratio: 0.05, frequency: 4},/' \
    "$SRC/tests/data/df3_incline.yaml" > s3.yaml
  grep -q "damping:" s3.yaml || fail "the 3D scenario edit did not apply"
  "$DDA" run s3.yaml -o out3 --no-vtk --no-plots > out.txt 2> err.txt || fail "run 3D: $(cat err.txt)"
  grep -q "^DF: viscous damping 5 % of critical at 4 Hz" out.txt || fail "no 3D damping line: $(cat out.txt)"
}

case_df_default_dt() {
  # control.dt not given: the P-wave crossing time of the median block,
  # worked by hand. 2D incline: slider 1 x 1 m and slab of 8 m^2, the lower
  # median of two is the slider; E 50 GPa, nu 0.25, rho 2000, plane stress:
  # c = sqrt(E / (1 - nu^2) / rho) = 5164 m/s, dt = 1 / 5164 = 0.000193649 s.
  incline_blocks
  sed 's/dt: 0.001, total_time: 1.0/total_time: 0.01/' incline.yaml > s.yaml
  "$DDA" df s.yaml --blocks blocks.h5 -o r.h5 > out.txt 2> err.txt || fail "df: $(cat err.txt)"
  grep -q "^DF: dt 0.000193649 s from the model (control.dt not given): a P wave (5.16e+03 m/s) crosses the median block (1 m) in 0.000194 s$" out.txt \
    || fail "no 2D dt line: $(cat out.txt)"
  # Given, nothing is said about it.
  "$DDA" df incline.yaml --blocks blocks.h5 -o g.h5 --stop-at-step 1 > out.txt 2> err.txt || fail "df given: $(cat err.txt)"
  ! grep -q "from the model" out.txt || fail "a given dt was explained: $(cat out.txt)"
  # The soft slider at friction 0.1 degree above its slope (as
  # df_friction_limit) with no control tuning at all, the step included,
  # stays: under 1e-4 m in 1 s (E 1 GPa: c = 730.30 m/s, dt = 1 / 730.30 = 0.00136931 s).
  sed -e 's/interface: {friction_deg: 20}/interface: {friction_deg: 30.1}/' -e 's/young: 5.0e10/young: 1.0e9/' \
    -e 's/dt: 0.001, total_time: 1.0/total_time: 1.0/' incline.yaml > soft.yaml
  "$DDA" run soft.yaml -o soft --no-vtk --no-plots > out.txt 2> err.txt || fail "run soft: $(cat err.txt)"
  grep -q "^DF: dt 0.00136931 s from the model" out.txt || fail "soft dt: $(cat out.txt)"
  "$DDA" history soft/results.h5 --csv --point slider > h.csv || fail "history"
  slider_stayed h.csv
  # 3D incline: the slider is 27 m^3 (3 m), E 10 GPa, nu 0.25, rho 2600:
  # c = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu)) / rho) = 2148.3 m/s, dt = 3 / 2148.3 = 0.00139642 s.
  sed 's/control: {dt: 0.001, total_time: 1,/control: {total_time: 0.01,/' "$SRC/tests/data/df3_incline.yaml" > s3.yaml
  "$DDA" run s3.yaml -o out3 --no-vtk --no-plots > out.txt 2> err.txt || fail "run 3D: $(cat err.txt)"
  grep -q "^DF: dt 0.00139642 s from the model (control.dt not given): a P wave (2.15e+03 m/s) crosses the median block (3 m) in 0.0014 s$" out.txt \
    || fail "no 3D dt line: $(cat out.txt)"
}

case_df_friction_limit() {
  # The incline's slider, of soft rock (E 1 GPa, the scenario default),
  # with friction 0.1 degree above its 30-degree slope (factor of safety
  # 1.005) and no control tuning: the default start-up relaxation hands it
  # over in frictional equilibrium and it stays, moving less than 1e-4 m in
  # 1 s (a rigid block at rest does not move at all; measured 3.5e-11 m).
  # With the loads switched on at t = 0 the same slider slid 2.8e-4 m.
  write_incline
  sed -e 's/interface: {friction_deg: 20}/interface: {friction_deg: 30.1}/' -e 's/young: 5.0e10/young: 1.0e9/' \
    incline.yaml > s.yaml
  grep -q "young: 1.0e9" s.yaml || fail "the scenario edit did not apply"
  "$DDA" run s.yaml -o out -q --no-vtk --no-plots || fail "run"
  "$DDA" history out/results.h5 --csv --point slider > h.csv || fail "history"
  slider_stayed h.csv
}

case_df_history_columns() {
  write_incline
  "$DDA" run incline.yaml -o out -q --no-vtk || fail "run"
  "$DDA" history out/results.h5 --csv > all.csv || fail "history"
  expected="t"
  for p in slider slab; do for c in x y ux uy vx vy sxx syy sxy; do expected="$expected,$p.$c"; done; done
  [ "$(head -1 all.csv)" = "$expected" ] || fail "header '$(head -1 all.csv)', expected '$expected'"
  "$DDA" history out/results.h5 --csv --point slab > one.csv || fail "history --point"
  [ "$(head -1 one.csv)" = "t,slab.x,slab.y,slab.ux,slab.uy,slab.vx,slab.vy,slab.sxx,slab.syy,slab.sxy" ] \
    || fail "--point header '$(head -1 one.csv)'"
  [ "$(wc -l < one.csv)" -eq "$(wc -l < all.csv)" ] || fail "--point changed the row count"
  # The first sample is the start, t = 0, after the start-up relaxation: the
  # fixed slab has only sunk into its fixed-point springs (nanometres;
  # displacements count from the blocks as cut).
  /usr/bin/python3 -c "import csv; r=next(csv.DictReader(open('one.csv'))); assert float(r['t'])==0 and abs(float(r['slab.ux']))<1e-6" \
    || fail "first row is not the initial state"
  "$DDA" history --help | grep -q "NAME.sxy" || fail "--help does not document the columns"
  expect_error 1 "out/results.h5: has no measurement point 'nope' \(its points are slider, slab\)" -- \
    "$DDA" history out/results.h5 --csv --point nope
  expect_error 1 "out/blocks.h5: is a dda-blocks file, expected a dda-results file" -- "$DDA" history out/blocks.h5 --csv
}

case_df_bad_inputs() {
  write_incline
  "$DDA" run incline.yaml -o out -q --no-vtk || fail "run"
  B=out/blocks.h5
  sed 's/density: 2000/density: -5/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: materials.default.density must be > 0, got -5\.$" -- "$DDA" df s.yaml --blocks $B -o r.h5
  sed 's/dt: 0.001/dt: 0/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: control.dt must be > 0, got 0\.$" -- "$DDA" df s.yaml --blocks $B -o r.h5
  sed 's/  interface: {friction_deg: 20}/  interface: {friction_deg: 20}\n  J7: {friction_deg: 10}/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: joints.J7 names a joint set that out/blocks.h5 does not have \(its sets are interface\)" -- \
    "$DDA" df s.yaml --blocks $B -o r.h5
  sed 's/  interface: {friction_deg: 20}/  interface: {}/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: joints.interface gives no joint properties" -- "$DDA" df s.yaml --blocks $B -o r.h5
  printf 'bolts:\n  - {name: b1, from: [1, 0.2], to: [50, 50], stiffness: 1e8}\n' >> incline.yaml
  expect_error 1 "incline.yaml:[0-9]+: bolts\[0\].to lies outside every block" -- "$DDA" df incline.yaml --blocks $B -o r.h5
  printf 'domain: {box: [0, 0, 4, 4]}\nexcavations:\n  - {shape: rectangle, center: [2, 2], width: 4, height: 4}\ncontrol: {dt: 0.001, steps: 10}\n' > e.yaml
  expect_error 1 "out2/blocks.h5: has no blocks" -- "$DDA" run e.yaml -o out2 --no-vtk --no-plots
  printf 'domain: {box: [0, 0, 4, 4]}\nmaterials: {default: {density: 2000}}\n' > nc.yaml
  expect_error 1 "nc.yaml:1: control is required for a forward run" -- "$DDA" run nc.yaml -o out3
  [ ! -e out3/lines.h5 ] || fail "DL ran although the DF sections were wrong"
  [ ! -e r.h5 ] || fail "a results file was written despite the errors"
  expect_error 1 "dda df needs --blocks" -- "$DDA" df incline.yaml -o r.h5
}

# Friction laws with memory: a run stopped and resumed repeats the whole run
# (rate and state on the sliding interface, degradation by load cycles
# elsewhere), and a bad law parameter is one sentence naming file, line and key.
case_df_resume_friction_laws() {
  write_incline
  sed -e 's/  interface: {friction_deg: 20}/  interface: {friction_law: {name: rate_state, mu0: 0.36, a: 0.01, b: 0.015, dc: 1.0e-3, v0: 0.1}}/' \
      -e 's/  default: {friction_deg: 45}/  default: {friction_law: {name: degradation, phi_peak: 45, phi_residual: 40, measure: cycles, nc: 3}}/' \
      incline.yaml > rs.yaml
  grep -q rate_state rs.yaml || fail "sed did not put the law in"
  "$DDA" run rs.yaml -o out -q --no-vtk || fail "run"
  "$DDA" df rs.yaml --blocks out/blocks.h5 -o part.h5 --stop-at-step 300 -q || fail "df --stop-at-step"
  "$DDA" df --resume part.h5 -q || fail "resume"
  "$DDA" history out/results.h5 --csv > a.csv && "$DDA" history part.h5 --csv > b.csv || fail "history"
  cmp -s a.csv b.csv || fail "the resumed run differs from the uninterrupted one"
  /usr/bin/python3 -c "import csv; r=list(csv.DictReader(open('a.csv')))[-1]; assert abs(float(r['slider.ux'])) > 0.01" \
    || fail "the slider did not slide"
  sed 's/dc: 1.0e-3/dc: -1.0e-3/' rs.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: joints.interface.friction_law.dc must be > 0, got -0.001\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
  sed 's/v0: 0.1}/v0: 0.1, evolution: healing}/' rs.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: joints.interface.friction_law.evolution must be one of aging, slip, got 'healing'\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
}

# Oden-Martins normal compliance on the sliding interface (joints.<set>.normal_law):
# friction acts on top of it, so the slider still slides 1/2 g (sin 30 -
# cos 30 tan 20) t^2 = 0.9064 m down the 30 degree incline in 1 s
# (hand-computed); a bad law number or name is one sentence naming the
# file, line and key, and nothing is written.
case_df_normal_law() {
  write_incline
  sed 's/  interface: {friction_deg: 20}/  interface: {friction_deg: 20, normal_law: {name: oden_martins, c_n: 1.0e13, m_n: 1.5}}/' \
      incline.yaml > om.yaml
  grep -q oden_martins om.yaml || fail "sed did not put the law in"
  "$DDA" run om.yaml -o out -q --no-vtk || fail "run"
  "$DDA" history out/results.h5 --csv --point slider > h.csv || fail "history"
  /usr/bin/python3 -c "
import csv, math
r = list(csv.DictReader(open('h.csv')))[-1]
s = math.hypot(float(r['slider.ux']), float(r['slider.uy']))
assert abs(s - 0.9064) < 0.02 * 0.9064, s" || fail "the slider did not slide as friction on top of the normal law says"
  sed 's/m_n: 1.5/m_n: 0.5/' om.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: joints.interface.normal_law.m_n must be in \[1, 10\], got 0.5\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
  sed 's/name: oden_martins/name: hertz/' om.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: joints.interface.normal_law.name must be a known normal law \(penalty, oden_martins\), got 'hertz'\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
  [ ! -e r.h5 ] || fail "a results file was written despite the errors"
}

# Normal laws and per-set penalties in 3D: the 3 x 3 x 3 m slider of
# df3_incline.yaml on a level base (the plane at dip 0), W = 2600 * 9.81 *
# 27 = 688,662 N on its four bottom corners, W / 4 = 172,165.5 N each. On
# an Oden-Martins joint (c_n = 1e11, m_n = 2) the relaxed slider has sunk
# g = sqrt(172165.5 / 1e11) = 1.31212e-3 m; on a set's own penalty (1e9
# N/m) W / (4 pn) = 1.72166e-4 m (the run's default, E times the cube root
# of the volume, is 3e12 N/m: 5.7e-8 m).
# E = 1e12 Pa keeps the slider's own shortening between its base and its
# centre (about 6e-8 m) below 1e-3 of either. A bad m_n names file, line
# and key, and nothing is written.
case_df3_normal_law() {
  sed -e 's/dip: 20, dip_direction: 90/dip: 0, dip_direction: 90/' \
      -e 's/-0.3420201433256687, 0, -0.9396926207859084/0, 0, -1/g' \
      -e 's/young: 1.0e10/young: 1.0e12/' \
      -e 's/  slide: {friction_deg: 10}/  slide: {friction_deg: 30, normal_law: {name: oden_martins, c_n: 1.0e11, m_n: 2}}/' \
      -e 's/total_time: 1, output_interval: 0.25/total_time: 0.05, output_interval: 0.05/' \
      -e 's/initial_equilibrium: false/initial_equilibrium: true/' -e 's/vtk: true/vtk: false/' \
      "$SRC/tests/data/df3_incline.yaml" > om.yaml || fail "write the scenario"
  grep -q "oden_martins" om.yaml && grep -q "dip: 0," om.yaml && grep -q "initial_equilibrium: true" om.yaml \
    || fail "sed did not make the level Oden-Martins scenario"
  sed 's/normal_law: {name: oden_martins, c_n: 1.0e11, m_n: 2}/normal_penalty: 1.0e9/' om.yaml > pn.yaml
  "$DDA" run om.yaml -o out -q || fail "run on the Oden-Martins joint"
  "$DDA" df pn.yaml --blocks out/blocks3d.h5 -o pn.h5 -q || fail "run on the set's penalty"
  "$DDA" history out/results.h5 --csv --point slider > om.csv || fail "history"
  "$DDA" history pn.h5 --csv --point slider > pn.csv || fail "history of the penalty run"
  /usr/bin/python3 - <<'PY' || fail "the slider did not sink as the joint's normal law says"
import csv, math
for name, expected in (("om.csv", math.sqrt(172165.5 / 1e11)), ("pn.csv", 172165.5 / 1e9)):
    rows = list(csv.DictReader(open(name)))
    for r in (rows[0], rows[-1]):  # relaxed, and at rest 0.05 s later
        sink = -float(r["slider.uz"])
        print("%s t = %s: sink %.6e m, expected %.6e m" % (name, r["t"], sink, expected))
        assert abs(sink - expected) < 1e-3 * expected, (name, r["t"], sink)
PY
  sed 's/m_n: 2}/m_n: 0.5}/' om.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: joints.slide.normal_law.m_n must be in \[1, 10\], got 0.5\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks3d.h5 -o r.h5
  [ ! -e r.h5 ] || fail "a results file was written despite the error"
}

# An incident wave through a viscous base (boundaries.viscous, earthquake mode
# incident): a column of ten bonded 10 x 5 m beds shaken vertically (a P
# wave; a free-standing column rocks under horizontal shaking) by a Hann
# velocity pulse of outcrop amplitude 0.02 m/s (v_g = 0.02 sin^2(pi t /
# 0.1), a_g its derivative). Half of it enters as the incident wave; the free
# top doubles it back to the outcrop amplitude, 0.02 m/s (within 5 %). Bad
# entries: the incident mode without a viscous side to enter through.
case_df_incident_wave() {
  /usr/bin/python3 - > column.yaml <<'PY'
print("name: column\nseed: 1\ndomain: {box: [0, 0, 10, 50]}\nlines:")
for y in range(5, 50, 5): print("  - {set: bed, from: [0, %d], to: [10, %d]}" % (y, y))
print("""points:
  - {name: top, kind: measurement, at: [5, 47.5]}
materials:
  default: {density: 2000, young: 1.0e9, poisson: 0.25, plane: strain}
joints:
  default: {friction_deg: 45}
  bed: {friction_deg: 45, cohesion: 1.0e9, tensile_strength: 1.0e9, normal_penalty: 1.0e12}
boundaries:
  viscous: [bottom]
loading:
  gravity: [0, 0]
  earthquake: {record: pulse.csv, units: m/s2, direction: [0, 1], mode: incident, baseline: 0}
control: {dt: 0.0005, total_time: 0.25, output_interval: 0.05}
output: {vtk: false, plots: false}""")
PY
  /usr/bin/python3 - > pulse.csv <<'PY'
import math
print("t,ax")
for k in range(201):
    t = 0.1 * k / 200
    print("%.6f,%.9f" % (t, 0.02 * math.pi / 0.1 * math.sin(2 * math.pi * t / 0.1)))
PY
  "$DDA" run column.yaml -o out -q --no-vtk || fail "run"
  "$DDA" history out/results.h5 --csv --point top > h.csv || fail "history"
  /usr/bin/python3 - <<'PY' || fail "the top's peak velocity is not the outcrop amplitude 0.02 m/s within 5 %"
import csv
rows = list(csv.DictReader(open("h.csv")))
peak = max(abs(float(r["top.vy"])) for r in rows)
print("peak top velocity %.5f m/s (outcrop 0.02)" % peak)
assert abs(peak - 0.02) <= 0.05 * 0.02
PY
  sed 's/  viscous: \[bottom\]/  viscous: [left]/' column.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: loading.earthquake.mode incident needs a viscous boundary: the incident wave enters through side bottom, which boundaries.viscous does not list \(add it there\)\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
  sed 's/  viscous: \[bottom\]/  viscous: [bottom]\n  free_field: [top]/' column.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: boundaries.free_field.*must be left or right \(free-field boundaries stand on the lateral sides\), got 'top'\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
  sed 's/  viscous: \[bottom\]/  viscous: [bottom, left]\n  free_field: [left]/' column.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: boundaries.free_field.*is also in boundaries.viscous" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
  sed 's/  viscous: \[bottom\]/  viscous: [bottom, middle]/' column.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: boundaries.viscous.*must be bottom, top, left or right, got 'middle'\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
  # Free-field sides without an incident wave (as 3D refuses them).
  sed -e 's/  viscous: \[bottom\]/  viscous: [bottom]\n  free_field: [left]/' -e 's/mode: incident, //' column.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: boundaries.free_field needs an incident wave \(loading.earthquake with mode: incident\): the free field is the motion that wave gives the rock\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks.h5 -o r.h5
}

case_df_ana_import() {
  "$DDA" dl "$SRC/tests/data/df_pushblock.geo" -o lines.h5 -q || fail "dl of the .geo"
  "$DDA" dc lines.h5 -o blocks.h5 -q || fail "dc"
  "$DDA" df "$SRC/tests/data/df_pushblock.ana" --blocks blocks.h5 -o r.h5 -q || fail "df of the .ana"
  "$DDA" history r.h5 --csv > h.csv || fail "history"
  /usr/bin/python3 - <<'PY' || fail "pushed block: displacement at 0.5 s is not within 1 % of (F/m - g tan20) t^2 / 2"
import csv, math
last = list(csv.DictReader(open("h.csv")))[-1]
s = float(last["measured_1.ux"])
expected = 0.5 * (15000 / 2000 - 9.81 * math.tan(math.radians(20))) * 0.5 ** 2
print("s(0.5 s) = %.6f m, expected %.6f m" % (s, expected))
assert abs(float(last["t"]) - 0.5) < 1e-9 and abs(s - expected) <= 0.01 * expected
PY
  sed 's/<Maxtimestep maxtimestep="0.001"\/>/<Maxtimestep maxtimestep="0"\/>/' "$SRC/tests/data/df_pushblock.ana" > bad.ana
  expect_error 1 "bad.ana:[0-9]+: <Maxtimestep> needs maxtimestep > 0, got 0\.$" -- "$DDA" df bad.ana --blocks blocks.h5 -o x.h5
}

# 3D: a small scenario (tests/data/s3d_small.yaml), copied with the CSV
# polygons it reads (paths in a scenario are relative to it).
copy_s3d() { cp "$SRC/tests/data/s3d_small.yaml" "$SRC/tests/data/dl3_polygons.csv" . || fail "copy the 3D fixture"; }

case_dl3_fractures_and_report() {
  copy_s3d
  "$DDA" dl s3d_small.yaml -o fr.h5 --vtk fr.vtu --report r.json > out.txt || fail "dl of a 3D scenario"
  for f in fr.h5 fr.vtu r.json fr.mid.lines.h5 fr.mid.lines.vtu; do [ -s "$f" ] || fail "$f missing"; done
  grep -q "DL report, 3D (seed 11)" out.txt || fail "no 3D report printed"
  grep -qE "^[0-9]+ fractures written to fr.h5$" out.txt || fail "no fracture count printed"
  grep -qE "^trace plane mid: [0-9]+ lines written to fr.mid.lines.h5$" out.txt || fail "no section printed"
  json_get r.json "d['dimension'] == 3 and [s['name'] for s in d['sets']][:4] == ['F1', 'F2', 'S1', 'fault']" \
    | grep -q True || fail "sets not in the documented order"
  json_get r.json "d['totals']['fractures'] > 0 and all(s['p32'] > 0 for s in d['sets'][:4])" | grep -q True \
    || fail "no fractures measured"
  "$DDA" info fr.mid.lines.h5 | grep -q "seed: *11" || fail "the section lost the fractures' provenance"
  "$DDA" dl s3d_small.yaml -o again.h5 --report r2.json -q || fail "second run"
  cmp -s r.json r2.json || fail "the same seed gave another report"
  ls -a | grep -q '\.tmp' && fail "temporary files left behind"
  true
}

case_trace_then_dc() {
  copy_s3d
  "$DDA" dl s3d_small.yaml -o fr.h5 -q || fail "dl"
  "$DDA" trace fr.h5 --point 5 5 5 --dip 90 --dip-direction 90 -o sec.h5 --vtk sec.vtu > out.txt || fail "trace"
  grep -qE "^[0-9]+ lines \(section of 100 m\^2\) written to sec.h5$" out.txt || fail "trace printed: $(cat out.txt)"
  [ -s sec.vtu ] || fail "sec.vtu missing"
  "$DDA" info sec.h5 | grep -q "dda-lines" || fail "the section is not a lines file"
  "$DDA" dc sec.h5 -o blocks.h5 -q || fail "dc of the section"
  "$DDA" stats blocks.h5 --json > s.json || fail "stats"
  # The section x = 5 of the 10 m cube, minus the tunnel's 16-gon of radius 1.5.
  json_get s.json "abs(d['total_area'] - (100 - 8 * 1.5**2 * __import__('math').sin(__import__('math').pi / 8))) < 1e-9 * 100" \
    | grep -q True || fail "total area $(json_get s.json "d['total_area']")"
  # The scenario's trace plane 'mid' is the same plane: the same blocks.
  "$DDA" dc fr.mid.lines.h5 -o blocks_mid.h5 -q || fail "dc of the scenario's section"
  "$DDA" stats blocks_mid.h5 --json > s2.json || fail "stats of the scenario's section"
  [ "$(json_get s.json "d['blocks']")" = "$(json_get s2.json "d['blocks']")" ] || fail "the two sections differ"
  "$DDA" trace --help | grep -q "Usage" || fail "trace --help"
  expect_error 1 "^dda: fr.h5: the plane through \(5, 5, 50\) misses the domain of the fractures\.$" -- \
    "$DDA" trace fr.h5 --point 5 5 50 --dip 0 --dip-direction 0 -o x.h5
  expect_error 1 "sec.h5" -- "$DDA" trace sec.h5 --point 5 5 5 --dip 0 --dip-direction 0 -o x.h5
  expect_usage_error "$DDA" trace fr.h5 --point 5 5 --dip 0 --dip-direction 0 -o x.h5
  [ ! -e x.h5 ] || fail "an output was written despite the error"
}

case_dl3_bad_key() {
  copy_s3d
  sed 's/spacing: 4/spaceing: 4/' s3d_small.yaml > bad.yaml
  expect_error 1 "^dda: bad.yaml:12: unknown key 'persistent_sets\[0\]\.spaceing' \(did you mean 'spacing'\?\)" -- \
    "$DDA" dl bad.yaml -o f.h5
  { cat s3d_small.yaml; printf 'joint_sets: []\n'; } > bad2.yaml
  expect_error 1 "^dda: bad2.yaml:23: joint_sets is a 2D section, not read with dimension: 3 \(in 3D, use fracture_sets\)\.$" -- \
    "$DDA" dl bad2.yaml -o f.h5
  sed 's/^dimension: 3/dimension: 4/' s3d_small.yaml > bad3.yaml
  expect_error 1 "^dda: bad3.yaml:5: dimension must be 2 or 3, got 4\.$" -- "$DDA" dl bad3.yaml -o f.h5
  sed 's/radius: 1.5, sides: 16/radius: 1.5, sides: 2/' s3d_small.yaml > bad4.yaml
  expect_error 1 "^dda: bad4.yaml:18: excavations\[0\]\.sides must be in \[3, 1000\], got 2\.$" -- "$DDA" dl bad4.yaml -o f.h5
  [ ! -e f.h5 ] || fail "an output was written despite the error"
  write_scenario
  printf 'planes: []\n' >> scenario.yaml
  expect_error 1 "^dda: scenario.yaml:[0-9]+: planes is a 3D section; add dimension: 3 at the top level to use it\.$" -- \
    "$DDA" dl scenario.yaml -o l.h5
}

case_dc3d_stats_plot_info() {
  copy_s3d
  "$DDA" dl s3d_small.yaml -o fr.h5 -q || fail "dl"
  "$DDA" dc fr.h5 -o b3.h5 --vtk b3.vtu --report r.json > out.txt || fail "dc of a fractures file"
  grep -qE "^[0-9]+ bodies \([0-9]+ convex parts, total volume [0-9.]+ m\^3\) written to b3.h5$" out.txt \
    || fail "dc printed: $(cat out.txt)"
  [ -s b3.vtu ] || fail "b3.vtu missing"
  grep -q 'type="Int64" Name="faces"' b3.vtu || grep -q 'Name="faces"' b3.vtu || fail "no polyhedron faces in b3.vtu"
  "$DDA" stats b3.h5 --json > s.json || fail "stats"
  # The 10 m cube minus the tunnel: a 16-gon prism of radius 1.5 m, 10 m long.
  json_get s.json "d['dimension'] == 3 and abs(d['total_volume'] + d['excavated_volume'] - 1000) < 1e-9 * 1000 and abs(d['excavated_volume'] - 80 * 1.5**2 * __import__('math').sin(__import__('math').pi / 8)) < 1e-9 * 1000" \
    | grep -q True || fail "volumes $(json_get s.json "(d['total_volume'], d['excavated_volume'])")"
  "$DDA" stats b3.h5 | grep -q "block theory:" || fail "no block theory in the text summary"
  "$DDA" info b3.h5 | grep -qE "dda-blocks3d, [0-9]+ bodies" || fail "info"
  "$DDA" info fr.h5 | grep -qE "dda-fractures, [0-9]+ fractures" || fail "info of fractures"
  "$DDA" plot b3.h5 -o b3.png --view 20 30 --explode 0.2 --color body -q || fail "plot 3D blocks"
  "$DDA" plot fr.h5 -o fr.png -q || fail "plot fractures"
  [ -s b3.png ] && [ -s fr.png ] || fail "figures missing"
  # through: finite fractures that end inside a block leave it whole, so
  # fewer convex parts than glue (which splits and glues them).
  "$DDA" dc fr.h5 -o t.h5 --finite-fractures through --report t.json -q || fail "dc through"
  "$DDA" stats t.h5 --json > t_s.json
  json_get t.json "d['finite_fractures_mode'] == 'through'" | grep -q True || fail "the option was not used"
  [ "$(json_get t_s.json "d['blocks']")" -lt "$(json_get s.json "d['blocks']")" ] || fail "through split as much as glue"
  expect_error 1 "^dda: --min-area, --max-aspect and --slivers apply to 2D cuts; fr.h5 is a 3D fractures file\.$" -- \
    "$DDA" dc fr.h5 -o x.h5 --min-area 1
  "$DDA" trace fr.h5 --point 5 5 5 --dip 90 --dip-direction 90 -o sec.h5 -q
  expect_error 1 "^dda: --finite-fractures applies to 3D cuts; sec.h5 is not a fractures file\.$" -- \
    "$DDA" dc sec.h5 -o x.h5 --finite-fractures glue
  [ ! -e x.h5 ] || fail "an output was written despite the error"
}

case_run3d_writes_everything() {
  copy_s3d
  "$DDA" run s3d_small.yaml -o out > log.txt || fail "run of a 3D scenario: $(cat log.txt)"
  for f in fractures.h5 blocks3d.h5 dl_report.json dc_report.json stats.json sections/mid.lines.h5 \
           sections/mid.blocks.h5 vtk/fractures.vtu vtk/blocks3d.vtu vtk/model.pvd figures/fractures.png \
           figures/blocks3d.png figures/blocks3d_exploded.png; do
    [ -s "out/$f" ] || fail "out/$f missing"
  done
  "$DDA" run s3d_small.yaml -o out2 --no-plots --no-vtk -q || fail "run without plots"
  [ ! -e out2/figures ] && [ ! -e out2/vtk ] || fail "--no-plots/--no-vtk ignored"
  cmp -s out/stats.json out2/stats.json || fail "the same scenario gave other statistics"
  expect_error 1 "^dda: --min-area, --max-aspect and --slivers apply to 2D cuts; s3d_small.yaml is a 3D scenario\.$" -- \
    "$DDA" run s3d_small.yaml -o out3 --min-area 1
}

# The 3D forward run end to end: DL -> DC -> DF of a block on a 20-degree
# plane (phi = 10) slides V1's distance; a run stopped and resumed repeats
# the uninterrupted one bit for bit; history and info know the 3D file.
case_df3_incline_run_resume_history() {
  cp "$SRC/tests/data/df3_incline.yaml" . || fail "copy the fixture"
  "$DDA" run df3_incline.yaml -o out -q || fail "run"
  for f in blocks3d.h5 results.h5 vtk/df.pvd vtk/df_blocks_00000.vtu vtk/df_contacts_00004.vtu; do
    [ -s "out/$f" ] || fail "out/$f missing"
  done
  [ "$(grep -c '<DataSet' out/vtk/df.pvd)" -eq 10 ] || fail "expected 5 frames x (blocks, contacts) in df.pvd"
  grep -q 'Name="faces"' out/vtk/df_blocks_00004.vtu || fail "the block frames are not polyhedra"
  "$DDA" history out/results.h5 --csv --point slider > h.csv || fail "history"
  expected="t"
  for c in x y z ux uy uz vx vy vz sxx syy szz syz szx sxy; do expected="$expected,slider.$c"; done
  [ "$(head -1 h.csv)" = "$expected" ] || fail "header '$(head -1 h.csv)', expected '$expected'"
  /usr/bin/python3 - <<'PY' || fail "slide at t = 1 s is not within 1 % of g(sin20 - cos20 tan10)/2"
import csv, math
rows = list(csv.DictReader(open("h.csv")))
last = rows[-1]
assert abs(float(last["t"]) - 1.0) < 1e-12, last["t"]
assert float(rows[0]["slider.ux"]) == 0
s = math.sqrt(sum(float(last["slider.u" + c]) ** 2 for c in "xyz"))
a = math.radians(20)
expected = 9.81 * (math.sin(a) - math.cos(a) * math.tan(math.radians(10))) / 2
print("s(1 s) = %.6f m, expected %.6f m, error %.3f %%" % (s, expected, 100 * abs(s - expected) / expected))
assert abs(s - expected) <= 0.01 * expected
assert abs(float(last["slider.uy"])) < 1e-9   # no drift across the slope
PY
  "$DDA" history out/results.h5 --csv > all.csv || fail "history of all points"
  [ "$(head -1 all.csv | tr ',' '\n' | grep -c '^base\.')" -eq 15 ] || fail "base columns: $(head -1 all.csv)"
  "$DDA" df df3_incline.yaml --blocks out/blocks3d.h5 -o part.h5 --stop-at-step 300 -q || fail "df --stop-at-step"
  "$DDA" info part.h5 | grep -q "dda-results3d (scenario), 2 blocks (1 fixed), 300 steps .* incomplete" \
    || fail "dda info on a stopped 3D run: $("$DDA" info part.h5)"
  "$DDA" df --resume part.h5 -q || fail "resume"
  "$DDA" history part.h5 --csv > b.csv || fail "history of the resumed run"
  cmp -s all.csv b.csv || fail "the resumed run differs from the uninterrupted one"
  "$DDA" history out/results.h5 --steps > a.csv && "$DDA" history part.h5 --steps > b.csv || fail "history --steps"
  cmp -s a.csv b.csv || fail "the resumed run's step log differs"
  "$DDA" info out/results.h5 | grep -q "dda-results3d (scenario), .* complete" || fail "dda info on a 3D results file"
  # The energy ledger: the resumed run's equals the uninterrupted one's, and
  # the balance closes to a residual of under 1 % of the energy moved
  # (gravity switched on at t = 0 loads the penalty springs in a jolt).
  "$DDA" info out/results.h5 | grep "^energy:" > e1.txt && "$DDA" info part.h5 | grep "^energy:" > e2.txt \
    || fail "no energy line in dda info"
  cmp -s e1.txt e2.txt || fail "the resumed run's energy differs: $(cat e1.txt e2.txt)"
  /usr/bin/python3 - <<'PY' || fail "3D energy balance: $(cat e1.txt)"
import re
line = open("e1.txt").read()
share = float(re.search(r"\(([-0-9.e+]+) % of the energy moved", line).group(1))
print(line.strip())
assert abs(share) < 1.0 and line.rstrip().endswith("J)"), line
PY
  expect_error 1 "out/results.h5: has no measurement point 'nope' \(its points are slider, base\)" -- \
    "$DDA" history out/results.h5 --csv --point nope
  sed 's/dt: 0.001/dt: 0/' df3_incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: control.dt must be > 0, got 0\.$" -- "$DDA" df s.yaml --blocks out/blocks3d.h5 -o r.h5
  sed 's/fixed: {below: 3}/fixed: {below: 30}/' df3_incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: fixed fixes every block of out/blocks3d.h5, so nothing can move\.$" -- \
    "$DDA" df s.yaml --blocks out/blocks3d.h5 -o r.h5
  [ ! -e r.h5 ] || fail "a results file was written despite the errors"
  # A runaway (a block thrown further than the model in one step) stops with
  # the diagnosis and keeps the steps before it.
  sed 's/  gravity: \[0, 0, -9.81\]/  gravity: [0, 0, -1.0e13]/' df3_incline.yaml > s.yaml
  expect_error 1 "a block moves .* more than the model's size; .* run.h5 holds the run up to the step before\.$" -- \
    "$DDA" df s.yaml --blocks out/blocks3d.h5 -o run.h5 -q
  "$DDA" info run.h5 | grep -q "dda-results3d .* incomplete" || fail "the runaway left no results: $("$DDA" info run.h5)"
  ls -a out | grep -q '\.tmp' && fail "temporary files left behind"
  true
}

# Glued artificial cuts in 3D (docs/solver3d.md, "Glued artificial cuts"):
# the cutter splits the intact rock around a gallery into walls, floor and
# roof, one body meeting on artificial faces (tests/data/df3_glued_roof.yaml).
# The run says how many contacts are glued (16: four corners on each of the
# walls' cuts against the roof and the floor). The roof, which hangs on its
# two cuts alone, stays up: it starts from equilibrium and moves less than
# a nanometre in 0.2 s (as ordinary contacts it fell freely, g t^2 / 2 =
# 0.196 m), and its drop in the start-up is the springs' and the rock's
# give under the weights, by hand about 1e-4 m (the walls' bed corners
# 8.2 MN / 4 / pn = 3.7e-5 m, the walls' elastic shortening rho g 3.5 m /
# E x 7 m / 2 = 3e-5 m, the roof's shear springs 2.0 MN / 8 / ps = 5e-6 m;
# measured 7.6e-5 m); a stopped and resumed run repeats the uninterrupted
# one bit for bit.
case_df3_glued_roof() {
  cp "$SRC/tests/data/df3_glued_roof.yaml" . || fail "copy the fixture"
  "$DDA" run df3_glued_roof.yaml -o out > out.txt 2> err.txt || fail "run: $(cat err.txt)"
  glued=$(sed -n 's/.* \([0-9][0-9]*\) of them glued across artificial cuts.*/\1/p' out.txt err.txt | head -1)
  [ "$glued" = 16 ] || fail "expected 16 glued contacts reported, got '$glued': $(cat out.txt err.txt)"
  "$DDA" history out/results.h5 --csv --point roof > h.csv || fail "history"
  /usr/bin/python3 - <<'PY' || fail "the glued roof moved more than its springs' stretch"
import csv
rows = list(csv.DictReader(open("h.csv")))
u0, uz = float(rows[0]["roof.uz"]), float(rows[-1]["roof.uz"])
print("roof uz: %.3e m after the start-up, %.3e m at t = %s s" % (u0, uz, rows[-1]["t"]))
assert abs(uz - u0) < 1e-9, (u0, uz)
assert abs(uz) < 2e-4, uz
PY
  "$DDA" df df3_glued_roof.yaml --blocks out/blocks3d.h5 -o part.h5 --stop-at-step 100 -q || fail "df --stop-at-step"
  "$DDA" df --resume part.h5 -q || fail "resume"
  "$DDA" history out/results.h5 --csv > a.csv && "$DDA" history part.h5 --csv > b.csv || fail "history of both runs"
  cmp -s a.csv b.csv || fail "the resumed run differs from the uninterrupted one"
  "$DDA" history out/results.h5 --steps > a.csv && "$DDA" history part.h5 --steps > b.csv || fail "history --steps"
  cmp -s a.csv b.csv || fail "the resumed run's step log differs"
  "$DDA" info out/results.h5 | grep "^energy:" > e1.txt && "$DDA" info part.h5 | grep "^energy:" > e2.txt \
    || fail "no energy line in dda info"
  cmp -s e1.txt e2.txt || fail "the resumed run's energy differs: $(cat e1.txt e2.txt)"
}

# Measurement points by block (docs/scenario.md, "points"): a point placed
# by the block containing a point of the slider, at the slider's centroid,
# rides with it as the explicit point `slider` at its centre does; each
# mistake is one sentence naming the key.
case_df_points_by_block() {
  write_incline
  sed -i 's/^materials:/  - {name: centre, block: {containing: [5.5, 3.8]}}\nmaterials:/' incline.yaml
  "$DDA" run incline.yaml -o out -q --no-vtk || fail "run"
  "$DDA" history out/results.h5 --csv > all.csv || fail "history"
  /usr/bin/python3 - <<'PY' || fail "the point by block does not ride with the slider"
import csv, math
rows = list(csv.DictReader(open("all.csv")))
# The slider's centre (6.5, 0.5) in the slope frame, rotated 30 deg by hand;
# the first row is after the start-up relaxation: x - ux is where it started.
a = math.radians(30)
centre = (6.5 * math.cos(a) - 0.5 * math.sin(a), 6.5 * math.sin(a) + 0.5 * math.cos(a))
start = [float(rows[0]["centre." + c]) - float(rows[0]["centre.u" + c]) for c in "xy"]
assert math.dist(start, centre) < 1e-9, (start, centre)
for r in rows:
    for c in ("ux", "uy", "vx", "vy"):
        assert abs(float(r["centre." + c]) - float(r["slider." + c])) < 1e-9, (r["t"], c)
print("centre moved %.4f m, as slider" % math.hypot(float(rows[-1]["centre.ux"]), float(rows[-1]["centre.uy"])))
PY
  B=out/blocks.h5
  sed 's/block: {containing: \[5.5, 3.8\]}/block: 7/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: points\[5\].block is block 7, but out/blocks.h5 has 2 blocks \(ids 0 to 1\)\.$" -- \
    "$DDA" df s.yaml --blocks $B -o r.h5
  sed 's/containing: \[5.5, 3.8\]/containing: [50, 50]/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: points\[5\].block.containing puts \(50, 50\) outside every block of out/blocks.h5\.$" -- \
    "$DDA" df s.yaml --blocks $B -o r.h5
  sed 's/{name: centre, block/{name: centre, kind: load, block/' incline.yaml > s.yaml
  expect_error 1 "s.yaml:[0-9]+: points\[5\].kind is 'load', but only a measurement point can be placed by block" -- \
    "$DDA" run s.yaml -o out2
  [ ! -e out2/lines.h5 ] || fail "DL ran although the point was wrong"
  sed '/^control:/d' incline.yaml | sed '/^materials:/,/^  interface:/d' > nc.yaml
  expect_error 1 "nc.yaml:[0-9]+: points\[5\].block places a measurement point on a block, which only the forward run does" -- \
    "$DDA" dl nc.yaml -o l.h5
  [ ! -e r.h5 ] && [ ! -e l.h5 ] || fail "an output was written despite the errors"
}

# The same in 3D, on the slider of df3_incline.yaml (x, y in [3.5, 6.5],
# between the plane z = 3 - (x - 5) tan 20 and the top z = 6): its centroid
# by hand is x = 5 + tan 20 / 4 = 5.0909925, y = 5, z = 4.5 - tan^2 20 / 8 =
# 4.4834407 (the wedge of rock under x > 5 is thicker: integrate the
# column height 3 + (x - 5) tan 20 over x).
case_df3_points_by_block() {
  cp "$SRC/tests/data/df3_incline.yaml" . || fail "copy the fixture"
  sed 's/^materials:/  - {name: centre, block: {containing: [5, 5, 4.5]}}\n  - {name: same, block: {containing: [5, 5, 4.5]}, at: [5, 5, 4.5]}\nmaterials:/' \
    df3_incline.yaml > s.yaml
  "$DDA" run s.yaml -o out -q || fail "run"
  "$DDA" history out/results.h5 --csv > all.csv || fail "history"
  /usr/bin/python3 - <<'PY' || fail "the points by block are not where they should be or do not ride with the slider"
import csv, math
rows = list(csv.DictReader(open("all.csv")))
t = math.tan(math.radians(20))
expected = (5 + t / 4, 5, 4.5 - t * t / 8)
got = tuple(float(rows[0]["centre." + c]) for c in "xyz")
assert max(abs(g - e) for g, e in zip(got, expected)) < 1e-9, (got, expected)
for r in rows:   # `same` is the explicit `slider`, placed by block
    for c in ("x", "y", "z", "ux", "uy", "uz"):
        assert r["same." + c] == r["slider." + c], (r["t"], c)
u = [float(rows[-1]["centre.u" + c]) for c in "xyz"]
v = [float(rows[-1]["slider.u" + c]) for c in "xyz"]
assert math.dist(u, v) < 1e-3 * math.hypot(*v), (u, v)   # one rigid block, up to its small rotation
print("centre at (%.7f, %.7f, %.7f), moved %.4f m" % (got + (math.hypot(*u),)))
PY
  B=out/blocks3d.h5
  # A resumed run places them again from the scenario it stored: the same run.
  "$DDA" df s.yaml --blocks $B -o part.h5 --stop-at-step 300 -q || fail "df --stop-at-step"
  "$DDA" df --resume part.h5 -q || fail "resume"
  "$DDA" history part.h5 --csv > resumed.csv || fail "history of the resumed run"
  cmp -s all.csv resumed.csv || fail "the resumed run differs from the uninterrupted one"
  sed 's/name: centre, block: {containing: \[5, 5, 4.5\]}/name: centre, block: {below: 10}/' s.yaml > e.yaml
  expect_error 1 "e.yaml:[0-9]+: points\[2\].block.below selects 2 blocks of $B \(0, 1\), but a point rides with one" -- \
    "$DDA" df e.yaml --blocks $B -o r.h5
  sed 's/name: centre, block: {containing: \[5, 5, 4.5\]}/name: centre, block: {box: [0, 0, 20, 1, 1, 21]}/' s.yaml > e.yaml
  expect_error 1 "e.yaml:[0-9]+: points\[2\].block.box selects no block of $B\.$" -- "$DDA" df e.yaml --blocks $B -o r.h5
  sed 's/name: centre, block: {containing: \[5, 5, 4.5\]}/name: centre, block: 2/' s.yaml > e.yaml
  expect_error 1 "e.yaml:[0-9]+: points\[2\].block is block 2, but $B has 2 blocks \(ids 0 to 1\)\.$" -- \
    "$DDA" df e.yaml --blocks $B -o r.h5
  sed 's/block: {containing: \[5, 5, 4.5\]}, at: \[5, 5, 4.5\]/block: {containing: [5, 5, 4.5]}, at: [5, 5, 1]/' s.yaml > e.yaml
  expect_error 1 "e.yaml:[0-9]+: points\[3\].at puts point 'same' at \(5, 5, 1\), outside block [01] \(centroid \(5.09, 5, 4.48\)\), the block it names\.$" -- \
    "$DDA" df e.yaml --blocks $B -o r.h5
  [ ! -e r.h5 ] || fail "a results file was written despite the errors"
}

# Rock bolts in 3D (docs/scenario.md, "bolts"): a cube hanging on a bolt
# from a fixed roof block (tests/data/df3_bolt.yaml) settles with the bolt
# carrying its weight W = 25506 N at L0 + W/k = 2.0025506 m and stays there;
# a bolt with breaking force W/2 and gravity switched on at t = 0 breaks at
# t = T/6 = (pi/3) sqrt(m/k) (k (L - L0) reaches W/2 there) within a step,
# after which the cube falls freely; a stopped and resumed run repeats the
# uninterrupted one bit for bit; a misplaced end is one sentence naming it.
case_df3_bolt_run_history() {
  cp "$SRC/tests/data/df3_bolt.yaml" . || fail "copy the fixture"
  "$DDA" run df3_bolt.yaml -o out -q || fail "run"
  "$DDA" history out/results.h5 > summary.txt || fail "history"
  grep -qE "^b1 +25506" summary.txt || fail "no bolt line in the summary: $(cat summary.txt)"
  "$DDA" info out/results.h5 | grep -q "1 measurement points, 1 bolts, complete" || fail "dda info: $("$DDA" info out/results.h5)"
  "$DDA" history out/results.h5 --bolts > b.csv || fail "history --bolts"
  [ "$(head -1 b.csv)" = "t,b1.force,b1.length,b1.broken" ] || fail "header '$(head -1 b.csv)'"
  /usr/bin/python3 - <<'PY' || fail "the settled bolt does not carry W at L0 + W/k"
import csv
rows = list(csv.DictReader(open("b.csv")))
assert len(rows) == 21, len(rows)   # t = 0, then 20 steps of 0.01 s
W, k = 2600 * 9.81, 1.0e7
for r in rows:
    assert abs(float(r["b1.force"]) - W) < 1e-3, r
    assert abs(float(r["b1.length"]) - (2 + W / k)) < 1e-9, r
    assert r["b1.broken"] == "0", r
print("force %s N, length %s m" % (rows[-1]["b1.force"], rows[-1]["b1.length"]))
PY
  # Weaker than the weight, released at t = 0.
  sed -e 's/stiffness: 1.0e7}/stiffness: 1.0e6, breaking_force: 12753}/' \
      -e 's/control: {dt: 0.01, total_time: 0.2, output_interval: 0.1}/control: {dt: 0.001, total_time: 0.1, output_interval: 0.05, initial_equilibrium: false}/' \
      df3_bolt.yaml > weak.yaml
  grep -q "breaking_force: 12753" weak.yaml && grep -q "initial_equilibrium: false" weak.yaml || fail "sed weak.yaml"
  "$DDA" df weak.yaml --blocks out/blocks3d.h5 -o weak.h5 -q || fail "df of the weak bolt"
  "$DDA" history weak.h5 --bolts > w.csv && "$DDA" history weak.h5 --csv > p.csv || fail "history of the weak bolt"
  /usr/bin/python3 - <<'PY' || fail "the weak bolt does not break at T/6, or the cube does not then fall freely"
import csv, math
bolt = list(csv.DictReader(open("w.csv")))
cube = list(csv.DictReader(open("p.csv")))
m, k, g = 2600.0, 1.0e6, 9.81
t6 = math.pi / 3 * math.sqrt(m / k)
at = next(i for i, r in enumerate(bolt) if r["b1.broken"] == "1")
tb = float(bolt[at]["t"])
print("broke at t = %.4f s, T/6 = %.5f s" % (tb, t6))
assert t6 <= tb < t6 + 0.001 + 1e-12, (tb, t6)
assert all(r["b1.broken"] == "1" and float(r["b1.force"]) == 0 for r in bolt[at:])
z0, v0 = float(cube[at]["cube.z"]), float(cube[at]["cube.vz"])
t = float(cube[-1]["t"]) - tb
assert abs(float(cube[-1]["cube.z"]) - (z0 + v0 * t - g * t * t / 2)) < 1e-9
PY
  "$DDA" df weak.yaml --blocks out/blocks3d.h5 -o part.h5 --stop-at-step 30 -q || fail "df --stop-at-step"
  "$DDA" df --resume part.h5 -q || fail "resume"
  "$DDA" history part.h5 --bolts > w2.csv || fail "history of the resumed run"
  cmp -s w.csv w2.csv || fail "the resumed run's bolt differs from the uninterrupted one's"
  sed 's/to: \[0.5, 0.5, 0.5\]/to: [0.5, 0.5, 1.5]/' df3_bolt.yaml > s.yaml
  expect_error 1 "^dda: s.yaml:[0-9]+: bolts\[0\]\.to lies outside every block\.$" -- \
    "$DDA" df s.yaml --blocks out/blocks3d.h5 -o r.h5
  sed 's/to: \[0.5, 0.5, 0.5\]/to: [0.5, 0.5, 2.9]/' df3_bolt.yaml > s.yaml
  expect_error 1 "^dda: s.yaml:[0-9]+: bolts\[0\]\.to lies in the same block as .from. \(a bolt must join two blocks\)\.$" -- \
    "$DDA" df s.yaml --blocks out/blocks3d.h5 -o r.h5
  [ ! -e r.h5 ] || fail "a results file was written despite the errors"
}

# 3D incident wave through `dda run` (docs/solver3d.md, "Viscous boundaries
# and incident waves"): a 10 m column of four 2.5 m plates (nu = 0: c =
# sqrt(E / rho) = 707.1 m/s) with dashpots on its bottom and top, and an
# outcrop velocity pulse 2 a sin^2(pi t / 0.1 s), a = 1e-3 m/s, sent in. An
# up-going pulse whose velocity is up compresses, so the contacts need no
# precompression, and the viscous top sends nothing back: the second plate's
# centroid moves as the incident wave, half the outcrop motion, peaking at
# 1e-3 m/s (within 5 %) at 0.05 + 3.75 / 707.1 = 55.3 ms (within 2 %).
# Then one sentence for a side that is not one, and for free-field sides
# given without an incident wave, on a viscous side or on the top.
case_df3_incident_wave() {
  cat > col3.yaml <<'YAML'
name: col3
dimension: 3
domain: {box: [0, 0, 0, 5, 5, 10]}
planes:
  - {name: b1, dip: 0, dip_direction: 0, point: [0, 0, 2.5]}
  - {name: b2, dip: 0, dip_direction: 0, point: [0, 0, 5]}
  - {name: b3, dip: 0, dip_direction: 0, point: [0, 0, 7.5]}
points:
  - {name: second, kind: measurement, at: [2.5, 2.5, 3.75]}
materials:
  default: {density: 2000, young: 1.0e9, poisson: 0}
boundaries:
  viscous: [bottom, top]
loading:
  gravity: [0, 0, 0]
  earthquake: {record: pulse.csv, units: m/s2, direction: [0, 0, 1], mode: incident, baseline: 0}
control: {dt: 0.0005, total_time: 0.15, output_interval: 0.05, normal_penalty: 2.5e12}
output: {vtk: false, plots: false}
YAML
  /usr/bin/python3 - > pulse.csv <<'PY'
import math
print("t,a")
for k in range(401):
    t = 0.1 * k / 400
    print("%.6f,%.9f" % (t, 2e-3 * math.pi / 0.1 * math.sin(2 * math.pi * t / 0.1)))
PY
  "$DDA" run col3.yaml -o out -q || fail "run"
  "$DDA" history out/results.h5 --csv --point second > h.csv || fail "history"
  /usr/bin/python3 - <<'PY' || fail "the second plate does not move as the incident wave (1e-3 m/s at 55.3 ms)"
import csv
rows = list(csv.DictReader(open("h.csv")))
peak = max(rows, key=lambda r: float(r["second.vz"]))
v, t = float(peak["second.vz"]), float(peak["t"])
print("peak %.6f m/s at %.4f s (1e-3 m/s at 0.0553 s)" % (v, t))
assert abs(v - 1e-3) <= 0.05 * 1e-3
assert abs(t - 0.0553) <= 0.02 * 0.0553
PY
  sed 's/  viscous: \[bottom, top\]/  viscous: [bottom, up]/' col3.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: boundaries.viscous\[1\] must be bottom, top, west, east, south or north, got 'up'\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks3d.h5 -o r.h5
  # Free-field sides: only with an incident wave, not on a side that also
  # has plain dashpots, only on the lateral sides.
  sed -e 's/  viscous: \[bottom, top\]/  viscous: [bottom, top]\n  free_field: [west, east]/' -e 's/ mode: incident,//' \
    col3.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: boundaries.free_field needs an incident wave \(loading.earthquake with mode: incident\): the free field is the motion that wave gives the rock\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks3d.h5 -o r.h5
  sed 's/  viscous: \[bottom, top\]/  viscous: [bottom, west]\n  free_field: [west]/' col3.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: boundaries.free_field\[0\] is also in boundaries.viscous; a side has plain dashpots or free-field ones, not both\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks3d.h5 -o r.h5
  sed 's/  viscous: \[bottom, top\]/  viscous: [bottom]\n  free_field: [top]/' col3.yaml > bad.yaml
  expect_error 1 "bad.yaml:[0-9]+: boundaries.free_field\[0\] must be west, east, south or north \(free-field boundaries stand on the lateral sides\), got 'top'\.$" -- \
    "$DDA" df bad.yaml --blocks out/blocks3d.h5 -o r.h5
}

# ---------------------------------------------------------------- hardening
# docs/reliability.md: strict YAML, write errors, outputs that spare the
# inputs.

case_strict_yaml() {
  write_scenario
  # A key given twice: yaml-cpp alone would keep seed: 7 without a word.
  cp scenario.yaml twice.yaml && echo "seed: 8" >> twice.yaml
  expect_error 1 "^dda: twice.yaml: key 'seed' is given twice \(lines 2 and 13\)\.$" -- "$DDA" dl twice.yaml -o l.h5
  sed 's/mean_spacing: 1.5,/mean_spacing: 1.5, dip: 35,/' scenario.yaml > inner.yaml
  expect_error 1 "^dda: inner.yaml: key 'joint_sets\[0\]\.dip' is given twice \(both on line 6\)\.$" -- \
    "$DDA" run inner.yaml -o out
  # A second document: everything after the `---` would have been ignored.
  { cat scenario.yaml; printf -- '---\nseed: 9\n'; } > two.yaml
  expect_error 1 "^dda: two.yaml:13: a second YAML document starts here \('---'\); the file must hold exactly one\.$" -- \
    "$DDA" dl two.yaml -o l.h5
  # The same in a 3D scenario and in the sections `dda df` reads.
  copy_s3d
  { cat s3d_small.yaml; echo "seed: 2"; } > s3.yaml
  expect_error 1 "^dda: s3.yaml: key 'seed' is given twice" -- "$DDA" dl s3.yaml -o f.h5
  write_incline
  sed 's/^control: {dt: 0.001,/control: {dt: 0.001, dt: 0.002,/' incline.yaml > dfdup.yaml
  "$DDA" dl incline.yaml -o l.h5 -q && "$DDA" dc l.h5 -o b.h5 -q || fail "dl, dc of the incline"
  expect_error 1 "^dda: dfdup.yaml: key 'control.dt' is given twice \(both on line [0-9]+\)\.$" -- \
    "$DDA" df dfdup.yaml --blocks b.h5 -o r.h5
  [ ! -e f.h5 ] && [ ! -e r.h5 ] && [ ! -e out ] || fail "an output was written despite the errors"
}

# The command's output goes to a full device: one sentence, exit 1.
expect_stdout_error() {
  "$@" >/dev/full 2>err.txt; local rc=$?
  [ "$rc" -eq 1 ] || fail "$* > /dev/full: exit $rc, expected 1; stderr: $(cat err.txt)"
  [ "$(wc -l < err.txt)" -eq 1 ] || fail "$* > /dev/full: expected one line on stderr, got: $(cat err.txt)"
  grep -qxF "dda: could not write to standard output: No space left on device." err.txt \
    || fail "$* > /dev/full: stderr '$(cat err.txt)'"
}

case_stdout_write_errors() {
  [ -w /dev/full ] || { echo "SKIP: no /dev/full"; return 0; }
  write_incline
  "$DDA" run incline.yaml -o out -q --no-vtk --no-plots || fail "run"
  expect_stdout_error "$DDA" history out/results.h5 --csv
  expect_stdout_error "$DDA" history out/results.h5 --steps
  expect_stdout_error "$DDA" history out/results.h5
  expect_stdout_error "$DDA" stats out/blocks.h5 --json
  expect_stdout_error "$DDA" stats out/blocks.h5
  expect_stdout_error "$DDA" info out/results.h5
  expect_stdout_error "$DDA" wedge --plane 51.4/065.8 --plane 51.4/295.2 --phi 30 --json
  expect_stdout_error "$DDA" --version
  expect_stdout_error "$DDA" stats --help
  # Quiet commands print nothing, so a full standard output is no error.
  "$DDA" dc out/lines.h5 -o b2.h5 -q > /dev/full || fail "dc -q > /dev/full failed"
}

# A disk that fills while an output file is written (a file size limit
# stands in for it; SIGXFSZ ignored so that write() fails with EFBIG as on a
# full disk instead of killing the process): one sentence naming the file,
# exit 1, no temporary file and no older file damaged.
expect_full_disk() {
  local kib="$1" pattern="$2"; shift 2
  bash -c 'trap "" XFSZ; ulimit -f "$0"; exec "$@"' "$kib" "$@" >out.txt 2>err.txt; local rc=$?
  [ "$rc" -eq 1 ] || fail "$* (limit $kib KiB): exit $rc, expected 1; stderr: $(cat err.txt)"
  [ "$(wc -l < err.txt)" -eq 1 ] || fail "$* (limit $kib KiB): expected one line on stderr, got: $(cat err.txt)"
  grep -qE "$pattern" err.txt || fail "$* (limit $kib KiB): stderr '$(cat err.txt)' does not match '$pattern'"
  ls -a | grep -q '\.tmp' && fail "$*: temporary files left behind"
  true
}

case_full_disk_output() {
  write_incline
  "$DDA" run incline.yaml -o out -q --no-vtk --no-plots || fail "run"
  expect_full_disk 4 "^dda: l.h5: cannot write: .*\.$" "$DDA" dl incline.yaml -o l.h5 -q
  expect_full_disk 4 "^dda: b.h5: cannot write: .*\.$" "$DDA" dc out/lines.h5 -o b.h5 -q
  expect_full_disk 8 "^dda: r.h5: cannot write: .*\.$" "$DDA" df incline.yaml --blocks out/blocks.h5 -o r.h5 -q
  "$DDA" history out/results.h5 --csv > full.csv || fail "history"
  [ "$(stat -c %s full.csv)" -gt 2048 ] || fail "the history is too short for the test"
  expect_full_disk 2 "^dda: h.csv: cannot write: File too large\.$" "$DDA" history out/results.h5 --csv -o h.csv
  expect_full_disk 1 "^dda: s.json: cannot write: File too large\.$" "$DDA" stats out/blocks.h5 -o s.json -q
  [ ! -e l.h5 ] && [ ! -e b.h5 ] && [ ! -e r.h5 ] && [ ! -e h.csv ] && [ ! -e s.json ] || fail "a partial output was left"
}

# Every file below the work folder: name, inode, size and content (an
# atomic rename over a file changes its inode). The test's own out.txt and
# err.txt are left out.
snapshot() {
  find . -type f ! -name out.txt ! -name err.txt -print0 | sort -z | xargs -0 -r stat -c '%n %i %s'
  find . -type f ! -name out.txt ! -name err.txt -print0 | sort -z | xargs -0 -r md5sum
}

# expect_refused PATTERN -- command: refused with exit 1 before any work,
# every file unchanged and none added.
expect_refused() {
  local pattern="$1"; shift 2
  local before; before=$(snapshot)
  expect_error 1 "$pattern" -- "$@"
  [ "$(snapshot)" = "$before" ] || fail "$*: files changed"
}

case_outputs_spare_inputs() {
  write_incline
  "$DDA" dl incline.yaml -o l.h5 -q && "$DDA" dc l.h5 -o b.h5 -q || fail "dl, dc"
  "$DDA" df incline.yaml --blocks b.h5 -o r.h5 -q || fail "df"
  local same="; choose another output name\.$"
  expect_refused "^dda: incline.yaml: will not write the output over the input incline.yaml$same" -- \
    "$DDA" dl incline.yaml -o incline.yaml
  expect_refused "^dda: l.h5: will not write the output over the input l.h5$same" -- "$DDA" dc l.h5 -o l.h5
  expect_refused "^dda: b.h5: will not write the output over the input b.h5$same" -- \
    "$DDA" df incline.yaml --blocks b.h5 -o b.h5
  expect_refused "^dda: incline.yaml: will not write the output over the input incline.yaml$same" -- \
    "$DDA" df incline.yaml --blocks b.h5 -o incline.yaml
  expect_refused "^dda: l.h5: will not write the output over the input l.h5$same" -- \
    "$DDA" dc l.h5 -o b9.h5 --report l.h5
  # Another name for the same file: a symlink, a hard link, another spelling.
  ln -s b.h5 soft.h5 && ln l.h5 hard.h5 || fail "links"
  expect_refused "^dda: soft.h5: will not write the output over the input b.h5 \(they are the same file\)$same" -- \
    "$DDA" df incline.yaml --blocks b.h5 -o soft.h5
  expect_refused "^dda: hard.h5: will not write the output over the input l.h5 \(they are the same file\)$same" -- \
    "$DDA" dc l.h5 -o hard.h5
  expect_refused "^dda: \./incline.yaml: will not write the output over the input incline.yaml" -- \
    "$DDA" dl incline.yaml -o ./incline.yaml
  # The other commands with an output and an input.
  expect_refused "^dda: r.h5: will not write the output over the input r.h5$same" -- \
    "$DDA" history r.h5 --csv -o r.h5
  expect_refused "^dda: b.h5: will not write the output over the input b.h5$same" -- "$DDA" stats b.h5 -o b.h5
  expect_refused "^dda: b.h5: will not write the output over the input b.h5$same" -- "$DDA" plot b.h5 -o b.h5
  expect_refused "^dda: r.h5: will not write the output over the input r.h5$same" -- \
    "$DDA" spectra r.h5 --point slider -o r.h5
  expect_refused "^dda: r.h5: will not write the output over the input r.h5$same" -- \
    "$DDA" compare r.h5 --point slider --dip 30 --reference r.h5 -o r.h5
  expect_refused "^dda: incline.yaml: will not write the output over the input incline.yaml$same" -- \
    "$DDA" run incline.yaml -o incline.yaml
  # `dda run` writes fixed names into its folder: a scenario kept under one
  # of them, or inside its vtk/ folder, is refused too.
  mkdir -p o/vtk && cp incline.yaml o/stats.json && cp incline.yaml o/vtk/s.yaml
  expect_refused "^dda: o/stats.json: will not write the output over the input o/stats.json$same" -- \
    "$DDA" run o/stats.json -o o
  expect_refused "^dda: o/vtk: will not write into this output folder, it holds the input o/vtk/s.yaml; choose another output folder\.$" -- \
    "$DDA" run o/vtk/s.yaml -o o
  # A resumed run rewrites its own file by design.
  "$DDA" df incline.yaml --blocks b.h5 -o part.h5 -q --stop-at-step 5 || fail "df --stop-at-step"
  "$DDA" df --resume part.h5 -o part.h5 -q || fail "resume in place was refused"
}

# png_size FILE: "WIDTH HEIGHT" from the PNG header, or nothing if FILE is not a PNG.
png_size() {
  /usr/bin/python3 -c "
import struct, sys
d = open(sys.argv[1], 'rb').read(24)
if d[:8] == b'\x89PNG\r\n\x1a\n': print(*struct.unpack('>II', d[16:24]))" "$1"
}

# every_png FOLDER NAME...: each FOLDER/NAME.png is a PNG of a sensible size.
every_png() {
  local dir="$1"; shift
  for k in "$@"; do
    local size; size="$(png_size "$dir/$k.png")"
    [ -n "$size" ] || fail "$dir/$k.png is missing or not a PNG"
    set -- $size
    [ "$1" -ge 400 ] && [ "$2" -ge 300 ] || fail "$dir/$k.png is only $1 x $2 pixels"
  done
}

case_plot_results_2d() {
  write_incline
  "$DDA" run incline.yaml -o out -q --no-report || fail "run"
  "$DDA" plot out/results.h5 -o figs -q || fail "plot every figure"
  every_png figs blocks contacts histories energy steps
  [ "$(ls figs | wc -l)" -eq 5 ] || fail "figs holds $(ls figs)"
  "$DDA" plot out/results.h5 -o s.png --times 0 0.5 --color-by stress --component sxy --vectors -q \
    || fail "plot stress at two times"
  every_png . s
  # What is drawn is what the file holds: the colour scale of the deformed
  # blocks ends at the largest block displacement of the last frame, and the
  # history lines are the file's displacements.
  PYTHONPATH="$SRC/tools/plot" /usr/bin/python3 - <<'PY' || fail "the figures do not show the file's numbers"
import h5py, numpy as np
import results_figures as rf
from results_data import read_results
r = read_results("out/results.h5", h5py)
with h5py.File("out/results.h5") as f:
    off, v0, v1 = f["model/blocks/offsets"][()], f["model/blocks/vertices"][()], f["frames/vertices"][-1]
    u = f["series/displacement"][()]
top = max(np.linalg.norm(v1[a:b].mean(0) - v0[a:b].mean(0)) for a, b in zip(off[:-1], off[1:]))
fig, note = rf.draw(r, "blocks", rf.FigureOptions())
pc = fig.axes[0].collections[0]
label = fig.axes[1].get_ylabel()
factor = 1000.0 if "(mm)" in label else 1.0
assert "(m)" in label or "(mm)" in label, label
assert abs(pc.get_clim()[1] - factor * top) <= 1e-9 * factor * top, (pc.get_clim(), top)
fig, note = rf.draw(r, "histories", rf.FigureOptions())
ux = fig.axes[0].lines[0].get_ydata()
factor = 1000.0 if "(mm)" in fig.axes[0].get_ylabel() else 1.0
assert np.allclose(ux, factor * u[:, 0, 0]), "ux of the first point"
assert note is None
PY
  # A results file without contacts: said, and the blocks are drawn.
  /usr/bin/python3 -c "
import h5py, shutil
shutil.copy('out/results.h5', 'nc.h5')
with h5py.File('nc.h5', 'r+') as f: del f['checkpoint/contacts']" || fail "copy without contacts"
  "$DDA" plot nc.h5 -o nc.png --kind contacts > note.txt 2>&1 || fail "plot contacts of a file without them"
  grep -q "holds no contacts" note.txt || fail "no word about the missing contacts: $(cat note.txt)"
  every_png . nc
  expect_error 1 "out/results.h5: a 3D results file|out/results.h5: --kind sections is for 3D results" -- \
    "$DDA" plot out/results.h5 -o x.png --kind sections
  expect_error 1 "out/results.h5: --times 7 is outside the saved frames \(t = 0 to 1 s\)" -- \
    "$DDA" plot out/results.h5 -o x.png --times 7
  [ ! -e x.png ] || fail "a refused plot left x.png"
}

case_plot_results_3d() {
  cp "$SRC/tests/data/df3_incline.yaml" . || fail "copy the fixture"
  "$DDA" run df3_incline.yaml -o out -q || fail "run"
  "$DDA" plot out/results.h5 -o figs -q || fail "plot every figure"
  every_png figs blocks sections contacts histories energy steps
  "$DDA" plot out/results.h5 -o v.png --look 225/30 plan --times 0 1 --vectors --color-by velocity -q \
    || fail "plot views"
  "$DDA" plot out/results.h5 -o s.svg --kind sections --section z=4 y=5 -q || fail "plot sections"
  every_png . v
  grep -q "<svg" s.svg || fail "s.svg is not an SVG"
  # The views show the model's own extent: looking north, x spans the box (0..10 m) and z its height.
  PYTHONPATH="$SRC/tools/plot" /usr/bin/python3 - <<'PY' || fail "the 3D view does not span the model"
import h5py
import results_figures as rf
from results_data import read_results
r = read_results("out/results.h5", h5py)
fig, _ = rf.draw(r, "blocks", rf.FigureOptions(looks=["north"]))
ax = fig.axes[0]
assert ax.get_xlabel() == "x east (m)" and ax.get_ylabel() == "z up (m)", (ax.get_xlabel(), ax.get_ylabel())
lo, hi = ax.get_xlim()
assert lo <= 0 and hi >= 10 and hi - lo < 11, (lo, hi)
PY
  "$DDA" plot out/results.h5 -o e.png --kind energy -q || fail "the 3D energy figure"
  every_png . e
  expect_error 1 "dda: --look 30: give TREND/PLUNGE" -- "$DDA" plot out/results.h5 -o x.png --look 30
}

# dda compare on a 3D run against dda sliding3d: the df3_incline block slides
# down a 20 deg plane (dip direction 090) with friction 10 deg, s = a t^2 / 2,
# a = g (sin 20 - cos 20 tan 10). The run gives 0.86505 m at t = 1 s against
# 0.86488 m: +0.019 %. The DDA step integrates a constant acceleration
# exactly, so what is left is the contact's penalty spring settling under
# the block's weight and the first steps' open-close iterations. The test
# allows 0.01 % to 0.03 %: a direction 2 deg off (1 - cos 2 = 0.06 %), one step of
# delay in the time axis (2 dt / t = 0.2 %) or a sign error all fall outside.
case_compare_3d_sliding3d() {
  cp "$SRC/tests/data/df3_incline.yaml" . || fail "copy the fixture"
  "$DDA" run df3_incline.yaml -o out -q || fail "run"
  "$DDA" sliding3d --plane 20/090 --phi 10 --duration 1 --dt 1e-4 -o ref.csv -q || fail "sliding3d"
  "$DDA" compare out/results.h5 --point slider --trend-plunge 090/20 --reference ref.csv --json \
    --plot cmp.png -o cmp.csv > tp.json || fail "compare along trend/plunge"
  every_png . cmp
  "$DDA" compare out/results.h5 --point slider --intersection 20/090 90/000 --reference ref.csv --json > ix.json \
    || fail "compare along the line of two planes"
  "$DDA" compare out/results.h5 --point slider --direction 0.9396926207859084,0,-0.3420201433256687 \
    --reference ref.csv --json > v.json || fail "compare along a vector"
  /usr/bin/python3 - <<'PY' || fail "3D comparison"
import json, math
tp, ix, v = (json.load(open(n)) for n in ("tp.json", "ix.json", "v.json"))
d = tp["direction"]
assert len(d) == 3 and abs(d[0] - math.cos(math.radians(20))) < 1e-12 and abs(d[2] + math.sin(math.radians(20))) < 1e-12, d
for other in (ix, v):   # the same direction three ways: the same numbers
    assert abs(other["final_relative_error"] - tp["final_relative_error"]) < 1e-9, (other, tp)
assert tp["reference_direction"] == tp["direction"]
assert abs(tp["final_time"] - 1.0) < 1e-12
e = tp["final_relative_error"]
print("final relative error %.4f %%" % (100 * e))
assert 1e-4 <= e <= 3e-4, e
PY
  expect_error 1 "dda: --dip: is for 2D results" -- \
    "$DDA" compare out/results.h5 --point slider --dip 20 --reference ref.csv
  expect_error 1 "dda: --direction: give three numbers x,y,z for a 3D results file" -- \
    "$DDA" compare out/results.h5 --point slider --direction 1,0 --reference ref.csv
  expect_error 1 "dda: --intersection: the planes 20/090 and 20/090 are parallel" -- \
    "$DDA" compare out/results.h5 --point slider --intersection 20/090 20/090 --reference ref.csv
}

# dda run writes report.html after a forward run: every section, table and
# figure is there, and every figure is a PNG inside the page.
check_report() {
  /usr/bin/python3 - "$1" "$2" <<'PY' || fail "report $1"
import base64, sys
from html.parser import HTMLParser
path, dim = sys.argv[1], int(sys.argv[2])
class Page(HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.images, self.external = set(), [], []
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            assert a["id"] not in self.ids, "id %s twice" % a["id"]
            self.ids.add(a["id"])
        if tag == "img":
            self.images.append(a.get("src", ""))
        for k in ("href", "src"):   # self-contained: nothing fetched from elsewhere
            if k in a and not a[k].startswith(("data:", "#")):
                self.external.append(a[k])
p = Page()
p.feed(open(path, encoding="utf-8").read())
kinds = ["blocks", "contacts", "histories", "steps", "energy"] + ([] if dim == 2 else ["sections"])
want = {"figure-" + k for k in kinds} | {"table-" + t for t in ("provenance", "model", "run", "points")}
want |= {"provenance", "model", "run", "energy-balance", "warnings", "figures", "measurement-points", "scenario"}
want.add("table-energy")
missing = want - p.ids
assert not missing, "missing: %s" % sorted(missing)
assert not p.external, p.external
assert len(p.images) == len(kinds), len(p.images)
for src in p.images:
    assert src.startswith("data:image/png;base64,"), src[:40]
    assert base64.b64decode(src.split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
PY
}

case_report_html() {
  write_incline
  sed -i 's/plots: false/plots: true/' incline.yaml
  "$DDA" run incline.yaml -o out --no-vtk > run.log || fail "run"
  grep -q "report written to out/report.html" run.log || fail "dda run did not say where the report is"
  check_report out/report.html 2
  cp "$SRC/tests/data/df3_incline.yaml" . || fail "copy the fixture"
  "$DDA" run df3_incline.yaml -o out3 -q || fail "run 3D"
  [ ! -e out3/report.html ] || fail "a run with plots: false wrote a report"
  "$DDA" report out3 -o rep3 -q || fail "dda report on a 3D run folder"
  check_report rep3/report.html 3
  grep -q "residual (penalty springs, implicit step)</th><td>[^<]* k\?J = " rep3/report.html \
    || fail "the 3D report has no energy balance in J"
  expect_error 1 "out/blocks.h5: is not a results file \(dda-blocks\)" -- "$DDA" report out/blocks.h5 -o x
  mkdir empty
  expect_error 1 "empty: holds no results.h5" -- "$DDA" report empty -o x
  # A headless browser renders the page when one is installed.
  for b in chromium chromium-browser google-chrome; do
    if command -v "$b" > /dev/null; then
      "$b" --headless --disable-gpu --no-sandbox --screenshot="$PWD/shot.png" --window-size=1200,3000 \
        "file://$PWD/out/report.html" > /dev/null 2>&1 || fail "$b could not render the report"
      every_png . shot
      break
    fi
  done
  true
}

# Rock bolts in the VTK frames and the block figures (docs/formats.md,
# docs/plots.md). 2D: the incline's slider tied to its slab by a bolt of
# k = 1e5 N/m that breaks at 5000 N/m; the sliding slider stretches it
# until it breaks (at t = 0.611 s in this run), between the frames at 0.5
# and 0.75 s. 3D: the cube of df3_bolt.yaml on a weak bolt, which breaks
# at T/6 = 0.053 s (case df3_bolt_run_history), between the frames at 0.05
# and 0.1 s. Every frame's bolt file holds one line cell per bolt with the
# force `dda history --bolts` prints for that time and the broken flag; the
# figure draws each bolt between the ends the VTK file holds (the figure
# carries them from the checkpoint with their blocks, the solver moved them
# step by step), solid while intact and dashed once broken.
case_bolts_in_vtk_and_plots() {
  write_incline
  /usr/bin/python3 - >> incline.yaml <<'PY'
import math
a = math.radians(30)
r = lambda x, y: [round(math.cos(a) * x - math.sin(a) * y, 12), round(math.sin(a) * x + math.cos(a) * y, 12)]
print("bolts:\n  - {name: b1, from: %s, to: %s, stiffness: 1.0e5, breaking_force: 5000}" % (r(6.5, 0.5), r(6.5, -0.5)))
PY
  "$DDA" run incline.yaml -o out -q --no-report || fail "run 2D"
  "$DDA" history out/results.h5 --bolts > b2.csv || fail "history --bolts 2D"
  cp "$SRC/tests/data/df3_bolt.yaml" . || fail "copy the fixture"
  sed -e 's/stiffness: 1.0e7}/stiffness: 1.0e6, breaking_force: 12753}/' \
      -e 's/control: {dt: 0.01, total_time: 0.2, output_interval: 0.1}/control: {dt: 0.001, total_time: 0.1, output_interval: 0.05, initial_equilibrium: false}/' \
      -e 's/output: {vtk: false, plots: false, checkpoint_seconds: 0}/output: {vtk: true, plots: false, checkpoint_seconds: 0}/' \
      df3_bolt.yaml > weak.yaml
  grep -q "breaking_force: 12753" weak.yaml && grep -q "vtk: true" weak.yaml || fail "sed weak.yaml"
  "$DDA" run weak.yaml -o out3 -q --no-report || fail "run 3D"
  "$DDA" history out3/results.h5 --bolts > b3.csv || fail "history --bolts 3D"
  PYTHONPATH="$SRC/tools/plot" /usr/bin/python3 - <<'PY' || fail "the bolts of the VTK frames or the figures are not the run's"
import csv, glob
import xml.etree.ElementTree as ET
import h5py, numpy as np
import matplotlib
matplotlib.use("Agg")
import results_figures as rf
from results_data import read_results

def vtu(path):
    root = ET.parse(path).getroot()
    piece = root.find(".//Piece")
    arrays = {a.get("Name"): np.array(a.text.split(), dtype=float) for a in piece.iter("DataArray") if a.get("Name")}
    points = np.array(piece.find("Points/DataArray").text.split(), dtype=float).reshape(-1, 3)
    types = np.array(piece.find("Cells/DataArray[@Name='types']").text.split(), dtype=int)
    return points, types, arrays

def check(folder, history, dim):
    rows = list(csv.DictReader(open(history)))
    t_hist = np.array([float(r["t"]) for r in rows])
    r = read_results(f"{folder}/results.h5", h5py)
    pvd = open(f"{folder}/vtk/df.pvd").read()
    states = []
    for k, t in enumerate(r.frame_time):
        name = "df_bolts_%05d.vtu" % k
        assert name in pvd, name
        points, types, a = vtu(f"{folder}/vtk/{name}")
        assert list(types) == [3], types          # one VTK_LINE
        row = rows[int(np.argmin(np.abs(t_hist - t)))]
        assert abs(float(row["t"]) - t) < 1e-9, (row["t"], t)
        f = float(row["b1.force"])
        assert abs(a["axial_force"][0] - f) <= 1e-6 * max(1.0, abs(f)), (t, a["axial_force"][0], f)
        assert int(a["broken"][0]) == int(row["b1.broken"]), (t, a["broken"][0], row["b1.broken"])
        states.append(int(a["broken"][0]))
        # The figure's bolt at this frame: the ends the VTK holds, the style its state.
        fig, _ = rf.draw(r, "blocks", rf.FigureOptions(times=[t], looks=["north"] if dim == 3 else None))
        ax = fig.axes[0]
        drawn = [l for l in ax.lines if len(l.get_xdata()) == 2]
        assert len(drawn) == 1, len(drawn)
        ends = np.column_stack([drawn[0].get_xdata(), drawn[0].get_ydata()])
        want = points[:, :2] if dim == 2 else points[:, [0, 2]]  # 3D looking north: x to the right, z up
        assert np.allclose(ends, want, atol=1e-9), (t, ends, want)
        assert (drawn[0].get_linestyle() == "-") == (a["broken"][0] == 0), drawn[0].get_linestyle()
        rf.close(fig)
    assert states[0] == 0 and states[-1] == 1 and states == sorted(states), states
    print(folder, "bolt states by frame", states)

check("out", "b2.csv", 2)
check("out3", "b3.csv", 3)
PY
  "$DDA" plot out/results.h5 -o figs -q || fail "plot the 2D run with a bolt"
  "$DDA" plot out3/results.h5 -o figs3 -q || fail "plot the 3D run with a bolt"
  every_png figs blocks
  every_png figs3 blocks
  "$DDA" report out -o rep -q || fail "report of the 2D run with a bolt"
  check_report rep/report.html 2
  grep -q "Rock bolts: solid while intact, dashed red once broken" rep/report.html \
    || fail "the report's block figure does not say how the bolts are drawn"
}


# ---------------------------------------------------------------- studies
# (dda study, docs/studies.md)

# The V4 wedge of docs/validation.md as a study base.
write_wedge_study() {
  cat > wedge_study.yaml <<'YAML'
wedge:
  plane1: {dip: 51.4, dip_direction: 65.8}
  plane2: {dip: 51.4, dip_direction: 295.2}
  phi: 30
  azimuth: 0
vary:
  phi: [26, 28, 30]
sample:
  seed: 5
  draws: 4
  values:
    plane1.dip: {distribution: normal, mean: 51.4, std: 2}
measure: [fs, yield_acceleration]
failure: {measure: fs, below: 1.5}
YAML
}

# summary.csv without its seconds column (the one column that may differ
# between two runs of the same study).
without_seconds() {
  /usr/bin/python3 - "$1" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
k = rows[0].index("seconds")
for r in rows:
    print(",".join(r[:k] + r[k + 1:]))
PY
}

case_study_wedge_cases() {
  write_wedge_study
  "$DDA" study wedge_study.yaml -o out --no-plots > run.txt || fail "study"
  # 3 grid points x 4 draws = 12 cases.
  [ "$(wc -l < out/summary.csv)" -eq 13 ] || fail "expected a header and 12 rows: $(cat out/summary.csv)"
  head -1 out/summary.csv | grep -qx "case,seed,draw,phi,plane1.dip,fs,yield_acceleration,failed,status,seconds,error" \
    || fail "header: $(head -1 out/summary.csv)"
  grep -q "study: 12 cases, 12 ok, 0 failed" run.txt || fail "$(cat run.txt)"
  # Every row is dda wedge on its own values, digit for digit.
  /usr/bin/python3 - "$DDA" <<'PY' || fail "a case differs from dda wedge on the same planes"
import csv, json, subprocess, sys
for r in csv.DictReader(open("out/summary.csv")):
    j = json.loads(subprocess.run([sys.argv[1], "wedge", "--plane", f"{r['plane1.dip']}/65.8", "--plane", "51.4/295.2",
                                   "--phi", r["phi"], "--azimuth", "0", "--json"], check=True, capture_output=True).stdout)
    assert float(r["fs"]) == j["fs"], (r, j["fs"])
    assert float(r["yield_acceleration"]) == j["yield_acceleration_g"], (r, j)
    assert r["failed"] == ("1" if j["fs"] < 1.5 else "0"), r
PY
  # Draw d has the same dip at every phi (common random numbers), and the
  # study run again gives the same summary value for value.
  [ "$(cut -d, -f3,5 out/summary.csv | sort -u | wc -l)" -eq 5 ] || fail "draws differ between grid points"
  "$DDA" study wedge_study.yaml -o again --no-plots -q || fail "second run"
  cmp -s <(without_seconds out/summary.csv) <(without_seconds again/summary.csv) || fail "a second run differs"
  # The cases share out over threads (-j) without changing a value.
  "$DDA" study wedge_study.yaml -o threads -j 3 --no-plots -q || fail "run on three threads"
  cmp -s <(without_seconds out/summary.csv) <(without_seconds threads/summary.csv) || fail "-j 3 differs"
  /usr/bin/python3 -c "
import h5py, sys
f = h5py.File('out/study.h5', 'r')
assert f.attrs['format'] == b'dda-study' or f.attrs['format'] == 'dda-study'
assert len(f['cases/id']) == 12 and len(f['measures/fs']) == 12
assert 'phi: [26, 28, 30]' in (f.attrs['study_text'].decode() if isinstance(f.attrs['study_text'], bytes) else f.attrs['study_text'])
" || fail "study.h5"
  ls -a out | grep -q '\.tmp' && fail "temporary files left behind"
  true
}

case_study_bad_input() {
  write_wedge_study
  write_scenario
  # An unknown key path, as the scenario reader sees it (with its hint).
  printf 'scenario: scenario.yaml\nvary:\n  joint_sets[0].mean_lenght: [5, 10]\nmeasure: [{kind: stats, key: blocks}]\n' > s1.yaml
  expect_error 1 "^dda: s1.yaml:3: vary.joint_sets\[0\].mean_lenght\[0\] = 5 is refused by the scenario reader: unknown key 'joint_sets\[0\].mean_lenght' \(did you mean 'mean_length'\?\)" \
    -- "$DDA" study s1.yaml -o out1
  # A list index the base does not have.
  printf 'scenario: scenario.yaml\nvary:\n  joint_sets[5].dip: [5]\nmeasure: [{kind: stats, key: blocks}]\n' > s2.yaml
  expect_error 1 "^dda: s2.yaml:3: vary.joint_sets\[5\].dip\[0\] names no key of the base \(the base has no joint_sets\[5\]\)" \
    -- "$DDA" study s2.yaml -o out2
  # A value out of range, on its own line.
  printf 'scenario: scenario.yaml\nvary:\n  joint_sets[0].mean_length:\n    - 5\n    - -3\nmeasure: [{kind: stats, key: blocks}]\n' > s3.yaml
  expect_error 1 "^dda: s3.yaml:5: vary.joint_sets\[0\].mean_length\[1\] = -3 is refused by the scenario reader: joint_sets\[0\].mean_length must be > 0, got -3" \
    -- "$DDA" study s3.yaml -o out3
  # An empty grid.
  printf 'scenario: scenario.yaml\nvary:\n  joint_sets[0].dip: []\nmeasure: [{kind: stats, key: blocks}]\n' > s4.yaml
  expect_error 1 "^dda: s4.yaml:3: vary.joint_sets\[0\].dip has no values" -- "$DDA" study s4.yaml -o out4
  # A sampled value whose law the scenario cannot take.
  printf 'scenario: scenario.yaml\nsample:\n  seed: 1\n  draws: 3\n  values:\n    joint_sets[0].randomness: {distribution: uniform, min: 1, max: 2}\nmeasure: [{kind: stats, key: blocks}]\n' > s5.yaml
  expect_error 1 "^dda: s5.yaml:6: sample.values.joint_sets\[0\].randomness = 1.5 is refused by the scenario reader: joint_sets\[0\].randomness must be" \
    -- "$DDA" study s5.yaml -o out5
  # Too many cases for a study without --yes.
  printf 'scenario: scenario.yaml\nseeds: 600\nmeasure: [{kind: stats, key: blocks}]\n' > s6.yaml
  expect_error 1 "^dda: s6.yaml: makes 600 cases, more than 500; give --yes" -- "$DDA" study s6.yaml -o out6
  expect_error 1 "^dda: s6.yaml: makes 600 cases, more than 10; give --yes" -- "$DDA" study s6.yaml -o out6 --max-cases 10
  # A measure kind of the other case kind, and a missing file.
  printf 'scenario: scenario.yaml\nmeasure: [fs]\n' > s7.yaml
  expect_error 1 "^dda: s7.yaml:2: measure\[0\] names the measure kind 'fs', which a scenario study does not have" \
    -- "$DDA" study s7.yaml -o out7
  expect_error 1 "^dda: nothere.yaml: no such file" -- "$DDA" study nothere.yaml -o out8
  # Nothing was written for any of them.
  for k in 1 2 3 4 5 6 7 8; do [ ! -e "out$k" ] || fail "a refused study wrote out$k"; done
  true
}


# A block sliding down a 30 degree incline (write_incline) for 0.5 s, the
# interface friction varied: a study of three full pipelines whose
# measures have closed forms.
write_incline_study() {
  write_incline
  sed -i 's/total_time: 1.0, output_interval: 0.25/total_time: 0.5, output_interval: 0.25/' incline.yaml
  cat > study.yaml <<'YAML'
scenario: incline.yaml
vary:
  joints.interface.friction_deg: [10, 20, 40]
measure:
  - {kind: point_displacement, point: slider, name: slide}
  - {kind: point_displacement, point: slider, of: peak, name: slide_peak}
  - {kind: blocks_displaced, threshold: 0.1, name: moved}
  - {kind: stats, key: blocks, name: blocks}
  - kinetic_energy
failure: {measure: slide, above: 0.1}
YAML
}

case_study_pipeline_measures() {
  write_incline_study
  "$DDA" study study.yaml -o out -j 2 --no-plots > run.txt 2> err.txt || fail "study: $(cat err.txt)"
  grep -q "study: 3 cases, 3 ok, 0 failed" run.txt || fail "$(cat run.txt)"
  for c in c0000 c0001 c0002; do
    for f in scenario.yaml lines.h5 blocks.h5 stats.json results.h5 log.txt case.json; do
      [ -s "out/cases/$c/$f" ] || fail "out/cases/$c/$f missing"
    done
  done
  /usr/bin/python3 - <<'PY' || fail "the measures are not those of a block sliding on an incline"
import csv, math
g, a, t = 9.81, math.radians(30), 0.5
for r in csv.DictReader(open("out/summary.csv")):
    phi = math.radians(float(r["joints.interface.friction_deg"]))
    # Sliding block: s = g (sin a - cos a tan phi) t^2 / 2 while phi < a,
    # and at rest otherwise (friction 40 deg > 30 deg).
    acc = max(0.0, g * (math.sin(a) - math.cos(a) * math.tan(phi)))
    s = acc * t * t / 2
    slide = float(r["slide"])
    print(f"phi {r['joints.interface.friction_deg']}: slide {slide:.5f} m, expected {s:.5f} m")
    if s > 0:
        assert abs(slide - s) <= 0.02 * s, (slide, s)
        # Kinetic energy of the 1 m x 1 m slider (2000 kg/m) at v = acc t; the
        # fixed slab does not move.
        ke = 0.5 * 2000 * (acc * t) ** 2
        assert abs(float(r["kinetic_energy"]) - ke) <= 0.04 * ke, (r["kinetic_energy"], ke)
        assert r["moved"] == "1" and r["failed"] == "1", r
    else:
        assert slide < 1e-3, slide
        assert r["moved"] == "0" and r["failed"] == "0", r
    assert float(r["slide_peak"]) >= slide and float(r["slide_peak"]) <= slide + 1e-3, r
    # The model has two blocks: the slab and the slider.
    assert r["blocks"] == "2" and r["status"] == "ok", r
PY
  # Wilson 95 % interval of 2 of 3 by hand: centre (2/3 + z^2/6)/(1 + z^2/3) = 0.5731, half width
  # z/(1 + z^2/3) sqrt((2/9)/3 + z^2/36) = 0.3654, z = 1.96.
  grep -q "probability of failure P(slide > 0.1) = 0.6667 (2 of 3 cases; 95 % interval 0.2077 to 0.9385)" run.txt \
    || fail "$(cat run.txt)"
  ls -a out | grep -q '\.tmp' && fail "temporary files left behind"
  true
}

# The same measures in 3D: the cube of df3_incline.yaml on its 20 deg plane,
# at phi 10 (it slides) and 30 (it holds), 0.5 s.
case_study_pipeline_measures_3d() {
  cp "$SRC/tests/data/df3_incline.yaml" . || fail "copy the fixture"
  sed -i 's/total_time: 1, output_interval: 0.25/total_time: 0.5, output_interval: 0.25/; s/vtk: true/vtk: false/' df3_incline.yaml
  cat > study.yaml <<'YAML'
scenario: df3_incline.yaml
vary:
  joints.slide.friction_deg: [10, 30]
measure:
  - {kind: point_displacement, point: slider, name: slide}
  - {kind: blocks_displaced, threshold: 0.1, name: moved}
  - {kind: blocks_below, level: 4.45, name: dropped}
  - kinetic_energy
YAML
  "$DDA" study study.yaml -o out -j 2 --no-plots > run.txt 2> err.txt || fail "study: $(cat err.txt)"
  grep -q "study: 2 cases, 2 ok, 0 failed" run.txt || fail "$(cat run.txt)"
  /usr/bin/python3 - <<'PY' || fail "the 3D measures are not those of a block sliding on a plane"
import csv, math
g, a, t = 9.81, math.radians(20), 0.5
# The 3 x 3 m prism between the plane (z = 3 - (x - 5) tan a) and z = 6:
# volume 27 m^3, mass 2600 * 27 kg; its centroid height by hand
# (27 - (1.5 tan a)^2 / 3) / 6 = 4.4834 m, above the level 4.45.
m = 2600 * 27
for r in csv.DictReader(open("out/summary.csv")):
    phi = math.radians(float(r["joints.slide.friction_deg"]))
    acc = max(0.0, g * (math.sin(a) - math.cos(a) * math.tan(phi)))   # V1 in 3D
    s, v = acc * t * t / 2, acc * t
    slide, ke = float(r["slide"]), float(r["kinetic_energy"])
    print(f"phi {r['joints.slide.friction_deg']}: slide {slide:.5f} m (expected {s:.5f}), "
          f"kinetic energy {ke:.1f} J (expected {0.5 * m * v * v:.1f})")
    if s > 0:
        # 0.216 m down the plane drops the centroid 0.074 m, below 4.45.
        assert abs(slide - s) <= 0.01 * s, (slide, s)
        assert abs(ke - 0.5 * m * v * v) <= 0.02 * 0.5 * m * v * v, (ke, 0.5 * m * v * v)
        assert r["moved"] == "1" and r["dropped"] == "1", r
    else:
        assert slide < 1e-4 and ke < 1.0, r
        assert r["moved"] == "0" and r["dropped"] == "0", r
    assert r["status"] == "ok", r
PY
  true
}

# A failing case is recorded with its error and the others run; a study
# killed while a case runs resumes: the finished cases are kept, the killed
# one runs again, and the summary is the one an uninterrupted run gives.
case_study_resume_and_failure() {
  write_incline_study
  # The slider's measurement point sits in an opening the last value cuts
  # out of the slider: that case's forward run has no block for it.
  cat > study.yaml <<'YAML'
scenario: incline.yaml
vary:
  joints.interface.friction_deg: [10, 20, 25, 40]
  excavations:
    - []
    - [{shape: circle, center: [5.379, 3.683], radius: 0.2}]
measure:
  - {kind: point_displacement, point: slider, name: slide}
YAML
  "$DDA" study study.yaml -o full -j 1 --no-plots -q || fail "uninterrupted study"
  [ "$(grep -c ',ok,' full/summary.csv)" -eq 4 ] || fail "expected 4 cases ok: $(cat full/summary.csv)"
  [ "$(grep -c ',failed,' full/summary.csv)" -eq 4 ] || fail "expected 4 cases failed: $(cat full/summary.csv)"
  grep ",failed," full/summary.csv | head -1 | grep -q ",\"scenario.yaml: the measurement point .slider. at (5.379165125, 3.683012702) lies in no block: it is inside an excavation.\"$" \
    || fail "a failed case does not say why: $(grep ',failed,' full/summary.csv | head -1)"
  # Killed while its third case runs, then run again.
  DDA_PROGRESS_SECONDS=0.2 "$DDA" study study.yaml -o part -j 1 --no-plots 2> part.log &
  pid=$!
  for _ in $(seq 1 600); do [ -e part/cases/c0002/scenario.yaml ] && break; sleep 0.05; done
  [ -e part/cases/c0002/scenario.yaml ] || { kill $pid; fail "the study never reached its third case"; }
  kill -TERM $pid; wait $pid 2>/dev/null
  # The killed study's running case died with it (no dda run left on c0002).
  sleep 0.5
  pgrep -f "run part/cases/c0002/scenario.yaml" > /dev/null && fail "the killed study's case runs on"
  [ -e part/cases/c0000/case.json ] && [ -e part/cases/c0001/case.json ] || fail "the first two cases did not finish"
  # The finished cases are a prefix (one at a time): the case running when
  # the study was killed (c0002, or a later one if c0002 ended first: a
  # failing case ends at once) has no record, nor has any case after it.
  unfinished=0
  for k in 2 3 4 5 6 7; do
    if [ -e "part/cases/c000$k/case.json" ]; then
      [ "$unfinished" -eq 0 ] || fail "case c000$k has a record after an unfinished case"
    else
      unfinished=1
    fi
  done
  [ "$unfinished" -eq 1 ] || fail "the killed study finished every case"
  [ ! -e part/summary.csv ] || fail "a killed study wrote a summary"
  done_before=$(ls part/cases/*/case.json | wc -l)
  before=$(stat -c %Y part/cases/c0000/case.json)
  sleep 1
  DDA_PROGRESS_SECONDS=0.05 "$DDA" study study.yaml -o part -j 2 --no-plots 2> resume.log > /dev/null \
    || fail "resume: $(cat resume.log)"
  grep -q "$done_before of 8 cases already finished, $((8 - done_before)) to run" resume.log \
    || fail "resume did not skip: $(cat resume.log)"
  [ "$(stat -c %Y part/cases/c0000/case.json)" = "$before" ] || fail "a finished case ran again"
  cmp -s <(without_seconds full/summary.csv) <(without_seconds part/summary.csv) \
    || fail "the resumed summary differs: $(diff <(without_seconds full/summary.csv) <(without_seconds part/summary.csv))"
  # Progress lines while it runs, and the last one counts the case that failed before the kill too.
  [ "$(grep -c "^study: [0-9]/8 cases  [0-9] failed  .* elapsed  ETA" resume.log)" -ge 2 ] || fail "progress: $(cat resume.log)"
  tail -1 resume.log | grep -q "^study: 8/8 cases  4 failed" || fail "last progress line: $(cat resume.log)"
  true
}

# A case whose run dies (here: killed) is a failed row and the study goes
# on; --retry-failed runs it again.
case_study_case_killed() {
  write_incline_study
  sed -i 's/total_time: 0.5,/total_time: 20,/' incline.yaml
  printf 'scenario: incline.yaml\nseeds: 2\nmeasure:\n  - {kind: point_displacement, point: slider, name: slide}\n' > two.yaml
  "$DDA" study two.yaml -o out -j 1 --no-plots > run.txt 2> err.txt &
  pid=$!
  child=""
  for _ in $(seq 1 600); do
    child=$(pgrep -f "run out/cases/c0000/scenario.yaml" | head -1)
    [ -n "$child" ] && break
    sleep 0.02
  done
  [ -n "$child" ] || { kill $pid; fail "the first case never started"; }
  kill -KILL "$child"
  wait $pid || fail "the study stopped with its case: $(cat err.txt)"
  grep -q "study: 2 cases, 1 ok, 1 failed" run.txt || fail "$(cat run.txt)"
  grep -q '^c0000,1,,,failed,.*,its dda run was killed by signal 9\.$' out/summary.csv || fail "$(cat out/summary.csv)"
  grep -q '^c0001,2,,[0-9.e-]*,ok,' out/summary.csv || fail "$(cat out/summary.csv)"
  "$DDA" study two.yaml -o out -j 1 --no-plots -q || fail "resume"
  grep -q '^c0000,1,,,failed' out/summary.csv || fail "a plain rerun ran the failed case again"
  "$DDA" study two.yaml -o out -j 1 --no-plots -q --retry-failed || fail "--retry-failed"
  [ "$(grep -c ',ok,' out/summary.csv)" -eq 2 ] || fail "--retry-failed left: $(cat out/summary.csv)"
}

# The same study across three MPI ranks (rank 0 hands out the cases): the
# summary is the local run's, value for value.
case_study_mpi_matches_local() {
  write_incline_study
  "$DDA" study study.yaml -o local --no-plots -q || fail "local study"
  as_root=()
  [ "$(id -u)" -eq 0 ] && as_root=(--allow-run-as-root)
  "${MPIEXEC:-mpirun}" -n 3 --oversubscribe "${as_root[@]}" "$DDA" study study.yaml -o mpi --no-plots > mpi.log 2>&1 \
    || fail "mpirun: $(cat mpi.log)"
  grep -q "study: 3 cases, 3 ok, 0 failed" mpi.log || fail "$(cat mpi.log)"
  cmp -s <(without_seconds local/summary.csv) <(without_seconds mpi/summary.csv) \
    || fail "the MPI summary differs: $(diff <(without_seconds local/summary.csv) <(without_seconds mpi/summary.csv))"
  # Wedge cases are shared among the ranks too (every rank takes every
  # third case), with the local summary.
  write_wedge_study
  "$DDA" study wedge_study.yaml -o wedge_local --no-plots -q || fail "local wedge study"
  "${MPIEXEC:-mpirun}" -n 3 --oversubscribe "${as_root[@]}" "$DDA" study wedge_study.yaml -o wedge_mpi --no-plots \
    > wedge_mpi.log 2>&1 || fail "mpirun wedge: $(cat wedge_mpi.log)"
  cmp -s <(without_seconds wedge_local/summary.csv) <(without_seconds wedge_mpi/summary.csv) \
    || fail "the MPI wedge summary differs: $(diff <(without_seconds wedge_local/summary.csv) <(without_seconds wedge_mpi/summary.csv))"
  # A bad study is refused by every rank, and said once, by rank 0.
  sed 's/phi: \[26, 28, 30\]/phi: [26, 28, 95]/' wedge_study.yaml > bad_study.yaml
  "${MPIEXEC:-mpirun}" -n 3 --oversubscribe "${as_root[@]}" "$DDA" study bad_study.yaml -o bad --no-plots \
    > bad.out 2> bad.err && fail "mpirun accepted a friction angle of 95 deg"
  [ "$(grep -c '^dda: ' bad.err)" -eq 1 ] || fail "expected the error once: $(cat bad.err)"
  grep -q "^dda: bad_study.yaml.*phi" bad.err || fail "$(cat bad.err)"
  true
}

"case_$CASE"
echo "PASS [$CASE]"
