#!/usr/bin/env bash
# Builds (scripts/setup.sh) and runs the bundled example, then says where the results
# and plots are. Extra arguments go to `dyncontact solve` (e.g. --set solver.backend=ipopt).
#
# The example is the paper's Section 5 problem (a cylinder under a driving moment, Figs 4-6,
# one run per rate of the moment). Any other case file can be put in EXAMPLE.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

EXAMPLE="examples/paper-cylinder.json"   # the paper's Section 5 cylinder (Figs 4-6)

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
# Only what this script runs: the program and the Python module (scripts/test.sh builds the tests).
DYNCONTACT_BUILD_TARGET=dyncontact_programs scripts/setup.sh

[[ -f "$EXAMPLE" ]] || { echo "run: error: $EXAMPLE not found" >&2; exit 1; }
name="$(basename "$EXAMPLE" .json)"
out="out/$name"

echo "\$ $BUILD_DIR/bin/dyncontact solve $EXAMPLE --out $out $*"
"$BUILD_DIR/bin/dyncontact" solve "$EXAMPLE" --out "$out" "$@"

echo
[[ -d "$out" ]] || { echo "run: error: $out was not written" >&2; exit 1; }
echo "Results: $out/"
[[ -f "$out/summary.json" ]] && echo "  summary: $out/summary.json"
mapfile -t tables < <(find "$out" -maxdepth 2 -type f -name '*.csv' | sort)
mapfile -t plots < <(find "$out" -maxdepth 2 -type f \( -name '*.svg' -o -name '*.png' \) | sort)
if [[ ${#tables[@]} -gt 0 ]]; then
  echo "  data:"
  printf '    %s\n' "${tables[@]}"
fi
if [[ ${#plots[@]} -gt 0 ]]; then
  echo "  plots:"
  printf '    %s\n' "${plots[@]}"
else
  echo "  plots: none written (gnuplot missing or plots disabled in the case)"
fi
