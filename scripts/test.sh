#!/usr/bin/env bash
# Builds and runs the tests.
#   scripts/test.sh              the quick suites (ctest label "unit"), Release build in build/
#   scripts/test.sh --all        also the slow validations (label "slow"), at most 900 s per test,
#                                and the dynamic step's work against docs/dynamic-bench.tsv
#                                (scripts/bench.sh dynamic --steps 200 --check: fails when contact
#                                solves or alternations per step rise above the recorded ones)
#   scripts/test.sh --sanitize   only the unit suites built with AddressSanitizer and
#                                UndefinedBehaviorSanitizer (build-sanitize/; any report fails)
#   scripts/test.sh --fuzz S     only the fuzz targets for S seconds in total (scripts/fuzz.sh)
# Options combine (the parts run in the order --all, --sanitize, --fuzz).
# Any other argument is passed to ctest, e.g. scripts/test.sh -R Hertz, scripts/test.sh -V.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
SANITIZE_DIR="${DYNCONTACT_SANITIZE_BUILD_DIR:-build-sanitize}"
JOBS="${DYNCONTACT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
all=0 sanitize=0 fuzz_seconds=""
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --all) all=1 ;;
    --sanitize) sanitize=1 ;;
    --fuzz) fuzz_seconds="${2:?--fuzz needs a number of seconds}"; shift ;;
    *) args+=("$1") ;;
  esac
  shift
done
release=1
if [[ $all -eq 0 && ( $sanitize -eq 1 || -n "$fuzz_seconds" ) ]]; then release=0; fi

status=0
if [[ $release -eq 1 ]]; then
  scripts/setup.sh
  echo "== unit tests"
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j2 -L unit "${args[@]}" || status=$?
  if [[ $all -eq 1 ]]; then
    echo "== slow tests"
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j2 -L slow --timeout 900 "${args[@]}" || status=$?
    scripts/bench.sh dynamic --steps 200 --check || status=$?
  fi
fi

if [[ $sanitize -eq 1 ]]; then
  echo "== unit tests under AddressSanitizer + UndefinedBehaviorSanitizer ($SANITIZE_DIR)"
  scripts/setup.sh --packages-only
  if [[ ! -f "$SANITIZE_DIR/CMakeCache.txt" ]]; then
    mkdir -p "$SANITIZE_DIR"
    # -O1, as AddressSanitizer advises, and without UBSan's alignment and null checks: gcc took
    # 3 x longer with them on Eigen-heavy sources (a null dereference still faults under ASan).
    cmake -S . -B "$SANITIZE_DIR" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O1 \
      -DDYNCONTACT_SANITIZE=address,undefined -DDYNCONTACT_SANITIZE_SKIP=alignment,null \
      -DDYNCONTACT_BUILD_BENCH=OFF >"$SANITIZE_DIR/configure.log" 2>&1 ||
      { cat "$SANITIZE_DIR/configure.log" >&2; exit 1; }
  fi
  if ! cmake --build "$SANITIZE_DIR" -j"$JOBS" >"$SANITIZE_DIR/build.log" 2>&1; then
    grep -E -B2 -A8 '(error|undefined reference)' "$SANITIZE_DIR/build.log" | head -100 >&2
    echo "sanitizer build failed (full log: $SANITIZE_DIR/build.log)" >&2
    exit 1
  fi
  # Every report is fatal (the test or the program it runs fails); leaks included.
  # Gmsh's own end-of-process allocations are suppressed (tests/sanitizer/lsan.supp).
  ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0" \
  LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0" \
  UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1" \
    ctest --test-dir "$SANITIZE_DIR" --output-on-failure -j2 -L unit --timeout 900 "${args[@]}" || status=$?
fi

if [[ -n "$fuzz_seconds" ]]; then
  echo "== fuzzing for $fuzz_seconds s"
  scripts/fuzz.sh "$fuzz_seconds" || status=$?
fi
exit "$status"
