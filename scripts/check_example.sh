#!/usr/bin/env bash
# Runs one example and checks its README against what it just produced:
# every number marked <!-- check: ... --> in examples/NAME/README.md must be
# the number the run gives now (scripts/check_readme_numbers.py).
# Usage: [DDA=path/to/dda] [OUT=folder] bash scripts/check_example.sh NAME
# OUT defaults to a temporary folder, removed afterwards; the example's own
# check (run.sh's exit status) counts too.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
name="${1:?usage: check_example.sh NAME (a folder of examples/)}"
export DDA="${DDA:-$root/build/bin/dda}"
if [[ -z "${OUT:-}" ]]; then
  OUT="$(mktemp -d)"
  trap 'rm -rf "$OUT"' EXIT
fi
export OUT
bash "$root/examples/$name/run.sh"
/usr/bin/python3 "$root/scripts/check_readme_numbers.py" "$root/examples/$name/README.md" "$OUT"
