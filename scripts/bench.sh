#!/usr/bin/env bash
# Builds (scripts/setup.sh) and times the backends on a Hertz sphere: the normal problem,
# then the tangential shift (Cattaneo) and steady rolling on the same sphere.
#   scripts/bench.sh            normal: 32..512 (ipopt up to 128^2, nlopt up to 64^2);
#                               shift: 32..256; rolling: 32..256 (native and auto)
#   scripts/bench.sh --quick    32,64 for each
#   scripts/bench.sh dynamic [--steps 1000] [--check]
#                               problem "dynamic", one thread: a sphere rolling on a 32^2 grid
#                               along x and diagonally (transient contact: the memory convected
#                               along x, and along x and y, kappa != 0), the same sphere on equal
#                               materials (kappa = 0), the sphere on a 64^2 grid and the 2-D
#                               cylinder on 200 strips (steady):
#                               ms, contact solves, (p, tau) alternations and Newton iterations
#                               per step, and the counts of the run's second half (the start-up
#                               transient over; from timeseries.csv), against the figures recorded
#                               in docs/dynamic-bench.tsv
#                               (the rows of the same case and step count). --check: exit 1 when
#                               solves or alternations per step (the run's or its second half's)
#                               exceed the recorded ones by more than 0.02 (the counts are the machine's; the times are not, and
#                               only fail beyond 1.5 x with --check-time)
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
#   scripts/bench.sh subsurface [--sizes 64,128,256] [--repeat 5] [--depths 32]
#                               one thread: one normal solve (set-up and solve, native) of the Hertz
#                               sphere and the subsurface field of one body from its pressure at 32
#                               depths to 1.5 a with the measures (von Mises, Tresca, hydrostatic,
#                               |sigma_xz| and their extremes), thread CPU time, medians of the
#                               repeats, and their ratio (dyncontact_subsurface_bench;
#                               docs/subsurface.md "Speed")
#   scripts/bench.sh finite [--repeat 2] [--sparse-dofs 10k] [--dofs 10k,50k,200k] [--grids 32,64]
#                               problem "finite" (examples/bench/finite-hemisphere-bench.json): a hemisphere of
#                               about 10k, 50k and 200k dofs on a 32^2 and a 64^2 grid, condensed program
#                               (native), and the sparse saddle form (Ipopt) for the bodies of
#                               --sparse-dofs on 32^2: factorisation, solve, iterations, peak memory,
#                               p0 against Hertz (medians of --repeat runs; docs/finite.md)
#   scripts/bench.sh wear       one thread: 1e5 fretting cycles of a 64^2 sphere with cycle jumping
#                               (examples/bench/fretting-sphere-wear.json): time, profile updates,
#                               worn depth and volume; exit 1 beyond 60 s (docs/wear_energy.md "Wear");
#                               then one rolling pass with wear update of a 64^2 sphere
#                               (examples/bench/rolling-sphere-wear.json, the mean of 20 passes)
#                               against one steady rolling solve of the same case: exit 1 beyond 2x
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
dyn_steps=1000 dyn_check=""
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
if [[ "${1:-}" == "subsurface" ]]; then
  shift
  scripts/setup.sh
  DYNCONTACT_THREADS=1 exec "$BUILD_DIR/bin/dyncontact_subsurface_bench" "$@"
fi
if [[ "${1:-}" == "wear" ]]; then
  DYNCONTACT_BUILD_TARGET=dyncontact DYNCONTACT_SKIP_PYTHON_INSTALL=1 scripts/setup.sh
  out="$(mktemp -d)"
  trap 'rm -rf "$out"' EXIT
  start=$(date +%s.%N)
  DYNCONTACT_THREADS=1 "$BUILD_DIR/bin/dyncontact" solve examples/bench/fretting-sphere-wear.json --out "$out/wear" -q >/dev/null
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
  /usr/bin/env python3 - "$out/wear/summary.json" "$seconds" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))["wear"]
print(f"fretting-sphere-wear 64^2: {w['cycles']} cycles in {sys.argv[2]} s, {w['updates']} profile updates, "
      f"max depth {w['base']['max_depth']:.3g} m, volume {w['base']['volume']:.3g} m^3 per body")
PY
  awk -v s="$seconds" 'BEGIN { exit !(s <= 60) }' || { echo "bench: wear took $seconds s (target <= 60 s)" >&2; exit 1; }
  # One rolling pass with wear update (its steady solve on the worn gap, the row integrals, the gap
  # update: wear.history's time_s) against the steady solve of the case without its wear block.
  rolling=examples/bench/rolling-sphere-wear.json
  /usr/bin/env python3 -c 'import json, sys; c = json.load(open(sys.argv[1])); del c["wear"]; json.dump(c, open(sys.argv[2], "w"))' \
    "$rolling" "$out/rolling-plain.json"
  DYNCONTACT_THREADS=1 "$BUILD_DIR/bin/dyncontact" solve "$rolling" --out "$out/rolling-wear" -q >/dev/null
  DYNCONTACT_THREADS=1 "$BUILD_DIR/bin/dyncontact" solve "$out/rolling-plain.json" --out "$out/rolling-plain" -q >/dev/null
  /usr/bin/env python3 - "$out/rolling-wear/summary.json" "$out/rolling-plain/summary.json" <<'PY'
import json, sys
h = json.load(open(sys.argv[1]))["wear"]["history"]
plain = json.load(open(sys.argv[2]))["solver"]["time_s"]
per_pass = sum(u["time_s"] for u in h) / len(h)
ratio = per_pass / plain
print(f"rolling-sphere-wear 64^2: one pass with wear update {per_pass:.3f} s (mean of {len(h)}; first {h[0]['time_s']:.3f} s), "
      f"steady rolling solve {plain:.3f} s: ratio {ratio:.2f} (target <= 2)")
sys.exit(0 if ratio <= 2.0 else 1)
PY
  exit 0
fi
if [[ "${1:-}" == "finite" ]]; then
  shift
  exec scripts/bench_finite.sh "$@"
fi
while [[ $# -gt 0 ]]; do
  case "$1" in
    dynamic) mode=dynamic ;;
    --steps) dyn_steps="${2:?--steps needs a number}"; shift ;;
    --check) dyn_check=counts ;;
    --check-time) dyn_check=time ;;
    --quick) sizes="32,64"; shift_sizes="32,64"; rolling_sizes="32,64" ;;
    --sizes) sizes="${2:?--sizes needs a value}"; shift ;;
    --sizes=*) sizes="${1#--sizes=}" ;;
    --backends) backends="${2:?--backends needs a value}"; shift ;;
    --backends=*) backends="${1#--backends=}" ;;
    *) args+=("$1") ;;
  esac
  shift
done

if [[ $mode == dynamic ]]; then
  DYNCONTACT_BUILD_TARGET=dyncontact DYNCONTACT_SKIP_PYTHON_INSTALL=1 scripts/setup.sh
  out="$(mktemp -d)"
  trap 'rm -rf "$out"' EXIT
  recorded=docs/dynamic-bench.tsv
  failed=0
  run_case() {  # steps, example, dt, overrides...: the output folder, or nothing when the run failed
    local steps="$1" example="$2" dt="$3"
    shift 3
    local sets=(--set "time.dt=$dt" --set "time.t_end=$(awk -v n="$steps" -v dt="$dt" 'BEGIN { printf "%.12g", n * dt }')")
    for s in "$@"; do sets+=(--set "$s"); done
    DYNCONTACT_THREADS=1 "$BUILD_DIR/bin/dyncontact" solve "examples/$example.json" --out "$out/$example-$steps" -q \
      --set output.plots=false "${sets[@]}" >/dev/null && echo "$out/$example-$steps"
  }
  run_dynamic() {  # label, example, dt, overrides...
    local label="$1" example="$2" dt="$3"
    shift 3
    local run
    run="$(run_case "$dyn_steps" "$example" "$dt" "$@")" || { echo "bench: $label did not complete" >&2; failed=1; return; }
    # steps, ms/step, solves/step, alternations/step, Newton/step, sensitivities/step; then the
    # second half's solves/step and alternations/step (the start-up transient over: each step's
    # counts in timeseries.csv; its time is not measured apart, the run's is one process's)
    local row
    row="$(/usr/bin/env python3 - "$run" <<'PY'
import csv, json, sys
d = json.load(open(sys.argv[1] + "/summary.json")); s = d["solver"]; n = d["steps"]
rows = list(csv.DictReader(open(sys.argv[1] + "/" + d["timeseries"])))[n // 2:]
m = max(len(rows), 1)
print(n, 1000 * s["time_s"] / n, s["contact_solves"] / n, s.get("outer_iterations", 0) / n,
      (s["newton_iterations"] + s.get("chord_steps", 0)) / n, s.get("sensitivities", 0) / n,
      sum(int(r["contact_solves"]) for r in rows) / m, sum(int(r["alternations"]) for r in rows) / m)
PY
)"
    read -r steps ms solves outer newton sens solves2 outer2 <<<"$row"
    printf "%-44s %5d steps %7.2f ms/step %5.2f solves/step %5.2f alternations/step %5.2f Newton updates/step %5.2f sensitivities/step\n" \
      "$label" "$steps" "$ms" "$solves" "$outer" "$newton" "$sens"
    printf "    second half (steps %d-%d): %5.2f solves/step %5.2f alternations/step\n" \
      $((steps / 2 + 1)) "$steps" "$solves2" "$outer2"
    [[ -f $recorded ]] || return 0
    local ref
    ref="$(awk -F'\t' -v c="$label" -v n="$steps" '$1 == c && $2 == n { print $3, $4, $5, $6, $7 }' "$recorded")"
    if [[ -z $ref ]]; then echo "    (no figures recorded for $steps steps in $recorded)"; return 0; fi
    read -r ref_ms ref_solves ref_outer ref_solves2 ref_outer2 <<<"$ref"
    local verdict
    if ! verdict="$(awk -v ms="$ms" -v s="$solves" -v o="$outer" -v s2="$solves2" -v o2="$outer2" -v rms="$ref_ms" \
        -v rs="$ref_solves" -v ro="$ref_outer" -v rs2="${ref_solves2:-}" -v ro2="${ref_outer2:-}" -v check="$dyn_check" 'BEGIN {
      bad = 0
      if (s > rs + 0.02) { printf "    MORE SOLVES: %.2f per step, recorded %.2f\n", s, rs; bad = 1 }
      if (o > ro + 0.02) { printf "    MORE ALTERNATIONS: %.2f per step, recorded %.2f\n", o, ro; bad = 1 }
      if (rs2 != "" && s2 > rs2 + 0.02) { printf "    MORE SOLVES IN THE SECOND HALF: %.2f per step, recorded %.2f\n", s2, rs2; bad = 1 }
      if (ro2 != "" && o2 > ro2 + 0.02) { printf "    MORE ALTERNATIONS IN THE SECOND HALF: %.2f per step, recorded %.2f\n", o2, ro2; bad = 1 }
      if (ms > 1.5 * rms) { printf "    SLOWER: %.2f ms per step, recorded %.2f (x %.2f)\n", ms, rms, ms / rms; if (check == "time") bad = 1 }
      else printf "    recorded: %.2f ms/step (x %.2f), %.2f solves/step, %.2f alternations/step\n", rms, ms / rms, rs, ro
      exit bad }')"; then
      [[ -z $dyn_check ]] || failed=1
    fi
    echo "$verdict"
  }
  echo "== dynamic ($dyn_steps steps each, one thread; recorded figures: $recorded)"
  run_dynamic "sphere rolling, 32^2, transient" bowling-ball 1e-4 grid.nx=32 grid.ny=32 contact_model=transient \
    'body.initial.omega=[0,27.5229,0]'
  run_dynamic "sphere rolling diagonally, 32^2, transient" bowling-ball 1e-4 grid.nx=32 grid.ny=32 \
    contact_model=transient 'body.initial.velocity=[2.12132,2.12132,0]' 'body.initial.omega=[-19.4617,19.4617,0]'
  run_dynamic "sphere rolling, 32^2, transient, kappa = 0" bowling-ball 1e-4 grid.nx=32 grid.ny=32 \
    contact_model=transient 'body.initial.omega=[0,27.5229,0]' materials.base.E=2.0e9 materials.base.nu=0.4
  run_dynamic "sphere rolling, 64^2, transient" bowling-ball 1e-4 grid.nx=64 grid.ny=64 contact_model=transient \
    'body.initial.omega=[0,27.5229,0]'
  run_dynamic "2-D cylinder, 200 strips, steady" cylinder-dynamic-2d 0.005 grid.nx=200
  exit "$failed"
fi
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
