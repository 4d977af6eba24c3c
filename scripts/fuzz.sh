#!/usr/bin/env bash
# Fuzzes the input readers with libFuzzer (clang, AddressSanitizer + UndefinedBehaviorSanitizer):
#   scripts/fuzz.sh [SECONDS]     (default 60) shared between the targets of tests/fuzz:
#     fuzz_case   arbitrary bytes as a case file (parse, validate, sweep)
#     fuzz_set    --set overrides on the bundled examples
#     fuzz_table  arbitrary bytes as the CSV table of a table profile
# Builds build-fuzz (DYNCONTACT_FUZZ_BUILD_DIR), seeds each corpus (build-fuzz/corpus/<target>,
# kept between runs) from examples/ and fails on any crash, hang (10 s per input), leak or
# exception that is not an input error; the input is saved in build-fuzz/artifacts/.
# Installs clang and its libFuzzer runtime (Debian clang, libclang-rt-dev) when missing
# (DYNCONTACT_SKIP_APT=1: do not).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

SECONDS_TOTAL="${1:-60}"
BUILD_DIR="${DYNCONTACT_FUZZ_BUILD_DIR:-build-fuzz}"
JOBS="${DYNCONTACT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
TARGETS=(fuzz_case fuzz_set fuzz_table)
say() { printf 'fuzz: %s\n' "$*" >&2; }

# The project's packages (the libraries the targets link) with clang and libFuzzer.
DYNCONTACT_WITH_FUZZ=1 scripts/setup.sh --packages-only
command -v clang++ >/dev/null || { say "clang++ not found (apt-get install clang libclang-rt-dev)"; exit 1; }

if [[ ! -f "$BUILD_DIR/CMakeCache.txt" ]]; then
  mkdir -p "$BUILD_DIR"
  say "configuring $BUILD_DIR (clang, libFuzzer, address+undefined)"
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DDYNCONTACT_FUZZ=ON -DDYNCONTACT_SANITIZE=address,undefined -DDYNCONTACT_BUILD_TESTS=OFF \
    -DDYNCONTACT_BUILD_BENCH=OFF >"$BUILD_DIR/configure.log" 2>&1 || { cat "$BUILD_DIR/configure.log" >&2; exit 1; }
fi
cmake --build "$BUILD_DIR" -j"$JOBS" --target "${TARGETS[@]}" >"$BUILD_DIR/build.log" 2>&1 ||
  { grep -E -A5 'error' "$BUILD_DIR/build.log" | head -60 >&2; say "build failed (full log: $BUILD_DIR/build.log)"; exit 1; }

# Seeds: the bundled examples; --set assignments (first byte picks the example); tables.
seed() {  # seed TARGET NAME CONTENT
  mkdir -p "$BUILD_DIR/corpus/$1"
  printf '%b' "$3" >"$BUILD_DIR/corpus/$1/seed-$2"
}
mkdir -p "$BUILD_DIR/corpus/fuzz_case" "$BUILD_DIR/artifacts"
cp examples/*.json "$BUILD_DIR/corpus/fuzz_case/"
seed fuzz_set force '\x00normal.force=200'
seed fuzz_set grid '\x00grid={"nx":16,"ny":8,"extent":1.5}\nsolver.backend=native'
seed fuzz_set tangential '\x01tangential.force=[0.3,0]\nfriction.mu=0.5'
seed fuzz_set history '\x01tangential.history=[{"force":[1,0]},{"force":[2,0]}]'
seed fuzz_set friction '\x01friction={"law":"table","pressure":[0,1e9],"bound":[0,3e8]}'
seed fuzz_set rolling '\x03tangential.creepage=[1e-4,0]\ntangential.velocity=2'
seed fuzz_set sweep '\x05sweep={"dimensionless.gamma_bar":[0.1,0.5]}'
seed fuzz_set profile '\x00profile={"type":"ellipsoid","radius_x":0.01,"radius_y":0.03}'
seed fuzz_table xyh 'x,y,h\n0,0,1\n1,0,0\n0,1,0.5\n1,1,0.2\n'
seed fuzz_table xh '# a 2-D profile\nx,h\n-1,1\n0,0\n1,1\n'

per_target=$(( SECONDS_TOTAL / ${#TARGETS[@]} ))
(( per_target >= 1 )) || per_target=1
status=0
for t in "${TARGETS[@]}"; do
  say "$t for $per_target s"
  log="$BUILD_DIR/$t.log"
  if ! ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
      "$BUILD_DIR/bin/$t" "$BUILD_DIR/corpus/$t" -max_total_time="$per_target" -timeout=10 -rss_limit_mb=2048 \
      -max_len=16384 -artifact_prefix="$BUILD_DIR/artifacts/$t-" -print_final_stats=1 >"$log" 2>&1; then
    status=1
    say "$t FAILED (log: $log); the input:"
    grep -E 'Test unit written|ERROR|SUMMARY|fuzz:' "$log" | head -20 >&2
  else
    grep -E '^stat::number_of_executed_units|^Done' "$log" | head -2 | sed "s/^/fuzz: $t: /" >&2 || true
  fi
done
exit "$status"
