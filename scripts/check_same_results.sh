#!/usr/bin/env bash
# Behaviour unchanged, shown: solves every bundled example (examples/*.json) with the program
# built from BASE_REF and with this checkout's, and compares summary.json (timings aside) and
# the CSV/.dat files (scripts/compare_outputs.py). Exit 1 on any difference.
#   scripts/check_same_results.sh BASE_REF [--rel 1e-12]
# Environment: DYNCONTACT_BUILD_DIR (this checkout's build, default build), DYNCONTACT_BASE_BINARY
# (a program already built from BASE_REF: skips building it), DYNCONTACT_JOBS.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
base_ref="${1:?usage: scripts/check_same_results.sh BASE_REF [--rel REL]}"; shift
BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
JOBS="${DYNCONTACT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
work="$(mktemp -d "${TMPDIR:-/tmp}/dyncontact-same.XXXXXX")"
cleanup() {
  if [[ -d "$work/base" ]]; then git worktree remove --force "$work/base" >/dev/null 2>&1 || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

new_bin="$BUILD_DIR/bin/dyncontact"
DYNCONTACT_BUILD_TARGET=dyncontact DYNCONTACT_SKIP_PYTHON_INSTALL=1 scripts/setup.sh
base_bin="${DYNCONTACT_BASE_BINARY:-}"
if [[ -z "$base_bin" ]]; then
  git worktree add --detach "$work/base" "$base_ref" >/dev/null
  echo "building $base_ref in $work/base" >&2
  cmake -S "$work/base" -B "$work/base/build" -DCMAKE_BUILD_TYPE=Release -DDYNCONTACT_BUILD_TESTS=OFF \
    -DDYNCONTACT_BUILD_BENCH=OFF >"$work/base-configure.log" 2>&1
  cmake --build "$work/base/build" -j"$JOBS" --target dyncontact >"$work/base-build.log" 2>&1 ||
    { tail -30 "$work/base-build.log" >&2; exit 1; }
  base_bin="$work/base/build/bin/dyncontact"
fi

status=0
for example in examples/*.json; do
  name="$(basename "$example" .json)"
  # One thread each: the same order of sums in both runs.
  DYNCONTACT_THREADS=1 "$base_bin" solve "$example" --out "$work/old/$name" --set output.plots=false \
    >/dev/null 2>"$work/$name.old.err" || true
  DYNCONTACT_THREADS=1 "$new_bin" solve "$example" --out "$work/new/$name" --set output.plots=false \
    >/dev/null 2>"$work/$name.new.err" || true
  if diff_out="$(python3 scripts/compare_outputs.py "$work/old/$name" "$work/new/$name" "$@")"; then
    echo "same: $name"
  else
    status=1
    echo "DIFFERENT: $name"
    printf '%s\n' "$diff_out" | head -20 | sed 's/^/  /'
  fi
done
exit "$status"
