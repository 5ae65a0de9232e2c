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
  for sub in "" dl dc run stats plot info; do
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

"case_$CASE"
echo "PASS [$CASE]"
