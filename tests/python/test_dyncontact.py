"""The Python module against the closed forms: Hertz (sphere), the half-space operator against
the Boussinesq solution far from the load, input errors as exceptions carrying the key, and the
same summary from a dict, JSON text and a path."""
import json
import math
import os

import numpy as np
import pytest

import dyncontact

from example_cases import SOURCE, example


def small_hertz():
    case = example("hertz-sphere")
    case["grid"] = {"nx": 32, "ny": 32, "extent": 1.5}
    return case


def test_solve_hertz_sphere_against_the_closed_form():
    case = small_hertz()
    r = dyncontact.solve(case)
    P = case["normal"]["force"]
    R = case["profile"]["radius"]
    E, nu = case["materials"]["body"]["E"], case["materials"]["body"]["nu"]
    Eb, nub = case["materials"]["base"]["E"], case["materials"]["base"]["nu"]
    e_star = 1.0 / ((1 - nu**2) / E + (1 - nub**2) / Eb)
    a = (3 * P * R / (4 * e_star)) ** (1 / 3)
    p0 = 3 * P / (2 * math.pi * a * a)
    assert r["solver"]["status"] == "converged"
    assert r["normal_force"] == pytest.approx(P, rel=1e-6)
    # 32^2 over +-1.5 a (dx = a/10.7): the peak within 3 %, the area within 10 %.
    assert r["max_pressure"] == pytest.approx(p0, rel=0.03)
    assert r["contact_area"] == pytest.approx(math.pi * a * a, rel=0.10)
    f = r["fields"]
    assert f["p"].shape == (32, 32)
    assert isinstance(f["p"], np.ndarray)
    dA = (f["x"][0, 1] - f["x"][0, 0]) * (f["y"][1, 0] - f["y"][0, 0])
    assert f["p"].sum() * dA == pytest.approx(P, rel=1e-6)
    assert set(np.unique(f["state"])) <= {0, 1}


def test_dict_json_text_and_path_give_the_same_summary(tmp_path):
    case = small_hertz()
    path = tmp_path / "case.json"
    path.write_text(json.dumps(case))
    a = dyncontact.solve(case)
    b = dyncontact.solve(json.dumps(case))
    c = dyncontact.solve(path, out=tmp_path / "out")
    assert a["normal_force"] == b["normal_force"] == c["normal_force"]
    assert np.array_equal(a["fields"]["p"], c["fields"]["p"])
    assert (tmp_path / "out" / "summary.json").exists()
    assert (tmp_path / "out" / "fields.csv").exists()
    assert not (tmp_path / "case").exists()


def test_input_errors_carry_the_key():
    case = small_hertz()
    case["grid"]["nx"] = -3
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.solve(case)
    assert e.value.key.startswith("grid")
    assert isinstance(e.value, ValueError)
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.solve("/no/such/case.json")
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.HalfSpace(dyncontact.Grid(4, 4, -1, 1, -1, 1), dyncontact.Materials(2e11, 0.3, 2e11, 0.3)).normal().apply(np.ones(3))
    assert e.value.key == "x"


def test_half_space_normal_operator_far_field_is_boussinesq():
    # A unit force on the centre element; far away the displacement is (1-nu^2)/(pi E r) per body.
    n, L = 41, 1e-3
    grid = dyncontact.Grid(n, n, -L, L, -L, L)
    E, nu = 2.1e11, 0.3
    hs = dyncontact.HalfSpace(grid, dyncontact.Materials(E, nu, E, nu))
    op = hs.normal()
    assert op.rows == op.cols == n * n
    p = np.zeros(n * n)
    centre = (n // 2) * n + n // 2
    p[centre] = 1.0 / (grid.dx * grid.dy)  # 1 N
    w = op.apply(p).reshape(n, n)
    r = 20 * grid.dx
    expected = 2 * (1 - nu**2) / (math.pi * E * r)
    assert w[n // 2, n // 2 + 20] == pytest.approx(expected, rel=1e-3)
    assert np.array_equal(op.apply(p), op.apply(list(p)))


def test_help_names_the_entry_points():
    doc = dyncontact.__doc__
    for name in ("solve", "HalfSpace", "InputError"):
        assert name in doc
    assert "summary" in dyncontact.solve.__doc__


def test_hertz_example_script_passes(tmp_path):
    import subprocess
    import sys
    script = os.path.join(SOURCE, "examples", "python", "hertz_check.py")
    r = subprocess.run([sys.executable, script], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "Hertz" in r.stdout
