#!/usr/bin/env bash
# Runs one fuzz target (fuzz/fuzz_TARGET.cpp) for SECONDS, or every target
# for SECONDS each with TARGET "all" (docs/reliability.md, "Fuzzing").
# Builds it first in build-sanitize (clang, ASan + UBSan + libFuzzer; the
# folder scripts/sanitize.sh uses too). Starts from the seed corpus
# fuzz/corpus/TARGET/ and keeps what it finds in build-sanitize/fuzz/corpus/
# TARGET/; an input that crashes is saved under build-sanitize/fuzz/
# artifacts/TARGET/ and the script fails. JOBS sets the build's parallelism
# (default: every core). Extra arguments go to libFuzzer (e.g. -runs=1000000).
# Usage: bash scripts/fuzz.sh TARGET|all SECONDS [LIBFUZZER_ARGS...]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: bash scripts/fuzz.sh TARGET|all SECONDS [LIBFUZZER_ARGS...]" >&2; exit 2; }
cd "$(dirname "$0")/.."
src=$PWD
target=$1 seconds=$2
shift 2
if [ "$target" = all ]; then
  targets=$(cd fuzz/corpus && ls)
else
  [ -d "fuzz/corpus/$target" ] || { echo "fuzz.sh: no target '$target' (one of: $(ls fuzz/corpus | tr '\n' ' '))" >&2; exit 2; }
  targets=$target
fi

bash scripts/configure_sanitize.sh
cmake --build build-sanitize -j"${JOBS:-$(nproc)}" --target $(printf 'fuzz_%s ' $targets)

# A leak inside HDF5 itself is not ours (scripts/lsan.supp says which).
export LSAN_OPTIONS=suppressions=$src/scripts/lsan.supp:print_suppressions=0
for t in $targets; do
  corpus=build-sanitize/fuzz/corpus/$t artifacts=build-sanitize/fuzz/artifacts/$t
  mkdir -p "$corpus" "$artifacts"
  echo "== fuzz_$t, $seconds s"
  # Run inside the artifacts folder: a scenario may name files relative to
  # the working folder, and nothing of the source tree should be one.
  # -timeout: a reader that takes 20 s over one input hangs; -rss_limit_mb:
  # one that needs 2 GB allocates without bound.
  (cd "$artifacts" && "$src/build-sanitize/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=20 \
     -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$src/$artifacts/" "$@" \
     "$src/$corpus" "$src/fuzz/corpus/$t" 2>&1 | grep -v '^#[0-9]')
done
