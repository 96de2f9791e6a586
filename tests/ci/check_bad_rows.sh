#!/usr/bin/env bash
# scripts/check_bad_rows (the device run's check of the GPU's bad-row count, issue 49) on this
# machine's GL: every pattern on a field with NaN regions gives a count equal to the host's recount
# of its file, and the check fails when the counts differ (a recount that lies).
#
#   tests/ci/check_bad_rows.sh SOURCE_DIR SDFWB COUNT_BAD_ROWS SCRATCH_DIR
set -uo pipefail
source_dir="$1" sdfwb="$2" counter="$3" scratch="$4"
rm -rf "$scratch"
mkdir -p "$scratch"
fail() { echo "check_bad_rows: $1" >&2; exit 1; }
field="$source_dir/tests/foreign/15_nan_superquadric.glsl"
out=$("$source_dir/scripts/check_bad_rows" "$sdfwb" "$counter" "$field" 60000) || fail "the counts differ: $out"
echo "$out"
[ "$(grep -c ': equal$' <<< "$out")" -eq 7 ] || fail "expected 7 patterns with equal counts"
grep -q 'GPU count [1-9]' <<< "$out" || fail "no pattern had bad rows to count"
liar="$scratch/liar"
printf '#!/bin/sh\necho "60000 rows, 1 bad rows"\n' > "$liar"
chmod +x "$liar"
if "$source_dir/scripts/check_bad_rows" "$sdfwb" "$liar" "$field" 1000 rand > "$scratch/liar.log"; then
  fail "a recount that differs passed: $(cat "$scratch/liar.log")"
fi
grep -q 'DIFFERENT' "$scratch/liar.log" || fail "the difference is not named: $(cat "$scratch/liar.log")"
echo "check_bad_rows: equal counts pass, a different one fails"
