#!/usr/bin/env bash
# Runs every example (or those named) and checks each README's marked numbers
# against the run (scripts/check_example.sh). Not part of ctest: tunnel_roof
# takes about 8 minutes and shaking_table_wedge a few, too long for CI; the
# short examples are checked by ctest (example.*).
# Usage: [DDA=path/to/dda] bash scripts/check_examples.sh [NAME ...]
# Each run writes to a temporary folder; the examples' own out/ is untouched.
# Exit status 1 if any example fails; the log of each is kept until the end.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
if [[ $# -eq 0 ]]; then
  set -- $(cd "$root/examples" && for d in */; do [[ -f "$d/run.sh" && -f "$d/README.md" ]] && echo "${d%/}"; done)
fi
logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT
failed=()
for name in "$@"; do
  echo "== $name"
  if bash "$root/scripts/check_example.sh" "$name" > "$logs/$name.log" 2>&1; then
    tail -n 1 "$logs/$name.log"
  else
    failed+=("$name")
    # The checker's lines (or the end of the run's output if the run failed).
    grep -E '^(MISMATCH|ERROR) ' "$logs/$name.log" || tail -n 20 "$logs/$name.log"
    tail -n 1 "$logs/$name.log"
  fi
done
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "FAILED: ${failed[*]}"
  exit 1
fi
echo "all READMEs match their runs: $*"
