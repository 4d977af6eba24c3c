"""The accuracy block from Python (issue 28): every normal and tangential result carries its
estimated discretisation error; solve(case, accuracy=...) chooses the grid for a relative error,
met against Hertz's closed form; an unreachable target raises AccuracyError with the result."""
import copy

import numpy as np

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
        assert all(g["status"] == "converged" and g["certificate"]["complementarity"] < 1e-6 for g in acc["grids"])
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


def _tangential_case_and_problem(name, n, extent=1.2):
    """An example (steel sphere, 100 N) on n^2 elements over +-extent a, and the same as a
    TangentialProblem given by the sphere's heights."""
    case = copy.deepcopy(example(name))
    E, nu = case["materials"]["body"]["E"], case["materials"]["body"]["nu"]
    R, P = case["profile"]["radius"], case["normal"]["force"]
    a = (3 * P * R / (4 * E / (2 * (1 - nu**2)))) ** (1 / 3)
    L = extent * a
    case["grid"] = {"nx": n, "ny": n, "x": [-L, L], "y": [-L, L]}
    grid = dyncontact.Grid(n, n, -L, L, -L, L)
    x, y = dyncontact.grid_centres(grid)
    problem = dyncontact.TangentialProblem(grid, dyncontact.Materials(E, nu, E, nu), (x**2 + y**2) / (2 * R),
                                           mu=case["friction"]["mu"])
    return case, problem, a


def test_a_tangential_problem_given_by_heights_carries_the_cases_estimate():
    # Cattaneo-Mindlin by force (Q = 0.5 mu P) and Carter-Kalker steady rolling by creepage, as
    # element heights: estimate=True takes the same call on 2 and 4 times the element size, and
    # the estimate is the case's (dyncontact.solve on the same grid) to the solvers' tolerance. The
    # rigid shift's band bounds its true error against Mindlin's closed form
    # delta = 3 mu P (2 - nu) / (8 G a) [1 - (1 - Q / (mu P))^(2/3)] (similar materials).
    for name, call in (("cattaneo-sphere", "step"), ("rolling-sphere", "steady_rolling")):
        case, problem, a = _tangential_case_and_problem(name, 48)
        P, mu = case["normal"]["force"], case["friction"]["mu"]
        if call == "step":
            s = problem.step(force=P, force_x=case["tangential"]["force"][0], estimate=True)
        else:
            s = problem.steady_rolling(force=P, creepage_x=case["tangential"]["creepage"][0], estimate=True)
        acc = s.accuracy
        assert [g["nx"] for g in acc["grids"]] == [48, 24, 12], name
        assert all(g["status"] == "converged" and "certificate" in g for g in acc["grids"]), name
        reference = dyncontact.solve(case)["accuracy"]["quantities"]
        names = ("approach", "Fx", "stick_area") if call == "steady_rolling" else ("approach", "rigid_shift", "stick_area")
        for q in names:
            mine, theirs = acc["quantities"][q], reference[q]
            assert mine["method"] == theirs["method"], (name, q)
            assert mine["values"] == pytest.approx(theirs["values"], rel=1e-5, abs=1e-12), (name, q)
            assert mine["error_estimate"] == pytest.approx(theirs["error_estimate"], rel=1e-3, abs=1e-9), (name, q)
        # What the call prescribes has no estimate: the rolling creepage; a step's shift is solved for.
        assert ("creepage" in acc["quantities"]) is False and ("rigid_shift" in acc["quantities"]) == (call == "step")
        if call == "step":
            E, nu = case["materials"]["body"]["E"], case["materials"]["body"]["nu"]
            G = E / (2 * (1 + nu))
            Q = -case["tangential"]["force"][0]
            mindlin = 3 * mu * P * (2 - nu) / (8 * G * a) * (1 - (1 - Q / (mu * P)) ** (2 / 3))
            true = abs(abs(s.amplitudes[0]) / mindlin - 1)
            assert true <= acc["quantities"]["rigid_shift"]["error_estimate"] <= 3 * max(true, 1e-3)
        assert problem.step(force=P, force_x=-1.0).accuracy is None


def test_a_tangential_estimate_takes_the_coarse_grids_through_the_whole_history():
    # Mindlin-Deresiewicz: loaded to Q* = 15 N and unloaded to Q = 5 N the shift is
    # K [2 (1 - (Q* - Q) / (2 mu P))^(2/3) - (1 - Q* / (mu P))^(2/3) - 1], 23 % more than loading
    # straight to Q, K [1 - (1 - Q / (mu P))^(2/3)] (K = 3 mu P (2 - nu) / (8 G a)). The coarse
    # grids of an estimate asked for only at the unloading step take the loading step first
    # (recorded calls): their shifts are those of coarse problems taken through both steps
    # explicitly, each nearer Deresiewicz's than the direct loading's, and the band holds the fine
    # shift's true error; after reset() the history starts again (the direct loading's values).
    case, problem, a = _tangential_case_and_problem("cattaneo-sphere", 32)
    P, mu = case["normal"]["force"], case["friction"]["mu"]
    E, nu = case["materials"]["body"]["E"], case["materials"]["body"]["nu"]
    K = 3 * mu * P * (2 - nu) / (8 * E / (2 * (1 + nu)) * a)
    deresiewicz = K * (2 * (1 - 10.0 / (2 * mu * P)) ** (2 / 3) - (1 - 15.0 / (mu * P)) ** (2 / 3) - 1)
    direct = K * (1 - (1 - 5.0 / (mu * P)) ** (2 / 3))
    problem.step(force=P, force_x=-15.0)
    s = problem.step(force=P, force_x=-5.0, estimate=True)
    unloaded = s.accuracy["quantities"]["rigid_shift"]
    _, every_step, _ = _tangential_case_and_problem("cattaneo-sphere", 32)
    every_step.step(force=P, force_x=-15.0, estimate=True)
    both = every_step.step(force=P, force_x=-5.0, estimate=True).accuracy["quantities"]["rigid_shift"]
    assert unloaded["values"] == pytest.approx(both["values"], rel=1e-7)
    assert len(unloaded["values"]) == 3
    for v in unloaded["values"]:
        assert abs(v - deresiewicz) < abs(v - direct)
    assert abs(abs(s.amplitudes[0]) / deresiewicz - 1) <= unloaded["error_estimate"]
    problem.reset()
    again = problem.step(force=P, force_x=-5.0, estimate=True).accuracy["quantities"]["rigid_shift"]
    for v in again["values"]:
        assert abs(v - direct) < abs(v - deresiewicz)
    grid = dyncontact.Grid(31, 31, -2.6e-4, 2.6e-4, -2.6e-4, 2.6e-4)
    x, y = dyncontact.grid_centres(grid)
    odd = dyncontact.TangentialProblem(grid, dyncontact.Materials(2.1e11, 0.3, 2.1e11, 0.3), (x**2 + y**2) / 0.02,
                                       mu=0.3)
    assert "odd number" in odd.step(force=100.0, force_x=-15.0, estimate=True).accuracy["unavailable"]


def _hertz_steel():
    E, nu, R, P = 2.1e11, 0.3, 0.01, 100.0
    a = (3 * P * R / (4 * E / (2 * (1 - nu**2)))) ** (1 / 3)
    return dyncontact.Materials(E, nu, E, nu), R, P, a


def test_the_estimate_of_a_wavy_profile_holds_the_true_error(tmp_path):
    # A sphere with a waviness of 2 % of the Hertz approach a^2/R and wavelengths a/3 and a/2.1
    # (6-9 elements of a 48^2-64^2 grid over +-1.3 a: 1.5-2 elements of the grid of four times
    # the size, which aliases it), given as heights (NormalProblem) and as a measured table
    # (a case, 261^2 points). The reference is Richardson's from 256^2 and 512^2. Without the
    # height detail the coarse grid does not carry (unresolved_height) the approach's estimate was
    # 0.27 x its true error on 48^2; with it within 1-3 x, a band.
    materials, R, P, a = _hertz_steel()
    L = 1.3 * a

    def heights(x, y):
        return (x**2 + y**2) / (2 * R) + 0.02 * a * a / R * np.cos(6 * np.pi * x / a + 0.3) * np.cos(
            4.2 * np.pi * y / a + 1.1)

    def solved(n, estimate):
        grid = dyncontact.Grid(n, n, -L, L, -L, L)
        return dyncontact.NormalProblem(grid, materials, heights(*dyncontact.grid_centres(grid))).solve(
            force=P, estimate=estimate)

    fine, finer = solved(256, False).approach, solved(512, False).approach
    reference = finer + (finer - fine) / 3
    t = np.linspace(-L, L, 261)
    X, Y = np.meshgrid(t, t)
    np.savetxt(tmp_path / "h.csv", np.column_stack([X.ravel(), Y.ravel(), heights(X, Y).ravel()]), delimiter=",",
               header="x,y,h", comments="")
    shift = heights(X, Y).min()  # the table's heights are taken from their minimum
    case = copy.deepcopy(example("hertz-sphere"))
    case["profile"] = {"type": "table", "file": str(tmp_path / "h.csv")}
    case["output"] = {"plots": False}
    for n in (48, 64):
        s = solved(n, True)
        q = s.accuracy["quantities"]["approach"]
        true = abs(s.approach / reference - 1)
        assert true <= q["error_estimate"] <= 3 * true, n
        assert q["method"] == "band"
        case["grid"] = {"nx": n, "ny": n, "x": [-L, L], "y": [-L, L]}
        r = dyncontact.solve(case)
        q = r["accuracy"]["quantities"]["approach"]
        true = abs(r["approach"] / (reference - shift) - 1)
        assert q["method"] == "band" and true <= q["error_estimate"] <= 3 * true, n


def test_the_heights_estimate_of_a_flat_punch_and_of_a_noisy_sphere_are_bands():
    # A flat punch given as heights (0 on r <= b, +inf outside: the rim detection of
    # the case path): its force is a band not below Boussinesq's P = 2 b E* delta, its peak pressure
    # diverges (no error bar). A sphere with white noise of 1 % of its approach: the approach's band
    # is the height detail the coarse grid misses (far above the grids' differences), not 1/3 of
    # the smooth sphere's.
    materials, R, P, a = _hertz_steel()
    e_star = 2.1e11 / (2 * (1 - 0.3**2))
    b, delta = 2e-3, 0.5e-6
    for n in (48, 64):
        grid = dyncontact.Grid(n, n, -1.3 * b, 1.3 * b, -1.3 * b, 1.3 * b)
        x, y = dyncontact.grid_centres(grid)
        s = dyncontact.NormalProblem(grid, materials, np.where(x**2 + y**2 <= b * b, 0.0, np.inf)).solve(
            approach=delta, estimate=True)
        q = s.accuracy["quantities"]
        assert q["normal_force"]["method"] == "band" and q["max_pressure"]["method"] == "diverging", n
        assert q["max_pressure"]["error_estimate"] is None
        assert abs(s.force / (2 * b * e_star * delta) - 1) <= q["normal_force"]["error_estimate"], n
    L = 1.3 * a
    grid = dyncontact.Grid(64, 64, -L, L, -L, L)
    x, y = dyncontact.grid_centres(grid)
    noise = 0.01 * a * a / R * np.random.default_rng(7).standard_normal(x.shape)
    smooth = dyncontact.NormalProblem(grid, materials, (x**2 + y**2) / (2 * R)).solve(force=P, estimate=True)
    noisy = dyncontact.NormalProblem(grid, materials, (x**2 + y**2) / (2 * R) + noise).solve(force=P, estimate=True)
    q, q_smooth = noisy.accuracy["quantities"]["approach"], smooth.accuracy["quantities"]["approach"]
    # The detail the coarse grid misses: quintic minus cubic midpoint values along x and y, here over
    # every midpoint of the contact's bounding rows and columns (the program takes those beside a
    # contact element: no more than this).
    h = (x**2 + y**2) / (2 * R) + noise
    w = 3 * np.array([1, -3, 2, 2, -3, 1]) / 256
    inside = noisy.pressure > 0
    missed = 0.0
    for field, mask in ((h, inside), (h.T, inside.T)):
        for k in range(2, 64 - 3, 2):
            beside = mask[:, k] | mask[:, k + 1]
            if beside.any():
                missed = max(missed, np.abs(field[:, k - 2:k + 4] @ w)[beside].max())
    assert q["method"] == "band" and q["error_estimate_absolute"] == pytest.approx(missed, rel=1e-6)
    assert q["error_estimate"] > 3 * q_smooth["error_estimate"]


def test_a_transient_roll_is_estimated_on_coarse_grids_that_rolled_the_same_history():
    # Cattaneo's shifted state rolled over 3 a into Carter's (roll(): marching steps of each grid's
    # own dx over the same distance). The estimate asked at the roll alone takes the coarse grids
    # through the shift first: the same values as coarse grids estimated at both calls; the rolled
    # Fx approaches the steady-rolling one (within the estimate's band of each).
    case, problem, a = _tangential_case_and_problem("cattaneo-sphere", 32)
    P = case["normal"]["force"]
    kw = dict(force=P, creepage_x=1e-3)
    problem.step(force=P, force_x=-5.0)
    rolled = problem.roll(3 * a, **kw, estimate=True).accuracy
    _, mirror, _ = _tangential_case_and_problem("cattaneo-sphere", 32)
    mirror.step(force=P, force_x=-5.0, estimate=True)
    both = mirror.roll(3 * a, **kw, estimate=True).accuracy
    assert [g["nx"] for g in rolled["grids"]] == [32, 16, 8]
    assert all(g["status"] == "converged" for g in rolled["grids"])
    assert rolled["quantities"]["Fx"]["values"] == pytest.approx(both["quantities"]["Fx"]["values"], rel=1e-9)
    _, steady, _ = _tangential_case_and_problem("cattaneo-sphere", 32)
    carter = steady.steady_rolling(**kw, estimate=True).accuracy["quantities"]["Fx"]
    fx = rolled["quantities"]["Fx"]
    gap = abs(fx["value"] - carter["value"])
    assert gap <= fx["error_estimate_absolute"] + carter["error_estimate_absolute"]


def test_the_heights_estimate_of_a_grooved_sphere_is_not_below_its_true_error():
    # A sharp-edged groove across the sphere's contact (0.3 a off centre, 5 % of the approach deep,
    # 2 elements of a 64^2 grid over +-1.3 a wide): a step in the heights the coarse grids cannot
    # carry. The approach's estimate on 48^2, 64^2 and 96^2 is a band not below its true error
    # (2.5-10 x it; reference: Richardson from 256^2 and 512^2; without the unresolved-height floor
    # 0.2-0.7 x it). A groove narrower than the fine
    # element is not seen by the fine grid itself (no centre in it), so no estimate from its heights
    # can know it: docs/accuracy.md.
    materials, R, P, a = _hertz_steel()
    L = 1.3 * a
    width, depth = 2 * (2 * L / 64), 0.05 * a * a / R

    def solved(n, estimate):
        grid = dyncontact.Grid(n, n, -L, L, -L, L)
        x, y = dyncontact.grid_centres(grid)
        h = (x**2 + y**2) / (2 * R) + np.where(np.abs(x + 0.37 * a) < width / 2, depth, 0.0)
        return dyncontact.NormalProblem(grid, materials, h).solve(force=P, estimate=estimate)

    fine, finer = solved(256, False).approach, solved(512, False).approach
    reference = finer + (finer - fine) / 3
    for n in (48, 64, 96):
        s = solved(n, True)
        q = s.accuracy["quantities"]["approach"]
        assert q["method"] == "band", n
        assert abs(s.approach / reference - 1) <= q["error_estimate"], n
