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
