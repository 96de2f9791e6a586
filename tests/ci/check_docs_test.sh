#!/usr/bin/env bash
# scripts/check_docs fails when a generated doc's inputs changed since it was stamped, and names the
# doc and the command that regenerates it; it passes on a freshly stamped doc, and fails on an
# unstamped one and on a manifest glob that matches nothing.
#
#   tests/ci/check_docs_test.sh SOURCE_DIR SCRATCH_DIR
set -euo pipefail
source_dir="$1"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch/scripts" "$scratch/docs" "$scratch/src"
cp "$source_dir/scripts/check_docs" "$scratch/scripts/"
cd "$scratch"
git init -q .
echo "int measured() { return 1; }" > src/measured.cpp
echo "# A table" > docs/table.md
cat > docs/inputs.json <<'JSON'
{"docs/table.md": {"command": "scripts/make_table", "inputs": ["src/*.cpp"]}}
JSON
failures=0
expect() { # EXIT_CODE DESCRIPTION -- command; the output in $scratch/out
  local want="$1" what="$2"
  shift 2
  local got=0
  "$@" > out 2>&1 || got=$?
  if [ "$got" != "$want" ]; then echo "FAIL: $what: exit $got, expected $want"; cat out; failures=$((failures + 1)); else echo "ok: $what"; fi
}
expect 1 "an unstamped doc fails" scripts/check_docs
grep -q "docs/table.md has no inputs stamp; regenerate it with: scripts/make_table" out || { echo "FAIL: message"; cat out; failures=$((failures + 1)); }
expect 0 "stamping works" scripts/check_docs --stamp docs/table.md
expect 0 "a freshly stamped doc passes" scripts/check_docs
expect 0 "stamping again keeps one stamp" scripts/check_docs --stamp docs/table.md
[ "$(grep -c 'inputs sha256' docs/table.md)" = 1 ] || { echo "FAIL: two stamps"; failures=$((failures + 1)); }
echo "int measured() { return 2; }" > src/measured.cpp
expect 1 "a changed input fails" scripts/check_docs
grep -q "docs/table.md is stale" out && grep -q "regenerate it with: scripts/make_table" out ||
  { echo "FAIL: stale message"; cat out; failures=$((failures + 1)); }
echo "int more() { return 3; }" > src/new.cpp
scripts/check_docs --stamp docs/table.md > /dev/null
expect 0 "a new input file counts once stamped" scripts/check_docs
rm src/new.cpp
expect 1 "a removed input file fails" scripts/check_docs
cat > docs/inputs.json <<'JSON'
{"docs/table.md": {"command": "scripts/make_table", "inputs": ["nothing/*.cpp"]}}
JSON
expect 1 "a glob matching nothing fails" scripts/check_docs
[ "$failures" = 0 ]
