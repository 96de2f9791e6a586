#!/usr/bin/env bash
# scripts/lsan_ours passes a run whose leak reports all lie inside other libraries (the two blocks
# CI's GUI test reported, whose one frame names a library mapped at that address at exit), fails a
# run with a report whose stack passes through sdfwb's sources, and passes a run with no reports.
#
#   tests/ci/check_lsan_ours.sh SOURCE_DIR SCRATCH_DIR
set -euo pipefail
source_dir="$1"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch"
fail() { echo "check_lsan_ours: $1" >&2; exit 1; }
theirs="$scratch/theirs.log" ours="$scratch/ours.log" none="$scratch/none.log"
cat > "$theirs" <<'LOG'
[  PASSED  ] 39 tests.
=================================================================
==24167==ERROR: LeakSanitizer: detected memory leaks

Indirect leak of 56 byte(s) in 1 object(s) allocated from:
    #0 0x7f5f618b83b7 in __interceptor_calloc ../../../../src/libsanitizer/asan/asan_malloc_linux.cpp:77
    #1 0x7f5f53d8edd3  (/usr/lib/x86_64-linux-gnu/libsodium.so.23.3.0+0x5dd3)

SUMMARY: AddressSanitizer: 56 byte(s) leaked in 1 allocation(s).
LOG
cp "$theirs" "$ours"
cat >> "$ours" <<LOG

Direct leak of 40 byte(s) in 1 object(s) allocated from:
    #0 0x7f5f618b9c87 in operator new(unsigned long) ../../../../src/libsanitizer/asan/asan_new_delete.cpp:95
    #1 0x55d0c0a1b2c3 in sdfwb::widgets::ParametersPanel::setParameters() $source_dir/build-asan/../widgets/src/ParametersPanel.cpp:120
    #2 0x7f5f5f0a1b2c  (/usr/lib/x86_64-linux-gnu/libQt6Core.so.6+0x2a1b2c)

LOG
echo "[  PASSED  ] 39 tests." > "$none"
"$source_dir/scripts/lsan_ours" "$source_dir" "$theirs" > /dev/null || fail "reports inside other libraries failed the run"
"$source_dir/scripts/lsan_ours" "$source_dir" "$none" > /dev/null || fail "a run without reports failed"
if "$source_dir/scripts/lsan_ours" "$source_dir" "$ours" > /dev/null 2> "$scratch/ours.err"; then
  fail "a leak through sdfwb's code passed"
fi
grep -q "ParametersPanel::setParameters" "$scratch/ours.err" || fail "the leak through sdfwb's code was not printed"
echo "check_lsan_ours: ok"
