"""The subsurface block, first yield, shakedown and fatigue from Python (issue 29): the result
dict carries the same blocks as summary.json, against Hertz's closed forms."""
import math

import dyncontact

from example_cases import example


def test_solve_returns_the_subsurface_maxima_and_first_yield():
    case = example("hertz-sphere")
    case["subsurface"] = {}
    case["materials"]["base"]["yield"] = {"tresca_k": 4.0e8}
    case["grid"] = {"nx": 64, "ny": 64, "extent": 2.0}
    r = dyncontact.solve(case)
    h = r["hertz"]
    base = r["subsurface"]["base"]
    # Johnson 3.4: tau_1 = 0.31 p0 at 0.48 a (nu = 0.3), on 64^2 over +-2 a within 2 %.
    assert abs(base["max_tresca"] / h["max_pressure"] - 0.31) < 0.006
    assert abs(base["at_tresca"][2] / h["semi_axis_x"] - 0.48) < 0.05
    y = r["yield"]["base"]
    assert y["criterion"] == "tresca"
    assert math.isclose(y["utilisation"], base["max_tresca"] / 4.0e8, rel_tol=1e-12)
    # Tresca first yield at tau_1 = k: p0 = k / 0.31 after the factor (p0 ~ P^(1/3)).
    p0_at_yield = h["max_pressure"] * y["first_yield_load_factor"] ** (1 / 3)
    assert abs(p0_at_yield * 0.31 / 4.0e8 - 1) < 0.02


def test_solve_returns_the_shakedown_verdict():
    case = example("hertz-cylinder-2d")
    case["materials"]["base"]["yield"] = {"tresca_k": 3.0e8}
    case["shakedown"] = True
    r = dyncontact.solve(case)
    s = r["shakedown"]
    assert s["status"] == "optimal"
    assert abs(s["shakedown_p0_over_k"] - 4.0) < 0.06  # Johnson & Jefferis, frictionless
    assert s["verdict"] == ("elastic" if s["p0_over_k"] < 3.3 else "shakedown" if s["p0_over_k"] < 4.0 else "beyond")


def test_dynamic_run_returns_the_field_at_its_peak_load():
    """A dynamic run's field (dynamic_subsurface.hpp), as the command line computes it: the Hertz
    impact of ball-impact is quasi-static, so the field at its largest contact force is Hertz's
    static contact under that force: tau_1 = 0.31 p0 (Johnson 3.4; 32^2 over +-1.3 a, depths every
    0.03 a: within 0.012 p0, the printed digits and the grid's 3 %)."""
    case = example("ball-impact")
    case["output"] = {"plots": False, "snapshot_every": 40}
    case["subsurface"] = {"depths": "0:2.4e-4:41"}
    case["materials"]["base"]["yield"] = {"tresca_k": 1.0e9}
    r = dyncontact.solve(case)
    sub = r["subsurface"]
    assert len(sub["states"]) == 5  # snapshots at 40, 80, 120, 160 and the peak between them
    peaks = [s for s in sub["states"] if s.get("peak_normal_force", False)]
    assert len(peaks) == 1 and sub["base"]["step"] == peaks[0]["step"]
    force = r["peaks"]["max_normal_force"]
    e_star = 2.1e11 / (2 * (1 - 0.3**2))
    p0 = (6 * force * e_star**2 / (math.pi**3 * 0.01**2)) ** (1 / 3)
    assert abs(sub["base"]["max_tresca"] / p0 - 0.31) < 0.012
    assert math.isclose(r["yield"]["base"]["utilisation"], sub["base"]["max_tresca"] / 1.0e9, rel_tol=1e-12)
