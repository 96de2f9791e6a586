#!/usr/bin/env bash
# Configure fails, naming what is missing, when a dependency of a default-on part (the Python
# module, the GUI) cannot be found, instead of dropping that part and its tests. CMake is told to
# act as if pybind11, then Qt 6, were not installed.
#
#   tests/ci/check_configure.sh SOURCE_DIR SCRATCH_DIR
set -uo pipefail
source_dir="$1"
scratch="$2"
failures=0
check() { # NAME EXPECTED_TEXT CMAKE_ARGS...
  local name="$1" expected="$2"
  shift 2
  rm -rf "$scratch/$name"
  cmake -S "$source_dir" -B "$scratch/$name" -G Ninja "$@" > "$scratch/$name.log" 2>&1
  local status=$?
  if [ "$status" -eq 0 ]; then
    echo "FAIL: configure passed without $name"
    failures=$((failures + 1))
  elif ! grep -q "$expected" "$scratch/$name.log"; then
    echo "FAIL: configure without $name failed without saying '$expected':"
    tail -5 "$scratch/$name.log"
    failures=$((failures + 1))
  else
    echo "ok: without $name configure stops: $(grep -m1 "$expected" "$scratch/$name.log" | sed 's/^ *//')"
  fi
  rm -rf "$scratch/$name"
}
mkdir -p "$scratch"
check pybind11 "need pybind11-dev" -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=TRUE
check Qt6 "the workbench needs Qt 6" -DCMAKE_DISABLE_FIND_PACKAGE_Qt6=TRUE
[ "$failures" -eq 0 ]
