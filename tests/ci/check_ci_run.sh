#!/usr/bin/env bash
# .ci/run stops with a non-zero exit when any of its steps fails, and runs the README's second
# command as written there. The real .ci/run runs in a scratch folder where each step it calls
# (scripts/bootstrap, cmake, ctest, scripts/check_includes, scripts/check_architecture, scripts/check_format,
# scripts/check_sizes, scripts/check_docs, scripts/sanitize,
# scripts/fuzz) is a stand-in that logs its call and fails when told to; scripts/ci_plant shows the
# same on a real build with a planted compile error and a planted failing test.
#
#   tests/ci/check_ci_run.sh SOURCE_DIR SCRATCH_DIR
set -uo pipefail
source_dir="$1"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch/tree/.ci" "$scratch/tree/scripts" "$scratch/bin"
cp "$source_dir/.ci/run" "$scratch/tree/.ci/run"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The README's second command must be in .ci/run as written (what a new user types is what CI runs).
readme_command=$(grep -m2 -A1 '^```sh' "$source_dir/README.md" | grep -v '^```sh' | grep -v '^--' | sed -n 2p)
case "$readme_command" in
  *"ctest --preset default"*) ;;
  *) fail "could not find the README's test command (found: '$readme_command')" ;;
esac
if ! grep -qF -- "$readme_command" "$source_dir/.ci/run"; then
  fail ".ci/run does not run the README's test command: $readme_command"
fi

# One stand-in per step: it appends its name to the log and exits 1 when STEP_TO_FAIL names it.
stand_in() {
  local path="$1" name="$2"
  cat > "$path" <<STUB
#!/usr/bin/env bash
echo "$name" >> "\$CI_LOG"
[ "\${STEP_TO_FAIL:-}" = "$name" ] && exit 1
exit 0
STUB
  chmod +x "$path"
}
# cmake is called twice (configure, then --build): name the two calls apart.
cat > "$scratch/bin/cmake" <<'STUB'
#!/usr/bin/env bash
name=configure
[ "${1:-}" = "--build" ] && name=build
echo "$name" >> "$CI_LOG"
[ "${STEP_TO_FAIL:-}" = "$name" ] && exit 1
exit 0
STUB
chmod +x "$scratch/bin/cmake"
stand_in "$scratch/bin/ctest" ctest
for step in bootstrap check_includes check_architecture check_format check_sizes check_docs sanitize fuzz; do
  stand_in "$scratch/tree/scripts/$step" "$step"
done

steps=(bootstrap configure build ctest check_includes check_architecture check_format check_sizes check_docs sanitize fuzz)
run_ci() { # STEP_TO_FAIL (or empty) -> exit code; the log in $scratch/log
  : > "$scratch/log"
  CI_LOG="$scratch/log" STEP_TO_FAIL="$1" PATH="$scratch/bin:$PATH" bash "$scratch/tree/.ci/run" > "$scratch/out" 2>&1
}

run_ci ""
status=$?
[ "$status" -eq 0 ] || fail "with every step passing .ci/run exited $status"
[ "$(tr '\n' ' ' < "$scratch/log")" = "${steps[*]} " ] || fail "with every step passing it ran: $(tr '\n' ' ' < "$scratch/log")"

for index in "${!steps[@]}"; do
  step="${steps[$index]}"
  run_ci "$step"
  status=$?
  ran=$(tr '\n' ' ' < "$scratch/log")
  expected="${steps[*]:0:$((index + 1))} "
  if [ "$status" -eq 0 ]; then
    fail "a failing $step left .ci/run exiting 0 (ran: $ran)"
  elif [ "$ran" != "$expected" ]; then
    fail "a failing $step: expected the run to stop after it; it ran: $ran"
  else
    echo "ok: a failing $step stops .ci/run with exit $status after: $ran"
  fi
done
[ "$failures" -eq 0 ] || exit 1
echo "ok: .ci/run runs the README's command and stops on each of its ${#steps[@]} steps"
