#!/usr/bin/env bash
# Grid convergence against the closed forms (issue 28, docs/accuracy.md): solves the Hertz
# sphere, ellipse and line contact, Carter's rolling cylinder, Cattaneo's shifted sphere, Kalker's
# rolling sphere (C11) and Spence's frictional indentation (stick ratio) on a
# sequence of grids (the same extent, the element size halved and in between), takes each run's
# relative difference to its closed form (summary.json "hertz"; Carter's creepage and Mindlin's
# shift computed here), fits the observed order of each quantity (least squares of log|error|
# against log h over the finer half of the grids), and sets the program's own error estimate
# (summary.json "accuracy") beside the true error. Writes OUT/convergence.tsv, OUT/orders.tsv,
# OUT/estimates.tsv and a log-log figure per case with the fitted orders (OUT/<case>.svg,
# gnuplot); prints the orders and how often the estimate is within 1-3x the true error.
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

# Two cases made here from the examples: Kalker's linear theory (rolling-sphere at nu = 0.25, a
# creepage far below saturation, mu = 10: full stick; C11 against Kalker's table) and Spence's
# stick ratio (spence-sphere on a nearly incompressible substrate, nu = 0.49, |beta|/mu = 1.5,
# loaded in 48 steps: the load steps' own error stays below the coarse grids').
/usr/bin/env python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
k = json.load(open("examples/rolling-sphere.json"))
k["name"] = "kalker-sphere"
for body in ("body", "base"):
    k["materials"][body]["nu"] = 0.25
k["friction"]["mu"] = 10.0
k["tangential"]["creepage"] = [1.0e-5, 0.0]
json.dump(k, open(f"{work}/kalker-sphere.json", "w"), indent=1)
s = json.load(open("examples/spence-sphere.json"))
s["name"] = "spence-incompressible"
s["materials"]["base"]["nu"] = 0.49
beta = (1 - 2 * 0.49) / (2 * (1 - 0.49))  # Dundurs' beta of a rigid sphere on the substrate
s["friction"]["mu"] = beta / 1.5
s["grid"]["extent"] = 1.2
P = s["normal"]["force"]
s["tangential"]["history"] = [{"normal": {"force": P * (0.5 + 0.5 * i / 48) ** 3}} for i in range(49)]
json.dump(s, open(f"{work}/spence-incompressible.json", "w"), indent=1)
PY

# case, dimension, grids (elements along x; 3-D: ny = nx)
cases=(
  "hertz-sphere 3 16 24 32 48 64 96 128 192 256"
  "hertz-ellipse 3 16 24 32 48 64 96 128 192 256"
  "hertz-cylinder-2d 2 32 48 64 96 128 192 256 384 512 768 1024 1536 2048"
  "carter-2d 2 50 64 100 128 200 256 400 512 800 1024"
  "cattaneo-sphere 3 24 32 48 64 96 128"
  "kalker-sphere 3 24 32 40 48 56 64 80 96 112 128"
  "spence-incompressible 3 32 40 48 56 64 80 96 112 128"
)
for spec in "${cases[@]}"; do
  read -r name dim grids <<<"$spec"
  file="examples/$name.json"
  [[ -f "$work/$name.json" ]] && file="$work/$name.json"
  for n in $grids; do
    sets=(--set "grid.nx=$n" --set output.plots=false --set output.fields=false)
    [[ $dim == 3 ]] && sets+=(--set "grid.ny=$n")
    DYNCONTACT_THREADS=1 "$BUILD_DIR/bin/dyncontact" solve "$file" --out "$work/$name-$n" -q "${sets[@]}" \
      >/dev/null || { echo "convergence: $name on $n elements did not solve" >&2; exit 1; }
  done
  echo "$name $grids" >>"$work/cases"
done

/usr/bin/env python3 - "$work" "$out" <<'PY'
import json, math, os, sys
work, out = sys.argv[1], sys.argv[2]

def agm(a, b):
    while abs(a - b) > 1e-15 * a:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return a

def spence_stick_ratio(beta_over_mu):
    """c/a from |beta|/mu = t K'(t) / artanh(t) (core/contact_closed_forms.hpp), by bisection."""
    lo, hi = 1e-12, 1 - 1e-12
    for _ in range(200):
        t = (lo + hi) / 2
        if t * math.pi / (2 * agm(1, t)) / math.atanh(t) > beta_over_mu:
            lo = t
        else:
            hi = t
    return (lo + hi) / 2

def closed_form_errors(name, s):
    """Relative differences to the closed form: Hertz's from summary.json, Carter's creepage and
    Mindlin's shift (Johnson 7.42, 8.2), Kalker's C11 (Johnson Table 8.1: 4.12 at nu = 0.25) and
    Spence's stick ratio (Johnson 5.4) from the case's data."""
    if name == "kalker-sphere":
        case = json.load(open(os.path.join(work, name + ".json")))
        E, nu = case["materials"]["body"]["E"], case["materials"]["body"]["nu"]
        G, xi = E / (2 * (1 + nu)), case["tangential"]["creepage"][0]
        a = math.sqrt(s["hertz"]["semi_axis_x"] * s["hertz"]["semi_axis_y"])
        return {"Fx": -s["tangential_force"][0] / (G * a * a * xi) / 4.12 - 1}
    if name == "spence-incompressible":
        case = json.load(open(os.path.join(work, name + ".json")))
        nu = case["materials"]["base"]["nu"]
        beta = (1 - 2 * nu) / (2 * (1 - nu))
        ratio = spence_stick_ratio(beta / case["friction"]["mu"])
        return {"stick_fraction": s["stick_area"] / s["contact_area"] / ratio ** 2 - 1}
    if name in ("carter-2d", "cattaneo-sphere"):
        m = s["materials"]
        E, nu = m["body"]["E"], m["body"]["nu"]  # the two bodies are alike in these examples
        e_star, G = E / (2 * (1 - nu * nu)), E / (2 * (1 + nu))
        case = json.load(open(os.path.join("examples", name + ".json")))
        P, mu, R = case["normal"]["force"], case["friction"]["mu"], case["profile"]["radius"]
        Q = abs(case["tangential"]["force"][0])
        if name == "carter-2d":
            a = math.sqrt(4 * P * R / (math.pi * e_star))
            ref, value = mu * a / R * (1 - math.sqrt(1 - Q / (mu * P))), math.hypot(*s["creepage"])
            return {"creepage": (value - ref) / ref}
        a = (3 * P * R / (4 * e_star)) ** (1 / 3)
        ref = 3 * mu * P / (16 * a) * 2 * (2 - nu) / G * (1 - (1 - Q / (mu * P)) ** (2 / 3))
        return {"rigid_shift": (math.hypot(*s["rigid_shift"]) - ref) / ref}
    return s["hertz"]["relative_difference"]

quantities = ["max_pressure", "approach", "contact_area", "creepage", "rigid_shift", "Fx", "stick_fraction"]
rows, estimates, fits = [], [], {}
for line in open(os.path.join(work, "cases")):
    name, *grids = line.split()
    grids = [int(g) for g in grids]
    data = {}
    for n in grids:
        s = json.load(open(os.path.join(work, f"{name}-{n}", "summary.json")))
        data[n] = (s["grid"]["dx"], closed_form_errors(name, s), s)
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
            fits[(name, q)] = sum((x - mx) * (y - my) for x, y in fine) / sum((x - mx) ** 2 for x, _ in fine)
        # The program's own estimate (summary.json "accuracy") beside the true error.
        for n in grids:
            a = data[n][2].get("accuracy", {}).get("quantities", {}).get(q)
            true = abs(data[n][1][q])
            if a and true > 0:
                estimates.append((name, q, n, true, a["error_estimate"], a["method"], a["error_estimate"] / true))
with open(os.path.join(out, "convergence.tsv"), "w") as t:
    t.write("case\tquantity\tnx\th\trelative_error\n")
    for r in rows:
        t.write("%s\t%s\t%d\t%.6g\t%.6g\n" % r)
with open(os.path.join(out, "orders.tsv"), "w") as t:
    t.write("case\tquantity\tfitted_order\n")
    for (name, q), p in fits.items():
        t.write("%s\t%s\t%.2f\n" % (name, q, p))
with open(os.path.join(out, "estimates.tsv"), "w") as t:
    t.write("case\tquantity\tnx\ttrue_error\testimate\tmethod\testimate_over_true\n")
    for r in estimates:
        t.write("%s\t%s\t%d\t%.3e\t%.3e\t%s\t%.2f\n" % r)
print("fitted orders (finer half of the grids):")
for (name, q), p in fits.items():
    print(f"  {name:20s} {q:14s} {p:5.2f}")
print("the program's estimates against the true errors (estimate / true):")
groups = {}
for name, q, n, true, est, method, ratio in estimates:
    groups.setdefault((name, q), []).append(ratio)
for (name, q), r in groups.items():
    within = sum(1 for x in r if 1 <= x <= 3)
    below = sum(1 for x in r if x < 1)
    print(f"  {name:20s} {q:14s} {len(r):3d} grids: within 1-3x {within:3d}, below {below:3d}, "
          f"range {min(r):.2f}-{max(r):.2f}")
PY

if command -v gnuplot >/dev/null 2>&1; then
  while read -r name _; do
    plot=""
    for q in max_pressure approach contact_area creepage rigid_shift Fx stick_fraction; do
      awk -F'\t' -v c="$name" -v q="$q" '$1 == c && $2 == q { print $4, $5 }' "$out/convergence.tsv" >"$work/$name-$q.dat"
      order=$(awk -F'\t' -v c="$name" -v q="$q" '$1 == c && $2 == q { print $3 }' "$out/orders.tsv")
      [[ -s "$work/$name-$q.dat" ]] &&
        plot+="${plot:+, }'$work/$name-$q.dat' with linespoints title '$q (order ${order:-?})' noenhanced"
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
echo "wrote $out/convergence.tsv, $out/orders.tsv, $out/estimates.tsv and the figures $out/*.svg"
