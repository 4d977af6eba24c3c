#!/usr/bin/env bash
# scripts/bench.sh finite: times problem "finite" (examples/bench/finite-hemisphere-bench.json, a steel
# hemisphere on a steel half-space under P, Hertz for the pair) over body sizes and grids.
#   --dofs 10k,50k,200k     body sizes (about; the mesh's elements along each axis are chosen for them)
#   --grids 32,64           contact grids (n^2 over +-1.5 a)
#   --sparse-dofs 10k       bodies also solved in the sparse saddle form (Ipopt) on the first grid
#   --repeat 2              runs per point; the table shows medians (the machine may be shared)
# Columns: body dofs, grid, program, mesh, factorisation and solve seconds (the solve is the whole
# contact solve after the factorisation), the CPU seconds of the whole run (user + system, from
# /usr/bin/time: steadier than wall times on a shared machine), iterations, peak memory (max RSS),
# and the peak pressure's error against Hertz's p0.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
dofs="10k,50k,200k" grids="32,64" sparse_dofs="10k" repeat=2
while [[ $# -gt 0 ]]; do
  case "$1" in
    --dofs) dofs="${2:?--dofs needs a value}"; shift ;;
    --grids) grids="${2:?--grids needs a value}"; shift ;;
    --sparse-dofs) sparse_dofs="${2?--sparse-dofs needs a value}"; shift ;;
    --repeat) repeat="${2:?--repeat needs a value}"; shift ;;
    *) echo "bench finite: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done
[[ -x /usr/bin/time ]] || { echo "bench finite: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }
scripts/setup.sh
exe="$BUILD_DIR/bin/dyncontact"
case_file=examples/bench/finite-hemisphere-bench.json
# The case's constants (Hertz for the pair: E* = E / (2 (1 - nu^2)) for equal materials).
R=0.01 E=2.1e11 nu=0.3 P=3323.0
elements_for() {  # body size -> Gmsh elements along x, y, z of the hemisphere (measured: 11.2k, 52k dofs; 205k before the face was refined over the grid's disk)
  case "$1" in
    10k) echo "[8,8,4]" ;;
    50k) echo "[20,20,10]" ;;
    200k) echo "[33,33,16]" ;;
    *) echo "bench finite: unknown body size '$1' (10k, 50k, 200k)" >&2; exit 2 ;;
  esac
}
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : 0.5 * (v[NR / 2] + v[NR / 2 + 1]) }'; }

run_point() {  # size, grid n, program
  local size="$1" n="$2" program="$3" k
  local sets=(--set "fe_body.elements=$(elements_for "$size")" --set "grid.nx=$n" --set "grid.ny=$n"
              --set "normal.force=$P" --set "fe_body.program=$program")
  [[ $program == sparse ]] && sets+=(--set solver.backend=ipopt)
  : >"$out/runs"
  for ((k = 0; k < repeat; k++)); do
    rm -rf "$out/run"
    local status=0
    /usr/bin/time -f "%M %U %S" -o "$out/rss" "$exe" solve "$case_file" --out "$out/run" -q "${sets[@]}" || status=$?
    [[ $status -eq 0 ]] || echo "  (run exited with $status)" >&2
    local rss user sys
    read -r rss user sys < <(tail -n 1 "$out/rss")
    awk -v rss="$rss" -v cpu="$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')" -F'[:,]' '
      /"body_dofs"/ { dofs = $2 + 0 }
      /"mesh_time_s"/ { mesh = $2 + 0 }
      /"factorisation_time_s"/ { fact = $2 + 0 }
      /"max_pressure"/ && !p { p = $2 + 0 }
      /"iterations"/ && !it { it = $2 + 0 }
      /"time_s"/ { time = $2 + 0 }
      END { print dofs, mesh, fact, time - mesh - fact, it, rss / 1024, p, cpu }' "$out/run/summary.json" >>"$out/runs"
  done
  local col
  for col in 1 2 3 4 5 6 7 8; do awk -v c=$col '{ print $c }' "$out/runs" | median; done | tr '\n' ' ' |
    awk -v n="$n" -v program="$program" -v R=$R -v E=$E -v nu=$nu -v P=$P '{
      Es = E / (2 * (1 - nu * nu)); pi = atan2(0, -1)
      p0 = (6 * P * Es * Es / (pi * pi * pi * R * R)) ^ (1 / 3)
      printf "%8d  %3d^2  %-9s %7.2f %9.2f %9.2f %7.2f %6d %9.0f %+8.2f %%\n", $1, n, program, $2, $3, $4, $8, $5, $6, 100 * ($7 / p0 - 1)
    }'
}

echo "== finite contact: hemisphere R = $R m on the half-space, P = $P N (medians of $repeat runs)"
printf "%8s  %5s  %-9s %7s %9s %9s %7s %6s %9s %10s\n" dofs grid program mesh_s factor_s solve_s cpu_s iter rss_MB "p0-Hertz"
IFS=, read -ra size_list <<<"$dofs"
IFS=, read -ra grid_list <<<"$grids"
IFS=, read -ra sparse_list <<<"$sparse_dofs"
for size in "${size_list[@]}"; do
  for n in "${grid_list[@]}"; do run_point "$size" "$n" condensed; done
  for s in "${sparse_list[@]}"; do
    if [[ $s == "$size" ]]; then run_point "$size" "${grid_list[0]}" sparse; fi
  done
done
