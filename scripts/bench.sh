#!/usr/bin/env bash
# Builds (scripts/setup.sh) and times the backends on a Hertz sphere: the normal problem,
# then the tangential shift (Cattaneo) and steady rolling on the same sphere.
#   scripts/bench.sh            normal: 32..512 (ipopt up to 128^2, nlopt up to 64^2);
#                               shift: 32..256; rolling: 32..256 (native and auto)
#   scripts/bench.sh --quick    32,64 for each
#   scripts/bench.sh peer [--repeat 3] [case.json...]
#                               the cases of examples/bench/ (Hertz 512^2 and 1024^2, the wheel/rail
#                               table at 23k/93k/372k elements, Spence 35 and 69 steps) timed whole by
#                               dyncontact_peer_bench: time (median of the runs), iterations,
#                               alternations, error against the closed form (docs/solvers.md)
# --sizes/--backends override the defaults; other arguments go to dyncontact_bench (e.g. --repeat 3, --force, --csv out/bench.csv).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
sizes="32,64,128,256,512"
shift_sizes="32,64,128,256"
rolling_sizes="32,64,128,256"
backends="native,ipopt,nlopt"
args=()
if [[ "${1:-}" == "peer" ]]; then
  shift
  scripts/setup.sh
  peer="$BUILD_DIR/bin/dyncontact_peer_bench"
  [[ -x "$peer" ]] || { echo "bench: $peer missing (configured with -DDYNCONTACT_BUILD_BENCH=OFF?)" >&2; exit 1; }
  cases=() opts=()
  for a in "$@"; do
    if [[ "$a" == *.json ]]; then cases+=("$a"); else opts+=("$a"); fi
  done
  [[ -f examples/bench/wheel-rail-profile.csv ]] || scripts/make_wheel_rail.sh >/dev/null
  if [[ ${#cases[@]} -eq 0 ]]; then
    cases=(examples/bench/hertz-512.json examples/bench/hertz-1024.json examples/bench/wheel-rail-23k.json
           examples/bench/wheel-rail-93k.json examples/bench/wheel-rail-372k.json examples/bench/spence-35.json
           examples/bench/spence-69.json)
  fi
  echo "== peer cases (threads: ${DYNCONTACT_THREADS:-all cores})"
  exec "$peer" "${opts[@]}" "${cases[@]}"
fi
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) sizes="32,64"; shift_sizes="32,64"; rolling_sizes="32,64" ;;
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
bench="$BUILD_DIR/bin/dyncontact_bench"
echo "== normal contact"
"$bench" --backends "$backends" --sizes "$sizes" "${args[@]}"
echo; echo "== tangential shift (Cattaneo, Q = mu P / 2)"
"$bench" --problem shift --backends native,auto --sizes "$shift_sizes" "${args[@]}"
echo; echo "== steady rolling (F = mu P / 2)"
"$bench" --problem rolling --backends native --sizes "$rolling_sizes" "${args[@]}"
