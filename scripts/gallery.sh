#!/usr/bin/env bash
# Regenerates the figure gallery of the README (docs/gallery/): runs each
# example through scripts/check_example.sh (so its README numbers are
# checked on the way) and copies one or two of its figures. Not part of CI:
# tunnel_roof takes about 8 minutes and shaking_table_wedge a few.
# Usage: [DDA=path/to/dda] bash scripts/gallery.sh [NAME ...]   (default: every example below)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
gallery="$root/docs/gallery"
mkdir -p "$gallery"
# example: the figures (paths under the run's output folder) the gallery shows
declare -A shown=(
  [layered_tunnel]="figures/blocks.png figures/width_vs_bridge.png"
  [tunnel_roof]="figures/deformed_mesh.png"
  [site_response]="figures/spectral_ratios.png"
  [wedge3d]="figures/wedge_view.png"
  [wedge_backanalysis]="figures/friction_segments.png"
  [shaking_table_wedge]="figures/figure18.png"
  [probabilistic_wedge]="study/figures/fs_histogram.png study/figures/measure_fs_vs_phi.png"
  [tunnel_study]="study/figures/failure_vs_joint_sets_0_mean_length_joint_sets_0_mean_bridge.png study/figures/measure_crown_peak_vs_joint_sets_0_mean_length_joint_sets_0_mean_bridge.png"
)
[[ $# -gt 0 ]] || set -- layered_tunnel tunnel_roof site_response wedge3d wedge_backanalysis shaking_table_wedge \
  probabilistic_wedge tunnel_study
for name in "$@"; do
  [[ -n "${shown[$name]:-}" ]] || { echo "gallery.sh: no figures are chosen for example '$name'" >&2; exit 1; }
  out="$(mktemp -d)"
  echo "== $name"
  OUT="$out" bash "$root/scripts/check_example.sh" "$name" > "$out.log" 2>&1 || {
    tail -n 20 "$out.log"; echo "gallery.sh: example $name failed (log above)" >&2; exit 1; }
  for fig in ${shown[$name]}; do
    [[ -s "$out/$fig" ]] || { echo "gallery.sh: $name did not draw $fig" >&2; exit 1; }
    cp "$out/$fig" "$gallery/${name}_$(basename "$fig")"
    echo "   docs/gallery/${name}_$(basename "$fig")"
  done
  rm -rf "$out" "$out.log"
done
