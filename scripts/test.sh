#!/usr/bin/env bash
# Builds (scripts/setup.sh) and runs the tests.
#   scripts/test.sh            the quick suites (ctest label "unit")
#   scripts/test.sh --all      also the slow validations (label "slow"), at most 900 s per test
# Any other argument is passed to ctest, e.g. scripts/test.sh -R Hertz, scripts/test.sh -V.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
all=0
args=()
for a in "$@"; do
  case "$a" in
    --all) all=1 ;;
    *) args+=("$a") ;;
  esac
done

scripts/setup.sh

status=0
echo "== unit tests"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j2 -L unit "${args[@]}" || status=$?
if [[ $all -eq 1 ]]; then
  echo "== slow tests"
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j2 -L slow --timeout 900 "${args[@]}" || status=$?
fi
exit "$status"
