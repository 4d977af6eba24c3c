#!/usr/bin/env python3
"""Draw the paper's Fig. 4 with matplotlib: (a) the friction force F/(mu P), (b) the half-length
of the adhesion zone 1 - d/l and (c) the rigid slip velocity |v|/(mu eps V0) against the time
t mu P/(M V0), for several rates gamma_bar of the driving moment (Section 5; the bundled case
examples/paper-cylinder.json: eta = 2, M0_bar = 0.2, eps = 1e-3, mu = 0.3).

    python3 examples/python/paper_fig4.py [--out fig4.png] [--gamma 0.25,0.5,1.0]

Dashed: the quasi-static limit (eps -> 0), F = eta (M0_bar + gamma_bar t)/(1 + eta), which
reaches 1 (gross sliding) at t* = ((1 + eta)/eta - M0_bar)/gamma_bar (docs/paper_cylinder.md).
Needs the module `dyncontact` and matplotlib (Debian: python3-matplotlib); without matplotlib
it says so and exits 0 after printing the onsets of sliding.
"""
import argparse
import json
import os
import sys

import dyncontact  # first: it finds NumPy for an interpreter that has none of its own
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", default="fig4.png", help="image file (PNG, SVG or PDF by its extension)")
parser.add_argument("--gamma", help="the rates gamma_bar, comma-separated (default: the case's sweep)")
args = parser.parse_args()

with open(os.path.join(here, "..", "paper-cylinder.json")) as f:
    case = json.load(f)
if args.gamma:
    case["sweep"] = {"dimensionless.gamma_bar": [float(g) for g in args.gamma.split(",")]}
result = dyncontact.solve(case)  # one run per gamma_bar, over the cores

d = case["dimensionless"]
eta, M0 = d["eta"], d["M0_bar"]
for run in result["runs"]:
    gamma = run["dimensionless"]["gamma_bar"]
    t_star = ((1 + eta) / eta - M0) / gamma
    onset = run["sliding_onset_t_bar"]
    print(f"gamma_bar {gamma:g}: gross sliding from t_bar {onset if onset is not None else 'never'}"
          f" (quasi-static limit {t_star:.4g})")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed (Debian: apt-get install python3-matplotlib): no figure drawn")
    sys.exit(0)

fig, axes = plt.subplots(1, 3, figsize=(13, 4), constrained_layout=True)
panels = [("F_bar", r"friction force $|F|/(\mu P)$"), ("l_bar", r"adhesion half-length $1 - d/\ell$"),
          ("v_bar", r"rigid slip velocity $|v|/(\mu\varepsilon V_0)$")]
for run in result["runs"]:
    ts, gamma = run["timeseries"], run["dimensionless"]["gamma_bar"]
    for ax, (key, _) in zip(axes, panels):
        (line,) = ax.plot(ts["t_bar"], ts[key], lw=2, label=rf"$\bar\gamma$ = {gamma:g}")
        if key == "F_bar":
            quasi = np.minimum(eta * (M0 + gamma * ts["t_bar"]) / (1 + eta), 1.0)
            ax.plot(ts["t_bar"], quasi, "--", color=line.get_color(), lw=1)
for ax, (key, label), tag in zip(axes, panels, "abc"):
    ax.set_xlabel(r"time $t\,\mu P/(M V_0)$")
    ax.set_ylabel(label)
    ax.set_title(f"({tag})")
    ax.grid(True, alpha=0.3)
axes[2].set_yscale("symlog", linthresh=0.1)
axes[0].legend()
fig.suptitle(r"Fig. 4: cylinder under a growing driving moment ($\eta$ = %g, $\bar M_0$ = %g, $\varepsilon$ = %g)"
             % (eta, M0, d["epsilon"]))
fig.savefig(args.out, dpi=120)
print(f"wrote {args.out}")
