#!/usr/bin/env bash
# Builds (scripts/setup.sh) and times the backends on a Hertz sphere: the normal problem,
# then the tangential shift (Cattaneo) and steady rolling on the same sphere.
#   scripts/bench.sh            normal: 32..512 (ipopt up to 128^2, nlopt up to 64^2);
#                               shift: 32..256; rolling: 32..256 (native and auto)
#   scripts/bench.sh --quick    32,64 for each
#   scripts/bench.sh dynamic    1000 steps of problem "dynamic": a sphere rolling on a 32^2 grid
#                               along x and diagonally (transient contact: the memory convected
#                               along x, and along x and y) and the 2-D cylinder on 200 strips (steady):
#                               ms per step, contact solves and Newton iterations per step
#   scripts/bench.sh peer [--repeat 3] [case.json...]
#                               the cases of examples/bench/ (Hertz 512^2 and 1024^2, the wheel/rail
#                               table at 23k/93k/372k elements, Spence 35 and 69 steps, the gap bank:
#                               measured wheel/rail 6k-372k, conformal band, two patches, rough
#                               sphere 512^2, sharp punch, cone) timed whole by dyncontact_peer_bench:
#                               time (median of the runs), iterations, alternations, error against
#                               the closed form, backend; exit 1 if any case did not converge or
#                               fell back from its first backend (docs/solvers.md); the
#                               gap bank of examples/bench/ (scripts/make_gap_bank.py) runs when named
#   scripts/bench.sh fft [--sizes 45,91,152,304,512]
#                               one operator apply on the FFT path (normal, 2x2 tangential, kappa B21)
#                               and its set-up on n x n grids, one thread (dyncontact_fft_bench)
#   scripts/bench.sh finite [--repeat 2] [--sparse-dofs 10k] [--dofs 10k,50k,200k] [--grids 32,64]
#                               problem "finite" (examples/bench/finite-hemisphere-bench.json): a hemisphere of
#                               about 10k, 50k and 200k dofs on a 32^2 and a 64^2 grid, condensed program
#                               (native), and the sparse saddle form (Ipopt) for the bodies of
#                               --sparse-dofs on 32^2: factorisation, solve, iterations, peak memory,
#                               p0 against Hertz (medians of --repeat runs; docs/finite.md)
# --sizes/--backends override the defaults; other arguments go to dyncontact_bench (e.g. --repeat 3, --force, --csv out/bench.csv).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
sizes="32,64,128,256,512"
shift_sizes="32,64,128,256"
rolling_sizes="32,64,128,256"
backends="native,ipopt,nlopt"
args=()
mode=static
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
           examples/bench/spence-69.json
           # the gap bank (scripts/make_gap_bank.py, docs/solvers.md "Real gaps")
           examples/bench/measured-wheel-rail-6k.json examples/bench/measured-wheel-rail-23k.json
           examples/bench/measured-wheel-rail-23k-force.json examples/bench/measured-wheel-rail-93k.json
           examples/bench/measured-wheel-rail-372k.json examples/bench/conformal-band.json
           examples/bench/two-patches.json examples/bench/rough-sphere-512.json
           examples/bench/flat-punch-sharp.json examples/bench/cone.json)
  fi
  # the gap bank's tables too large to commit (scripts/make_gap_bank.py; NumPy: Debian's python3)
  for c in "${cases[@]}"; do
    if [[ "$(basename "$c")" == rough-sphere-512.json && ! -f "$(dirname "$c")/rough-sphere-512.csv" ]]; then
      py=/usr/bin/python3; [[ -x $py ]] || py=python3
      "$py" scripts/make_gap_bank.py --only rough-sphere-512 --out "$(dirname "$c")" >/dev/null
    fi
  done
  echo "== peer cases (threads: ${DYNCONTACT_THREADS:-all cores})"
  exec "$peer" "${opts[@]}" "${cases[@]}"
fi
if [[ "${1:-}" == "fft" ]]; then
  shift
  scripts/setup.sh
  exec "$BUILD_DIR/bin/dyncontact_fft_bench" "$@"
fi
if [[ "${1:-}" == "finite" ]]; then
  shift
  exec scripts/bench_finite.sh "$@"
fi
while [[ $# -gt 0 ]]; do
  case "$1" in
    dynamic) mode=dynamic ;;
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
if [[ $mode == dynamic ]]; then
  out="$(mktemp -d)"
  trap 'rm -rf "$out"' EXIT
  run_dynamic() {  # label, example, overrides...
    local label="$1" example="$2"
    shift 2
    local sets=()
    for s in "$@"; do sets+=(--set "$s"); done
    "$BUILD_DIR/bin/dyncontact" solve "examples/$example.json" --out "$out/$example" -q --set output.plots=false "${sets[@]}"
    awk -v label="$label" -F'[:,]' '
      /"steps"/ && !steps { steps = $2 + 0 }
      /"time_s"/ { time = $2 + 0 }
      /"contact_solves"/ { solves = $2 + 0 }
      /"newton_iterations"/ { newton = $2 + 0 }
      END { printf "%-44s %5d steps  %7.2f ms/step  %5.2f contact solves/step  %5.2f Newton iterations/step  (%.2f s)\n",
                   label, steps, 1000 * time / steps, solves / steps, newton / steps, time }' "$out/$example/summary.json"
  }
  echo "== dynamic (1000 steps each)"
  run_dynamic "sphere rolling, 32^2, transient" bowling-ball grid.nx=32 grid.ny=32 contact_model=transient \
    time.dt=1e-4 time.t_end=0.1 'body.initial.omega=[0,27.5229,0]'
  run_dynamic "sphere rolling diagonally, 32^2, transient" bowling-ball grid.nx=32 grid.ny=32 contact_model=transient \
    time.dt=1e-4 time.t_end=0.1 'body.initial.velocity=[2.12132,2.12132,0]' 'body.initial.omega=[-19.4617,19.4617,0]'
  run_dynamic "2-D cylinder, 200 strips, steady" cylinder-dynamic-2d grid.nx=200 time.dt=0.005 time.t_end=5
  exit 0
fi
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
