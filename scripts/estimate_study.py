#!/usr/bin/env python3
"""How far the 3-D approach's error estimate can hold (issue 28, docs/accuracy.md "The 3-D
approach: what three grids can know"). Solves the Hertz sphere and two ellipsoids (radii 1:3 and
5:1) on 24^2-200^2 over extents 1.15-2.2 a (force control; the sphere also under approach
control), and prints how often the program's estimate of the approach (force control) or force
(approach control) is within 1-3x its true error against Hertz and how often below; then the
bound no estimate of the reported value can pass: an oracle that knows each series' smooth error
C/n^2 exactly (fitted over all its grids) and reports k times it, for the best k.
  PYTHONPATH=build/python python3 scripts/estimate_study.py      (about 5 s)"""
import collections
import copy
import itertools
import json
import math
import os
import sys

import dyncontact

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = json.load(open(os.path.join(HERE, "..", "examples", "hertz-ellipse.json")))
SHAPES = {"sphere": {"type": "sphere", "radius": 0.01},
          "ellipsoid 1:3": {"type": "ellipsoid", "radius_x": 0.01, "radius_y": 0.03},
          "ellipsoid 5:1": {"type": "ellipsoid", "radius_x": 0.02, "radius_y": 0.004}}
EXTENTS = (1.15, 1.3, 1.6, 2.2)
GRIDS = (24, 32, 40, 48, 56, 64, 80, 96, 128, 160, 200)

rows = []
for (shape, profile), extent, n, control in itertools.product(SHAPES.items(), EXTENTS, GRIDS, ("force", "approach")):
    if control == "approach" and shape != "sphere":
        continue
    c = copy.deepcopy(CASE)
    c["profile"] = profile
    c["grid"] = {"nx": n, "ny": n, "extent": extent}
    c["output"] = {"plots": False}
    if control == "approach":
        c["normal"] = {"approach": 2.6e-6}
    r = dyncontact.solve(c)
    q = r["accuracy"].get("quantities")
    if not q:
        continue
    name = "approach" if control == "force" else "normal_force"
    true = abs(q[name]["value"] / r["hertz"][name] - 1)
    rows.append((shape, extent, n, control, true, q[name]["error_estimate"]))

within = sum(1 <= est / true <= 3 for *_, true, est in rows)
below = sum(est < true for *_, true, est in rows)
print(f"the program's estimate: within 1-3x the true error on {within} of {len(rows)} grids "
      f"({within / len(rows):.0%}), below it on {below} ({below / len(rows):.0%})")

series = collections.defaultdict(list)
for shape, extent, n, control, true, _ in rows:
    if control == "force":
        series[(shape, extent)].append((n, true))
best = (0, 0.0)
scatter = []
for k in (1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 3.0):
    hits = total = 0
    for pts in series.values():
        c = math.exp(sum(math.log(e) + 2 * math.log(n) for n, e in pts) / len(pts))
        for n, e in pts:
            hits += 1 <= k * c / n**2 / e <= 3
            total += 1
            if k == 1.0:
                scatter.append(e / (c / n**2))
    best = max(best, (hits, k))
scatter.sort()
quantile = lambda f: scatter[int(f * (len(scatter) - 1))]
print(f"an oracle knowing each series' smooth error C/n^2: at best ({best[1]} x it) within 1-3x on {best[0]} of "
      f"{total} ({best[0] / total:.0%}); the true error is {quantile(0.05):.2f}-{quantile(0.95):.2f} x the smooth "
      f"one (5-95 %)")
sys.exit(0)
