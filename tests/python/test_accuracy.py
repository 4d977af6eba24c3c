"""The accuracy block from Python (issue 28): every normal and tangential result carries its
estimated discretisation error; solve(case, accuracy=...) chooses the grid for a relative error,
met against Hertz's closed form; an unreachable target raises AccuracyError with the result."""
import copy

import pytest

import dyncontact

from example_cases import example


def test_result_dict_carries_the_accuracy_block():
    r = dyncontact.solve(example("hertz-sphere"))
    a = r["accuracy"]
    p = a["quantities"]["max_pressure"]
    assert p["value"] == r["max_pressure"]
    assert set(p) >= {"value", "extrapolated", "error_estimate", "order", "method", "values"}
    # The estimate bounds the true error against Hertz, within a factor 3 on this grid.
    true = abs(r["hertz"]["relative_difference"]["max_pressure"])
    assert true <= p["error_estimate"] <= 3 * true
    assert [g["nx"] for g in a["grids"]] == [64, 32, 16]


@pytest.mark.parametrize("target", [1e-2, 1e-3])
def test_accuracy_argument_chooses_the_grid_and_meets_hertz(target):
    case = example("hertz-ellipse")
    del case["grid"]  # the target sizes the grid
    r = dyncontact.solve(case, accuracy=target)
    a = r["accuracy"]
    assert a["met"] is True and a["target"] == target
    assert r["grid"]["nx"] == a["grid"]["nx"] == r["fields"]["p"].shape[1]
    assert abs(r["hertz"]["relative_difference"]["max_pressure"]) <= target


def test_an_unreachable_target_raises_accuracy_error_with_the_result():
    case = example("hertz-sphere")
    case["accuracy"] = {"max_elements": 10000}
    with pytest.raises(dyncontact.AccuracyError) as e:
        dyncontact.solve(case, accuracy=1e-6)
    a = e.value.result["accuracy"]
    assert a["met"] is False and a["stopped_by"] == "max_elements"
    assert isinstance(e.value, RuntimeError)


def test_bad_accuracy_is_an_input_error_naming_the_key():
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.solve(example("hertz-sphere"), accuracy="fine")
    assert e.value.key == "accuracy"
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.solve(example("hertz-sphere"), accuracy=-1.0)
    assert e.value.key == "accuracy.target"


def test_a_dynamic_run_carries_its_peaks_and_their_estimate():
    case = copy.deepcopy(example("ball-impact"))
    case["grid"]["nx"] = case["grid"]["ny"] = 24
    case["time"]["dt"] = 1e-6
    case["output"] = {"plots": False}
    case["accuracy"] = {"estimate": True}
    r = dyncontact.solve(case)
    q = r["accuracy"]["quantities"]
    assert q["max_normal_force"]["value"] == r["peaks"]["max_normal_force"]
    assert [g["nx"] for g in r["accuracy"]["grids"]] == [24, 12] or len(r["accuracy"]["grids"]) == 3
    assert "contact_time" in q and q["contact_time"]["error_estimate"] > 0


def test_a_sweep_run_that_misses_its_target_raises_accuracy_error():
    case = example("ball-impact-speeds")
    case["grid"]["nx"] = case["grid"]["ny"] = 16
    case["accuracy"] = {"target": 1e-7, "max_elements": 1024}
    with pytest.raises(dyncontact.AccuracyError) as e:
        dyncontact.solve(case)
    runs = e.value.result["runs"]
    assert len(runs) == 3 and all(r["accuracy"]["met"] is False for r in runs)


def _sphere_heights(n, a, R=0.01):
    L = 1.3 * a
    grid = dyncontact.Grid(n, n, -L, L, -L, L)
    x, y = dyncontact.grid_centres(grid)
    return grid, (x**2 + y**2) / (2 * R)


def test_a_normal_problem_given_by_heights_carries_the_cases_estimate():
    # The Hertz sphere as element heights (NormalProblem, no profile): solve(estimate=True) solves
    # again on 2 and 4 times the element size, the heights carried there by cubic interpolation,
    # exact for the sphere's quadratic; the estimate is then the case's (dyncontact.solve on the same
    # grid) to the solver's tolerance, and bounds Hertz's true peak-pressure error within 3 x (64^2).
    # set_heights moves the coarse problems too: the heights raised by c raise each grid's approach
    # by c. An odd grid and a 2-D one say why they have no estimate; without estimate, None.
    case = example("hertz-sphere")
    E, nu = case["materials"]["body"]["E"], case["materials"]["body"]["nu"]
    steel = dyncontact.Materials(E, nu, E, nu)
    P = case["normal"]["force"]
    e_star = E / (2 * (1 - nu**2))
    a = (3 * P * 0.01 / (4 * e_star)) ** (1 / 3)
    p0 = 3 * P / (2 * 3.141592653589793 * a * a)
    for n in (48, 64):
        grid, h = _sphere_heights(n, a)
        problem = dyncontact.NormalProblem(grid, steel, h)
        s = problem.solve(force=P, estimate=True)
        acc = s.accuracy
        assert [g["nx"] for g in acc["grids"]] == [n, n // 2, n // 4]
        assert all(g["status"] == "converged" for g in acc["grids"])
        with_case = copy.deepcopy(case)
        with_case["grid"] = {"nx": n, "ny": n, "x": [-1.3 * a, 1.3 * a], "y": [-1.3 * a, 1.3 * a]}
        reference = dyncontact.solve(with_case)["accuracy"]["quantities"]
        for name in ("approach", "max_pressure", "contact_area"):
            mine, theirs = acc["quantities"][name], reference[name]
            assert mine["method"] == theirs["method"], name
            assert mine["error_estimate"] == pytest.approx(theirs["error_estimate"], rel=1e-3), name
            assert mine["values"] == pytest.approx(theirs["values"], rel=1e-6), name
        if n == 64:
            true = abs(s.pressure.max() / p0 - 1)
            assert true <= acc["quantities"]["max_pressure"]["error_estimate"] <= 3 * true
            c = 1e-7
            problem.set_heights(h + c)
            raised = problem.solve(force=P, estimate=True).accuracy["quantities"]["approach"]["values"]
            assert raised == pytest.approx([v + c for v in acc["quantities"]["approach"]["values"]], rel=1e-7)
        assert problem.solve(force=P).accuracy is None
    grid, h = _sphere_heights(63, a)
    odd = dyncontact.NormalProblem(grid, steel, h).solve(force=P, estimate=True).accuracy
    assert "odd number of elements" in odd["unavailable"] and odd["estimate"] is None
    L = 1.5 * a
    line = dyncontact.Grid(128, 1, -L, L, dimension=2)
    x, _ = dyncontact.grid_centres(line)
    flat = dyncontact.NormalProblem(line, steel, x**2 / 0.02).solve(force=1e5, estimate=True).accuracy
    assert "shifted" in flat["unavailable"]
