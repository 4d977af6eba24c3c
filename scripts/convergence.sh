#!/usr/bin/env bash
# Grid convergence against the closed forms (issue 28's evidence): solves the bundled Hertz
# cases on a sequence of grids (the same extent, the element size halved and in between),
# reads each run's relative difference to the closed form from summary.json ("hertz"), fits
# the observed order of each quantity (least squares of log|error| against log h over the
# finer half of the grids), and sets a three-grid Richardson estimate (h, 2h, 4h, the observed
# order; and Roache's grid convergence index with a safety factor of 1.25) beside the true
# error. Writes OUT/convergence.tsv, OUT/richardson.tsv and a log-log figure per case
# (OUT/<case>.svg, gnuplot), prints the fitted orders.
#   scripts/convergence.sh [--out DIR]      (default out/convergence)
# Environment: DYNCONTACT_BUILD_DIR (default build).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
out=out/convergence
while [[ $# -gt 0 ]]; do
  case "$1" in
    --out) out="${2:?--out needs a folder}"; shift ;;
    *) echo "convergence: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done
DYNCONTACT_BUILD_TARGET=dyncontact DYNCONTACT_SKIP_PYTHON_INSTALL=1 scripts/setup.sh
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# case, dimension, grids (elements along x; 3-D: ny = nx)
cases=(
  "hertz-sphere 3 16 24 32 48 64 96 128 192 256"
  "hertz-ellipse 3 16 24 32 48 64 96 128 192 256"
  "hertz-cylinder-2d 2 32 48 64 96 128 192 256 384 512 768 1024 1536 2048"
)
for spec in "${cases[@]}"; do
  read -r name dim grids <<<"$spec"
  for n in $grids; do
    sets=(--set "grid.nx=$n" --set output.plots=false)
    [[ $dim == 3 ]] && sets+=(--set "grid.ny=$n")
    DYNCONTACT_THREADS=1 "$BUILD_DIR/bin/dyncontact" solve "examples/$name.json" --out "$work/$name-$n" -q "${sets[@]}" \
      >/dev/null || { echo "convergence: $name on $n elements did not solve" >&2; exit 1; }
  done
  echo "$name $grids" >>"$work/cases"
done

/usr/bin/env python3 - "$work" "$out" <<'PY'
import json, math, os, sys
work, out = sys.argv[1], sys.argv[2]
quantities = ["max_pressure", "approach", "contact_area"]
rows, rich, fits = [], [], []
for line in open(os.path.join(work, "cases")):
    name, *grids = line.split()
    grids = [int(g) for g in grids]
    data = {}
    for n in grids:
        s = json.load(open(os.path.join(work, f"{name}-{n}", "summary.json")))
        data[n] = (s["grid"]["dx"], s["hertz"]["relative_difference"], s)
    for q in quantities:
        if q not in data[grids[0]][1]:
            continue
        pts = [(data[n][0], abs(data[n][1][q])) for n in grids]
        for (n, (h, e)) in zip(grids, pts):
            rows.append((name, q, n, h, e))
        fine = [(math.log(h), math.log(e)) for h, e in pts[len(pts) // 2:] if e > 0]
        if len(fine) >= 2:
            mx = sum(x for x, _ in fine) / len(fine)
            my = sum(y for _, y in fine) / len(fine)
            slope = sum((x - mx) * (y - my) for x, y in fine) / sum((x - mx) ** 2 for x, _ in fine)
            fits.append((name, q, slope))
        # Three grids h, 2h, 4h among the runs: value = reference * (1 + relative difference).
        for n in grids:
            if n % 4 or n // 2 not in data or n // 4 not in data:
                continue
            ref = data[n][2]["hertz"][q]
            f, m, c = (ref * (1 + data[k][1][q]) for k in (n, n // 2, n // 4))
            d1, d2 = f - m, m - c
            true = abs(data[n][1][q])
            if d1 != 0 and d1 * d2 > 0 and abs(d2 / d1) > 1.0:
                p = math.log2(abs(d2 / d1))
                est = abs(d1) / (2 ** p - 1) / abs(f)
            else:
                p = float("nan")
                est = max(abs(d1), abs(d2)) / abs(f)  # not monotone: the band of the last two changes
            gci = 1.25 * est if not math.isnan(p) else est
            rich.append((name, q, n, true, est, gci, p))
with open(os.path.join(out, "convergence.tsv"), "w") as t:
    t.write("case\tquantity\tnx\th\trelative_error\n")
    for r in rows:
        t.write("%s\t%s\t%d\t%.6g\t%.6g\n" % r)
with open(os.path.join(out, "richardson.tsv"), "w") as t:
    t.write("case\tquantity\tnx\ttrue_error\trichardson\tgci_1.25\tobserved_order\n")
    for r in rich:
        t.write("%s\t%s\t%d\t%.3e\t%.3e\t%.3e\t%.2f\n" % r)
print("fitted orders (finer half of the grids):")
for name, q, p in fits:
    print(f"  {name:20s} {q:14s} {p:5.2f}")
print("three-grid estimates (estimate / true error):")
for name, q, n, true, est, gci, p in rich:
    ratio = est / true if true > 0 else float("inf")
    print(f"  {name:20s} {q:14s} nx {n:5d}  true {true:.2e}  Richardson {est:.2e} (x {ratio:.2f})  "
          f"GCI {gci:.2e} (x {gci / true if true > 0 else float('inf'):.2f})  order {p:.2f}")
PY

if command -v gnuplot >/dev/null 2>&1; then
  while read -r name _; do
    for q in max_pressure approach contact_area; do
      awk -F'\t' -v c="$name" -v q="$q" '$1 == c && $2 == q { print $4, $5 }' "$out/convergence.tsv" >"$work/$name-$q.dat"
    done
    plot=""
    for q in max_pressure approach contact_area; do
      [[ -s "$work/$name-$q.dat" ]] && plot+="${plot:+, }'$work/$name-$q.dat' with linespoints title '$q' noenhanced"
    done
    gnuplot <<EOF
set terminal svg size 640,480
set output '$out/$name.svg'
set logscale xy
set xlabel 'element size h (m)'
set ylabel 'relative error against the closed form'
set title '$name: grid convergence' noenhanced
set key left top
plot $plot
EOF
  done <"$work/cases"
fi
echo "wrote $out/convergence.tsv, $out/richardson.tsv and the figures $out/*.svg"
