"""The Python module keeps the command line's guarantees: a result known to be wrong (a contact cut
by the grid) raises ResultLimitError with the limits of summary.json and the result; the problem
classes check their contact the same way; a case dict is read value by value (NaN and infinities
are an InputError naming the key path, NumPy numbers and arrays are numbers and lists)."""
import json
import math

import numpy as np
import pytest

import dyncontact

from example_cases import example

E, NU = 2.1e11, 0.3
R, P = 0.01, 100.0
STEEL = dyncontact.Materials(E, NU, E, NU)
E_STAR = E / (2 * (1 - NU**2))
A_HERTZ = (3 * P * R / (4 * E_STAR)) ** (1 / 3)  # 0.187 mm
P0_HERTZ = 3 * P / (2 * math.pi * A_HERTZ**2)


def hertz_case(grid):
    case = example("hertz-sphere")
    case["grid"] = grid
    return case


# The README's truncated grid: +-0.1 mm against a Hertz contact radius of 0.187 mm.
TRUNCATED = {"nx": 16, "ny": 16, "x": [-1e-4, 1e-4], "y": [-1e-4, 1e-4]}
RESOLVED = {"nx": 24, "ny": 24, "extent": 1.5}


def test_readme_truncated_grid_raises_result_limit_error():
    with pytest.raises(dyncontact.ResultLimitError) as e:
        dyncontact.solve(hertz_case(TRUNCATED))
    err = e.value
    assert isinstance(err, dyncontact.InputError) and isinstance(err, ValueError)
    assert err.key == "grid"
    assert "edge of the grid" in str(err) and "allow_edge_contact" in str(err)
    assert [l for l in err.limits if l["key"] == "grid" and l["level"] == "error" and not l["accepted"]]
    # The result is there to inspect: the summary with its limits and fields, the pressure
    # truncated (the force carried inside the square: the peak well above Hertz's).
    r = err.result
    assert r["limits"] == err.limits
    assert r["contact_edge_fraction"] > 0.5
    assert r["max_pressure"] > 2 * P0_HERTZ
    assert r["fields"]["p"].shape == (16, 16)


def test_truncated_grid_accepted_by_the_case_warns_and_returns_the_limits():
    grid = dict(TRUNCATED, allow_edge_contact=True)
    with pytest.warns(dyncontact.ResultLimitWarning, match="edge of the grid"):
        r = dyncontact.solve(hertz_case(grid))
    edge = [l for l in r["limits"] if l["key"] == "grid" and "edge" in l["message"]]
    assert len(edge) == 1 and edge[0]["accepted"]


def test_out_writes_the_limits_into_summary_json(tmp_path):
    # A resolved contact: no limits, in the result and in summary.json.
    r = dyncontact.solve(hertz_case(RESOLVED), out=tmp_path / "good")
    assert r["limits"] == []
    assert json.loads((tmp_path / "good" / "summary.json").read_text())["limits"] == []
    # A truncated one: the files are written, then ResultLimitError; summary.json lists the limits.
    with pytest.raises(dyncontact.ResultLimitError) as e:
        dyncontact.solve(hertz_case(TRUNCATED), out=tmp_path / "cut")
    summary = json.loads((tmp_path / "cut" / "summary.json").read_text())
    assert summary["limits"] == e.value.limits
    assert summary["max_pressure"] == e.value.result["max_pressure"]
    assert (tmp_path / "cut" / "fields.csv").exists()
    assert str(tmp_path / "cut") in str(e.value)


def sphere_grid(n, half_width):
    grid = dyncontact.Grid(n, n, -half_width, half_width, -half_width, half_width)
    x, y = dyncontact.grid_centres(grid)
    return grid, (x**2 + y**2) / (2 * R)


def test_normal_problem_on_a_one_element_grid_is_not_returned_as_right():
    # One element over +-1.5 a: the contact fills the grid (its edge) and is one element across.
    grid, h = sphere_grid(1, 1.5 * A_HERTZ)
    with pytest.raises(dyncontact.ResultLimitError) as e:
        dyncontact.NormalProblem(grid, STEEL, h).solve(force=P)
    assert e.value.key == "grid"
    s = e.value.result
    assert isinstance(s, dyncontact.NormalSolution)
    assert s.limits == e.value.limits
    assert any("1 element(s) across" in l["message"] and l["level"] == "warning" for l in s.limits)
    # Accepted: returned, the coarse contact a warning in .limits.
    with pytest.warns(dyncontact.ResultLimitWarning, match="element"):
        s = dyncontact.NormalProblem(grid, STEEL, h, allow_edge_contact=True).solve(force=P)
    assert s.converged
    # Both warnings; the edge one accepted by allow_edge_contact, the resolution one by nothing.
    assert all(l["level"] == "warning" for l in s.limits) and len(s.limits) == 2
    assert [l["accepted"] for l in s.limits if "edge" in l["message"]] == [True]
    assert [l["accepted"] for l in s.limits if "across" in l["message"]] == [False]


def test_problems_refuse_a_contact_filling_the_grid():
    # +-0.5 a: Hertz's contact (radius a) covers the whole grid.
    grid, h = sphere_grid(12, 0.5 * A_HERTZ)
    with pytest.raises(dyncontact.ResultLimitError) as e:
        dyncontact.NormalProblem(grid, STEEL, h).solve(force=P)
    assert e.value.key == "grid" and "edge of the grid" in str(e.value)
    with pytest.raises(dyncontact.ResultLimitError) as e:
        dyncontact.TangentialProblem(grid, STEEL, h, mu=0.3).step(force=P, force_x=10.0)
    assert e.value.key == "grid"
    assert isinstance(e.value.result, dyncontact.TangentialSolution)
    # The same sphere on +-1.5 a (16 elements: about 11 across the contact): no limits.
    grid, h = sphere_grid(16, 1.5 * A_HERTZ)
    s = dyncontact.NormalProblem(grid, STEEL, h).solve(force=P)
    assert s.converged and s.limits == []
    t = dyncontact.TangentialProblem(grid, STEEL, h, mu=0.3).step(force=P, force_x=10.0)
    assert t.converged and t.limits == []


@pytest.mark.parametrize(
    "change, key",
    [
        (lambda c: c["normal"].update(force=float("nan")), "normal.force"),
        (lambda c: c["normal"].update(force=np.float64("inf")), "normal.force"),
        (lambda c: c["materials"]["body"].update(E=-math.inf), "materials.body.E"),
        (lambda c: c.update(grid={"nx": 16, "ny": 16, "x": [-1e-4, math.inf], "y": [-1e-4, 1e-4]}), "grid.x[1]"),
        (lambda c: c.update(grid={"nx": 16, "ny": 16, "x": np.array([-1e-4, np.nan]), "y": [-1e-4, 1e-4]}),
         "grid.x[1]"),
        (lambda c: c["normal"].update(force={1.0, 2.0}), "normal.force"),       # a set
        (lambda c: c["normal"].update(force=1.0 + 2.0j), "normal.force"),       # complex
        (lambda c: c["grid"].update(x=np.zeros((2, 2, 2))), "grid.x"),          # three dimensions
        (lambda c: c["grid"].update({1: 2}), "grid"),                           # a key not a string
    ],
    ids=["nan", "numpy-inf", "minus-inf", "inf-in-list", "nan-in-array", "set", "complex", "3d-array", "int-key"],
)
def test_bad_values_in_a_case_dict_are_input_errors_naming_the_key(change, key):
    case = hertz_case(dict(RESOLVED))
    change(case)
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.solve(case)
    assert e.value.key == key, str(e.value)
    assert str(e.value).startswith(key + ":")


def test_numpy_numbers_and_arrays_give_the_python_numbers_answer():
    L = 1.5 * A_HERTZ
    plain = hertz_case({"nx": 20, "ny": 20, "x": [-L, L], "y": [-L, L]})
    plain["solver"]["fallback"] = True
    numpy_case = hertz_case(
        {"nx": np.int64(20), "ny": np.int32(20), "x": np.array([-L, L]), "y": (np.float64(-L), np.float64(L))}
    )
    numpy_case["normal"]["force"] = np.float64(P)
    numpy_case["profile"]["radius"] = np.float64(R)
    numpy_case["solver"]["fallback"] = np.bool_(True)
    a = dyncontact.solve(plain)
    b = dyncontact.solve(numpy_case)
    assert a["max_pressure"] == b["max_pressure"]
    assert a["normal_force"] == b["normal_force"]
    assert np.array_equal(a["fields"]["p"], b["fields"]["p"])
    # A 2-D array is a list of lists (here where a number belongs: the case model names it).
    bad = hertz_case({"nx": 20, "ny": 20, "x": np.array([[-L, L], [-L, L]]), "y": [-L, L]})
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.solve(bad)
    assert e.value.key.startswith("grid.x")


def test_normal_problem_refuses_nan_and_minus_inf_heights():
    grid, h = sphere_grid(8, 1.5 * A_HERTZ)
    for bad in (np.nan, -np.inf):
        heights = h.copy()
        heights[2, 3] = bad
        with pytest.raises(dyncontact.InputError) as e:
            dyncontact.NormalProblem(grid, STEEL, heights)
        assert e.value.key == "heights" and "element 19" in str(e.value)
        with pytest.raises(dyncontact.InputError) as e:
            dyncontact.TangentialProblem(grid, STEEL, heights, mu=0.3)
        assert e.value.key == "heights"
        problem = dyncontact.NormalProblem(grid, STEEL, h)
        with pytest.raises(dyncontact.InputError) as e:
            problem.set_heights(heights)
        assert e.value.key == "heights"
    # +inf keeps meaning "cannot touch": that element carries no pressure.
    heights = h.copy()
    heights[0, 0] = np.inf
    s = dyncontact.NormalProblem(grid, STEEL, heights).solve(force=P)
    assert s.converged and s.pressure[0, 0] == 0.0


def test_a_list_holding_itself_is_an_input_error_not_a_crash():
    case = hertz_case(dict(RESOLVED))
    loop = []
    loop.append(loop)
    case["grid"]["x"] = loop
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.solve(case)
    assert e.value.key.startswith("grid.x[0]") and "nested more than" in str(e.value)


@pytest.mark.parametrize("name", ["cattaneo-sphere", "spence-sphere"])  # a shift; a loading history
def test_tangential_cases_on_a_truncated_grid_raise_result_limit_error(name):
    case = example(name)
    case["grid"] = dict(TRUNCATED, nx=12, ny=12)
    with pytest.raises(dyncontact.ResultLimitError) as e:
        dyncontact.solve(case)
    assert e.value.key == "grid"
    assert "tangential_force" in e.value.result and e.value.result["limits"] == e.value.limits


def ball_impact(**time):
    """The ball-impact example (Hertz contact time 69 us) on 12 x 12 elements, its time block edited."""
    case = example("ball-impact")
    case["grid"]["nx"] = case["grid"]["ny"] = 12
    case["time"].update({"dt": 2e-6, **time})
    case["output"] = {"plots": False}
    return case


def test_dynamic_runs_keep_the_command_lines_limits():
    # Resolved: no limits, the energy balanced.
    r = dyncontact.solve(ball_impact())
    assert r["limits"] == [] and r["balances"]["energy"] < 0.05
    # 1.4 steps per contact: refused before the run, naming time.dt.
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.solve(ball_impact(dt=5e-5))
    assert e.value.key == "time.dt"
    # Accepted coarse step: the energy balance (0.2) above the tolerance is a result known wrong.
    with pytest.raises(dyncontact.ResultLimitError) as e:
        dyncontact.DynamicSimulation(ball_impact(dt=1e-5, allow_coarse_dt=True)).run()
    assert e.value.key == "time.dt"
    assert any(l["level"] == "error" and "energy balance" in l["message"] for l in e.value.limits)
    assert e.value.result["balances"]["energy"] > 0.05


def test_a_fallback_is_a_warning_with_the_failed_attempts():
    # Three iterations are too few for the native solver (and Ipopt) on 20^2: auto moves on, and
    # the module says so as the command line does on stderr; the report keeps the native history.
    case = hertz_case({"nx": 20, "ny": 20, "extent": 1.3})
    case["solver"] = {"backend": "auto", "max_iter": 3}
    with pytest.warns(dyncontact.SolverFallbackWarning, match="native: not_converged after 3 iterations"):
        r = dyncontact.solve(case)
    solver = r["solver"]
    assert solver["fallback_used"] and solver["status"] == "converged"
    native = solver["failed_attempts"][0]
    assert native["backend"] == "native" and native["iterations"] == 3
    assert [h["iteration"] for h in native["history"]] == [1, 2, 3]
    # A solve that needs no fallback warns of nothing.
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", dyncontact.SolverFallbackWarning)
        assert "failed_attempts" not in dyncontact.solve(hertz_case(RESOLVED))["solver"]
