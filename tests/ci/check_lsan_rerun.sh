#!/usr/bin/env bash
# scripts/ctest_lsan_rerun reruns, once, exactly the tests whose failure was LeakSanitizer's own
# tracer crash, and fails on anything else: a real failure beside a crash, a crash that happens
# again, a crash signature without the fatal-error line. Each case is a scratch CMake project whose
# tests print what a crashed or failing test prints.
#
#   tests/ci/check_lsan_rerun.sh SOURCE_DIR SCRATCH_DIR
set -uo pipefail
source_dir="$1"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

crash="echo 'Tracer caught signal 11: addr=0x34b0 pc=0x7f sp=0x7f'; echo '==1==LeakSanitizer has encountered a fatal error.'; exit 1"
# project NAME TEST_SH...: a project whose tests run the given shell lines (test i: t$i.Name).
project() {
  local dir="$scratch/$1" i=0
  shift
  mkdir -p "$dir"
  {
    echo 'cmake_minimum_required(VERSION 3.20)'
    echo 'project(p NONE)'
    echo 'enable_testing()'
    for body in "$@"; do
      i=$((i + 1))
      printf 'add_test(NAME t%d.Name COMMAND sh -c [==[%s]==])\n' "$i" "$body"
    done
  } >"$dir/CMakeLists.txt"
  cmake -S "$dir" -B "$dir/build" >/dev/null || fail "$dir: configure"
}
# runs NAME: how many times each test ran, as "t1=N t2=M ...".
runs() { (cd "$scratch/$1" && for f in ran.*; do [ -f "$f" ] && printf '%s=%s ' "${f#ran.}" "$(wc -l <"$f")"; done); }
# Each test logs one line per run into ran.tI.
logged() { echo "echo x >> $scratch/$1/ran.$2; $3"; }

# 1. A crash that does not happen again: rerun once, pass.
project once "$(logged once t1 'exit 0')" \
  "$(logged once t2 "[ -f $scratch/once/ran.t2 ] && [ \$(wc -l < $scratch/once/ran.t2) -ge 2 ] && exit 0; $crash")"
"$source_dir/scripts/ctest_lsan_rerun" "$scratch/once/build" --parallel 2 >"$scratch/once.log" 2>&1
rc=$?
[ "$rc" -eq 0 ] || fail "a crash that did not recur: exit $rc, expected 0"
[ "$(runs once)" = "t1=1 t2=2 " ] || fail "a crash that did not recur: runs '$(runs once)', expected t1 once, t2 twice"
grep -q "t2.Name" "$scratch/once.log" || fail "the rerun does not name the crashed test"

# 2. A crash that recurs fails.
project twice "$(logged twice t1 "$crash")"
"$source_dir/scripts/ctest_lsan_rerun" "$scratch/twice/build" >"$scratch/twice.log" 2>&1 && fail "a crash that recurred passed"
[ "$(runs twice)" = "t1=2 " ] || fail "a recurring crash: runs '$(runs twice)', expected 2"

# 3. A real failure beside a crash fails at once, nothing reruns.
project real "$(logged real t1 "$crash")" "$(logged real t2 "echo 'Expected equality'; exit 1")"
"$source_dir/scripts/ctest_lsan_rerun" "$scratch/real/build" >"$scratch/real.log" 2>&1 && fail "a real failure passed"
[ "$(runs real)" = "t1=1 t2=1 " ] || fail "a real failure beside a crash: runs '$(runs real)', expected no rerun"

# 4. Half the signature (an ordinary segfault message) is a real failure.
project half "$(logged half t1 "echo 'Tracer caught signal 11'; exit 1")"
"$source_dir/scripts/ctest_lsan_rerun" "$scratch/half/build" >"$scratch/half.log" 2>&1 && fail "half the signature passed"
[ "$(runs half)" = "t1=1 " ] || fail "half the signature: runs '$(runs half)', expected no rerun"

# 5. The rerun keeps to the crashed test even when the caller selected others with -R.
project select "$(logged select t1 'exit 0')" \
  "$(logged select t2 "[ -f $scratch/select/ran.t2 ] && [ \$(wc -l < $scratch/select/ran.t2) -ge 2 ] && exit 0; $crash")" \
  "$(logged select t3 'exit 0')"
"$source_dir/scripts/ctest_lsan_rerun" "$scratch/select/build" -R 't[12]' >"$scratch/select.log" 2>&1 || fail "selection: exit non-zero"
[ "$(runs select)" = "t1=1 t2=2 " ] || fail "selection: runs '$(runs select)', expected t1 once, t2 twice, t3 never"

if [ "$failures" -ne 0 ]; then
  echo "$failures check(s) failed; logs in $scratch"
  exit 1
fi
echo "ctest_lsan_rerun: 5 cases as expected"
