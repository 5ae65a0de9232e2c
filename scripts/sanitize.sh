#!/usr/bin/env bash
# The unit tests under AddressSanitizer and UndefinedBehaviorSanitizer
# (docs/reliability.md, "Sanitizers"), built in build-sanitize with clang.
# Any report (an overflow, a use after free, a leak, undefined behaviour)
# stops that test and fails it. FOLDER is a test folder (a ctest label):
# common, dl, df or analysis; default: common dl df. Not dc: clang 14 cannot
# compile DC (tests/CMakeLists.txt says why), and df leaves out its one test
# that cuts blocks with DC. JOBS sets the build's parallelism (default:
# every core).
# Usage: bash scripts/sanitize.sh [FOLDER...]
set -euo pipefail
cd "$(dirname "$0")/.."
folders=("$@")
[ ${#folders[@]} -gt 0 ] || folders=(common dl df)
bash scripts/configure_sanitize.sh
cmake --build build-sanitize -j"${JOBS:-$(nproc)}" --target $(printf 'test_%s ' "${folders[@]}")
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/scripts/lsan.supp:print_suppressions=0  # a leak inside HDF5 itself is not ours
cd build-sanitize
labels=$(IFS='|'; echo "^(${folders[*]})\$")
ctest --output-on-failure -j"${JOBS:-$(nproc)}" -L "$labels"
