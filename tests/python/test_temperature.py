"""The flash temperature from Python (issue 30): the result dict carries summary.json's
"temperature" block and the fields both surfaces' maps, against Blok's Hertzian circle."""
import math

import dyncontact

from example_cases import example


def test_solve_returns_the_flash_temperature_and_its_maps():
    case = example("rolling-sphere")
    case["tangential"]["creepage"] = [0.3, 0.0]  # full slip at mu = 0.3: the flux mu p V xi
    case["tangential"]["velocity"] = 20.0
    case["accuracy"] = {"estimate": False}
    for body in ("base", "body"):
        case["materials"][body]["thermal"] = {"conductivity": 50.0, "diffusivity": 1.4e-5}
    r = dyncontact.solve(case)
    t = r["temperature"]
    h = r["hertz"]
    a, p0 = h["semi_axis_x"], h["max_pressure"]
    pe = 20.0 * a / (2 * 1.4e-5)
    blok = 0.87301 * 0.5 * (0.3 * p0 * 20.0 * 0.3) * a / (50.0 * math.sqrt(pe))  # each surface q0/2
    assert abs(t["max_rise"] / blok - 1) < 1 / pe + 0.01  # 48^2 over +-1.2 a: -0.3 % measured
    f = r["fields"]
    assert math.isclose(f["temperature_base"].max(), t["base"]["max_rise"], rel_tol=1e-12)
    assert math.isclose(f["temperature_body"].max(), t["body"]["max_rise"], rel_tol=1e-12)
    assert "temperature_base" not in dyncontact.solve(example("rolling-sphere"))["fields"]


def test_dynamic_run_returns_the_snapshots_flash_temperature():
    """A dynamic run's temperature at its snapshots (dynamic_temperature.hpp), as the command line's:
    the sliding bowling ball's lane, all the heat into it, its heat the friction's mu m g |v_slip|."""
    case = example("bowling-ball")
    case["time"]["t_end"] = 0.05
    case["output"] = {"plots": False, "snapshot_every": 10}
    case["materials"]["base"]["thermal"] = {"conductivity": 0.16, "diffusivity": 1e-7}
    case["materials"]["body"]["thermal"] = {"conductivity": 0.25, "diffusivity": 1.2e-7}
    case["temperature"] = {"partition": 1.0}
    r = dyncontact.solve(case)
    t = r["temperature"]
    assert [s["step"] for s in t["states"]] == [10, 20]
    ts = r["timeseries"]
    k = t["step"] - 1  # the rows are the accepted steps from step 1
    slip = abs(ts["vx"][k] - ts["wy"][k] * 0.109)
    assert abs(t["heat"] / (0.2 * 7.0 * 9.81 * slip) - 1) < 2e-3
    assert t["body"]["max_rise"] == 0.0 and t["max_rise"] > 0.0


def test_dynamic_run_steps_the_transient_temperature():
    """temperature.model "transient" (core/transient_flash_temperature.hpp) through the module, as
    the command line's (tests/test_cli_temperature.cpp): the bowling ball started cold, steps of
    20 us, its lane's rise grows while t < 2a/V (0.94 ms) and after it is the quasi-steady
    snapshot's within 0.5 %."""
    case = example("bowling-ball")
    case["grid"] = {"nx": 16, "ny": 16, "extent": 1.3}
    case["time"]["dt"] = 2e-5
    case["time"]["t_end"] = 2e-3
    case["output"] = {"plots": False, "snapshot_every": 10}
    case["materials"]["base"]["thermal"] = {"conductivity": 0.16, "diffusivity": 1e-7}
    case["materials"]["body"]["thermal"] = {"conductivity": 0.25, "diffusivity": 1.2e-7}
    case["temperature"] = {"partition": 1.0}
    steady = dyncontact.solve(case)["temperature"]
    case["temperature"]["model"] = "transient"
    t = dyncontact.solve(case)["temperature"]
    assert t["model"] == "transient, stepped with the run"
    rises = [s["max_rise"] for s in t["states"]]
    assert rises[0] < rises[1] < rises[2] < rises[3]
    assert abs(rises[-1] / steady["states"][-1]["max_rise"] - 1) < 5e-3
