#!/usr/bin/env bash
# Checks the standalone fuzz driver against planted defects
# (planted_defects.cpp): each kind of finding fails the run with exit 1 (or
# the signal), names the input and saves it byte for byte; a refusal by
# InputError is no finding; a mutant-only defect is found at the same
# mutation every time, and --iteration makes that mutant again alone.
# Usage: bash check.sh PLANTED_STANDALONE_BINARY WORK_FOLDER
set -uo pipefail
exe=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_finding NAME PATTERN: the seed file NAME (holding NAME) is a finding
# whose message matches PATTERN, and its saved input is the seed itself.
expect_finding() {
  local name=$1 pattern=$2
  printf '%s' "$name" > "$name"
  "$exe" --runs 0 --timeout 1 --memory-mb 1024 --artifacts out "$name" > out.txt 2> err.txt
  local rc=$?
  [ "$rc" -ne 0 ] || fail "$name: exit 0"
  grep -qF "FINDING on input $name: the target $pattern" err.txt || fail "$name: no '$pattern' in: $(cat err.txt)"
  cmp -s "$name" out/finding-planted-input0 || fail "$name: the saved input differs from the seed"
  rm -rf out
}
expect_finding escape 'let a std::out_of_range escape ("planted escape")'
expect_finding segv 'crashed with a segmentation fault'
expect_finding abort 'aborted'
expect_finding hang 'took longer than the time limit'
expect_finding alloc 'let a std::bad_alloc escape'

printf 'refused' > refused
"$exe" --runs 0 refused > out.txt 2> err.txt || fail "refused: an InputError was taken for a finding: $(cat err.txt)"

# The mutant-only defect: found, at the same mutation twice, and again alone.
printf 'abcdef' > abcdef
first_finding() {
  "$exe" --runs 20000 --seed "$1" --artifacts out abcdef 2>&1 >/dev/null |
    sed -n 's/.*FINDING on mutation \([0-9]*\) .*planted byte.*/\1/p'
}
k=$(first_finding 7)
[ -n "$k" ] || fail "the planted byte was not found in 20000 mutations"
if [ -n "$k" ]; then
  [ "$(first_finding 7)" = "$k" ] || fail "a second run found it at another mutation than $k"
  [ "$(od -An -tx1 -j2 -N1 out/finding-planted-seed7-iteration$k | tr -d ' ')" = 80 ] ||
    fail "the saved mutant $k has no 0x80 as its third byte"
  "$exe" --seed 7 --iteration "$k" --artifacts again abcdef 2> err.txt && fail "--iteration $k alone found nothing"
  cmp -s out/finding-planted-seed7-iteration$k again/finding-planted-seed7-iteration$k ||
    fail "--iteration $k made another mutant"
  "$exe" --runs 0 out/finding-planted-seed7-iteration$k 2> err.txt && fail "replaying the saved mutant found nothing"
fi
[ "$failures" -eq 0 ] && echo "standalone driver: every planted defect found"
exit $((failures > 0))
