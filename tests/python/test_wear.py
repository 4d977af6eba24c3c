"""The "wear" block from Python: the worn depth maps in r['fields'] (wear_base, wear_body, m) and
wear.csv in the output folder, as `dyncontact solve` writes it; the summary's volume is the
map's sum times the element area. Steady rolling's maps are on the grid, uniform along x; a
dynamic run's are the track's in world x and y (wear_base_x, wear_base_y) and the body's round its circumference
(wear_body_s)."""
import numpy as np
import pytest

import dyncontact

from example_cases import example


def fretting(cycles_per_update):
    """cattaneo-sphere on 24^2 fretted at +-15 N (the first loading once) for 10 cycles, the base
    worn by Archard's law, the profile updated every `cycles_per_update` cycles."""
    case = example("cattaneo-sphere")
    case["grid"] = {"nx": 24, "ny": 24, "extent": 1.1}
    case["accuracy"] = {"estimate": False}
    case["output"] = {"plots": False}
    case["tangential"] = {"regime": "shift",
                          "history": [{"force": [-15.0, 0.0]}, {"force": [15.0, 0.0]}, {"force": [-15.0, 0.0]}]}
    case["wear"] = {"law": "archard", "k": 1e-4, "hardness": 2e9, "bodies": ["base"], "cycles": 10,
                    "cycle_from_step": 1, "update": {"cycles": cycles_per_update}}
    return case


def test_fretting_wear_maps_and_wear_csv(tmp_path):
    case = fretting(5)
    r = dyncontact.solve(case, out=tmp_path / "out")
    f = r["fields"]
    assert "wear_body" not in f
    depth = f["wear_base"]
    assert depth.shape == (24, 24)
    dA = (f["x"][0, 1] - f["x"][0, 0]) * (f["y"][1, 0] - f["y"][0, 0])
    assert r["wear"]["cycles"] == 10 and r["wear"]["updates"] == 2
    assert r["wear"]["base"]["volume"] == pytest.approx(depth.sum() * dA, rel=1e-12)
    assert r["wear"]["base"]["max_depth"] == depth.max() > 0.0
    table = np.loadtxt(tmp_path / "out" / "wear.csv", delimiter=",", skiprows=1)
    assert (tmp_path / "out" / "wear.csv").read_text().startswith("x,y,base\n")
    np.testing.assert_allclose(table[:, 2].reshape(24, 24), depth, rtol=1e-9, atol=0.0)


def test_rolling_wear_maps_are_uniform_along_x_and_match_the_frictional_work():
    # Steady rolling: one pass wears each row of the track (and the body's circumference) by the
    # row's integral of the law, the same at every x; Archard's volume per pass (travel 2 pi R)
    # is k/(mu H) x the frictional power x 2 pi R / V.
    case = example("rolling-sphere")
    case["grid"] = {"nx": 24, "ny": 24, "extent": 1.2}
    case["accuracy"] = {"estimate": False}
    case["output"] = {"plots": False}
    case["wear"] = {"law": "archard", "k": 1e-4, "hardness": 2e9}
    r = dyncontact.solve(case)
    f = r["fields"]
    depth = f["wear_base"]
    assert depth.shape == (24, 24)
    np.testing.assert_array_equal(depth, f["wear_body"])
    np.testing.assert_array_equal(depth, np.repeat(depth[:, :1], 24, axis=1))  # uniform along x
    R, V = 0.01, case["tangential"]["velocity"]
    work = r["energy"]["frictional_power"] * 2 * np.pi * R / V
    assert r["wear"]["base"]["volume"] == pytest.approx(1e-4 / (0.3 * 2e9) * work, rel=1e-9)
    assert r["wear"]["rolling_radius"] == R


def test_dynamic_wear_maps_reach_python_in_each_bodys_frame():
    # wheel-wear's wheel (wheel-drive) for 1 s: the track's map along world x, the wheel's round
    # its circumference; both volumes k/(mu H) x the dissipated energy.
    case = example("wheel-wear")
    case["time"]["t_end"] = 1.0
    case["output"] = {"plots": False}
    for body in ("base", "body"):
        case["materials"][body].pop("thermal")
    r = dyncontact.solve(case)
    f = r["fields"]
    track, x = f["wear_base"], f["wear_base_x"]
    wheel, s = f["wear_body"], f["wear_body_s"]
    assert track.shape == (12, x.size) and wheel.shape == (12, s.size)
    assert np.allclose(f["wear_base_y"], -0.0055 + 0.001 * np.arange(12), rtol=0, atol=1e-12)  # world y
    assert s.size == r["wear"]["body"]["cells"]
    assert x[0] < 0.01 and x[-1] == pytest.approx(r["wear"]["travel"], abs=2e-3)
    dy = 0.012 / 12
    expected = 1e-4 / (0.3 * 2e9) * r["energy"]["dissipated"]
    assert track.sum() * (x[1] - x[0]) * dy == pytest.approx(expected, rel=1e-9)
    assert wheel.sum() * (s[1] - s[0]) * dy == pytest.approx(expected, rel=1e-9)
    assert r["wear"]["base"]["max_depth"] == track.max() > 0.0


def test_the_worn_profiles_evolution_reaches_python_and_paraview(tmp_path):
    # The fretting cycle of the first test for 10 cycles, updated every 2: five states, after 2,
    # 4, ..., 10 cycles, each state's volume the summary's history entry's, the last the final
    # map; the images in wear.pvd read back by VTK as ParaView opens them.
    case = fretting(2)
    r = dyncontact.solve(case, out=tmp_path / "out")
    series = r["wear_series"]
    assert list(series["cycles"]) == [2, 4, 6, 8, 10]
    assert series["depth"].shape == (5, 24, 24)
    f = r["fields"]
    dA = (f["x"][0, 1] - f["x"][0, 0]) * (f["y"][1, 0] - f["y"][0, 0])
    for depth, entry in zip(series["depth"], r["wear"]["history"]):
        assert depth.sum() * dA == pytest.approx(entry["volume"], rel=1e-12)
    np.testing.assert_array_equal(series["depth"][-1], f["wear_base"])
    assert np.all(np.diff(series["depth"], axis=0) >= 0.0)
    from vtk_files import read_vti
    image, arrays = read_vti(tmp_path / "out" / "wear_4.vti")
    assert image.GetDimensions() == (24, 24, 1)
    np.testing.assert_allclose(arrays["wear_base"].reshape(24, 24), series["depth"][-1], rtol=1e-6, atol=0.0)
    assert (tmp_path / "out" / "wear.pvd").read_text().count("<DataSet") == 5
