#!/usr/bin/env python3
"""Solve the bundled Hertz sphere from Python and check it against the closed form.

    python3 examples/python/hertz_check.py [--plot pressure.png]

Needs the module `dyncontact` (built with the project: `cmake --install build`, or
PYTHONPATH=build/python). Exits 1 when the solution is off the closed form by more than the
grid allows (peak pressure 2 %, contact radius one element).
"""
import argparse
import json
import math
import os
import sys

import dyncontact  # first: it finds NumPy for an interpreter that has none of its own
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
case_path = os.path.join(here, "..", "hertz-sphere.json")

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plot", help="draw p(x) on the centre line with the closed form (matplotlib)")
args = parser.parse_args()

with open(case_path) as f:
    case = json.load(f)
result = dyncontact.solve(case)

# Hertz: a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2), p(r) = p0 sqrt(1 - r^2/a^2).
P, R = case["normal"]["force"], case["profile"]["radius"]
mats = dyncontact.Materials(case["materials"]["body"]["E"], case["materials"]["body"]["nu"],
                            case["materials"]["base"]["E"], case["materials"]["base"]["nu"])
a = (3 * P * R / (4 * mats.E_star)) ** (1 / 3)
p0 = 3 * P / (2 * math.pi * a * a)

fields = result["fields"]
x, p = fields["x"], fields["p"]
dx = x[0, 1] - x[0, 0]
radius = math.sqrt(result["contact_area"] / math.pi)
print(f"status            {result['solver']['status']} (certificate {result['solver']['certificate']})")
print(f"peak pressure     {result['max_pressure']:.5g} Pa   (Hertz {p0:.5g}, {result['max_pressure'] / p0 - 1:+.2%})")
print(f"contact radius    {radius:.5g} m    (Hertz {a:.5g}, element {dx:.3g})")

if args.plot:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    row = p.shape[0] // 2
    xs = x[row]
    r = np.linspace(-1.3 * a, 1.3 * a, 400)
    plt.plot(xs * 1e3, p[row] / 1e9, "o", ms=3, label="dyncontact")
    plt.plot(r * 1e3, p0 * np.sqrt(np.clip(1 - (r / a) ** 2, 0, None)) / 1e9, label="Hertz")
    plt.xlabel("x (mm)")
    plt.ylabel("p (GPa)")
    plt.legend()
    plt.savefig(args.plot, dpi=120)
    print(f"wrote {args.plot}")

ok = result["solver"]["status"] == "converged" and abs(result["max_pressure"] / p0 - 1) < 0.02 and abs(radius - a) < dx
sys.exit(0 if ok else 1)
