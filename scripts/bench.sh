#!/usr/bin/env bash
# Builds (scripts/setup.sh) and times the normal-contact backends on a Hertz sphere.
#   scripts/bench.sh            sizes 32,64,128,256,512 (ipopt up to 128^2, nlopt up to 64^2)
#   scripts/bench.sh --quick    sizes 32,64
# --sizes/--backends override the defaults; other arguments go to dyncontact_bench (e.g. --repeat 3, --force, --csv out/bench.csv).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
sizes="32,64,128,256,512"
backends="native,ipopt,nlopt"
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) sizes="32,64" ;;
    --sizes) sizes="${2:?--sizes needs a value}"; shift ;;
    --sizes=*) sizes="${1#--sizes=}" ;;
    --backends) backends="${2:?--backends needs a value}"; shift ;;
    --backends=*) backends="${1#--backends=}" ;;
    *) args+=("$1") ;;
  esac
  shift
done

scripts/setup.sh
[[ -x "$BUILD_DIR/bin/dyncontact_bench" ]] || {
  echo "bench: $BUILD_DIR/bin/dyncontact_bench missing (configured with -DDYNCONTACT_BUILD_BENCH=OFF?)" >&2
  exit 1
}
exec "$BUILD_DIR/bin/dyncontact_bench" --backends "$backends" --sizes "$sizes" "${args[@]}"
