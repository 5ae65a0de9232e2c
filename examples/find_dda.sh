# Sourced by every examples/*/run.sh: which dda program to run. DDA when it
# is set; otherwise `dda` on PATH (an installed program); otherwise the one
# this source tree builds (build/bin/dda).
find_dda() {
  if [ -n "${DDA:-}" ]; then
    echo "$DDA"
  elif command -v dda > /dev/null 2>&1; then
    command -v dda
  else
    echo "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build/bin/dda"
  fi
}
