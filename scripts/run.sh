#!/usr/bin/env bash
# Builds (scripts/setup.sh) and runs the bundled example, then says where the results
# and plots are. Extra arguments go to `dyncontact solve` (e.g. --set solver.backend=ipopt).
#
# The example is the paper's Section 5 problem once the dynamics lands; until then it is
# the Hertz sphere (normal contact). To switch, change EXAMPLE below, nothing else.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

EXAMPLE="examples/hertz-sphere.json"   # later: the paper's Section 5 case (problem "paper_cylinder")

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
scripts/setup.sh

[[ -f "$EXAMPLE" ]] || { echo "run: error: $EXAMPLE not found" >&2; exit 1; }
name="$(basename "$EXAMPLE" .json)"
out="out/$name"

if ! grep -Eq '"problem"[[:space:]]*:[[:space:]]*"paper_cylinder"' "$EXAMPLE"; then
  cat <<EOF
Note: the paper's Section 5 example (massive cylinder on a half-plane, Figs 4-6) needs the
dynamics, which is not finished yet. Running the static normal-contact example
$EXAMPLE instead.

EOF
fi

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
