"""dyncontact.subsurface(): the field inside the bodies as NumPy arrays (issue 29), against Hertz's
axis stresses (Johnson 3.45, Huber), the same values as the subsurface.vti that the run writes
read back with VTK as ParaView's Python reads it (vtkXMLImageDataReader; skipped only without
python3-vtk9), summary.json's maximum found in the image, and the errors of solve()."""
import json
import math

import numpy as np
import pytest

import dyncontact

from example_cases import example
from vtk_files import read_vti


def hertz_sphere(nx=65, extent=1.5):
    """The bundled Hertz sphere on an odd grid: one element centre on the axis."""
    case = example("hertz-sphere")
    case["grid"] = {"nx": nx, "ny": nx, "extent": extent}
    case["accuracy"] = {"estimate": False}
    return case


def test_axis_sigma_z_is_hubers():
    # 65^2 over +-1.5 a (dx = 0.046 a), the solved pressure: sigma_z on the axis within 5e-4 p0 of
    # -p0 / (1 + z^2/a^2) from z = 0.2 a (Johnson 3.45), sigma_r of Huber's formula too (1.3e-4 p0
    # and 8e-5 p0 measured), both bodies.
    case = hertz_sphere()
    probe = dyncontact.solve(case)
    a, p0 = probe["hertz"]["semi_axis_x"], probe["hertz"]["max_pressure"]
    depths = np.linspace(0.0, 2.0 * a, 41)
    r = dyncontact.subsurface(case, depths=depths)
    assert np.array_equal(r["depths"], depths)
    assert r["x"].shape == (65,) and r["y"].shape == (65,)
    assert abs(r["x"][32]) < 1e-12 * a and abs(r["y"][32]) < 1e-12 * a
    assert sorted(r["bodies"]) == ["base", "body"] and r["rigid"] == []
    nu = 0.3
    for name, body in r["bodies"].items():
        s = body["stress"]
        assert s.shape == (41, 65, 65, 6)
        assert body["displacement"].shape == (41, 65, 65, 3)
        assert body["von_mises"].shape == body["tresca"].shape == (41, 65, 65)
        z = depths[4:] / a
        sz = s[4:, 32, 32, 2] / p0
        sr = s[4:, 32, 32, 0] / p0
        exact_z = -1.0 / (1.0 + z**2)
        exact_r = -((1 + nu) * (1 - z * np.arctan(1 / z)) - 0.5 / (1 + z**2))
        print(f"{name}: axis |sigma_z error| <= {np.max(np.abs(sz - exact_z)):.2e} p0, "
              f"|sigma_r error| <= {np.max(np.abs(sr - exact_r)):.2e} p0")
        assert np.max(np.abs(sz - exact_z)) < 5e-4
        assert np.max(np.abs(sr - exact_r)) < 5e-4
        # The measures are those of the stresses: von Mises sqrt(3 J2) at every point.
        dev = s[..., :3] - s[..., :3].mean(axis=-1, keepdims=True)
        j2 = 0.5 * (dev**2).sum(axis=-1) + (s[..., 3:] ** 2).sum(axis=-1)
        assert np.allclose(body["von_mises"], np.sqrt(3 * j2), rtol=1e-12, atol=1e-9 * p0)
    # The summary is solve()'s, with the block's maxima: the largest von Mises of the arrays.
    base = r["summary"]["subsurface"]["base"]
    assert math.isclose(base["max_von_mises"], r["bodies"]["base"]["von_mises"].max(), rel_tol=1e-14)


def test_bad_input_names_the_key():
    case = hertz_sphere(nx=16, extent=1.5)
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.subsurface(case, depths=[0.0, -1e-4])
    assert e.value.key.startswith("subsurface.depths")
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.subsurface(case, bodies=["wheel"])
    assert e.value.key.startswith("subsurface.bodies")
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.subsurface(case, depths=[0.0, float("nan")])
    assert e.value.key.startswith("subsurface.depths")
    with pytest.raises(dyncontact.InputError) as e:
        dyncontact.subsurface(example("ball-impact"))
    assert e.value.key == "problem"


def test_a_contact_cut_by_the_grid_raises_with_the_field():
    case = example("hertz-sphere")
    case["grid"] = {"nx": 16, "ny": 16, "x": [-1e-4, 1e-4], "y": [-1e-4, 1e-4]}  # a = 0.187 mm
    with pytest.raises(dyncontact.ResultLimitError) as e:
        dyncontact.subsurface(case)
    assert e.value.key == "grid"
    assert e.value.result["bodies"]["base"]["stress"].shape == (32, 16, 16, 6)


@pytest.mark.parametrize("name", ["bearing-subsurface", "rail-shakedown"])
def test_example_subsurface_vti_reads_back_in_vtk(tmp_path, name):
    pytest.importorskip("vtk")  # python3-vtk9 (scripts/setup.sh)
    case = example(name)
    r = dyncontact.subsurface(case, out=tmp_path / "out")
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["files"]["subsurface"] == "subsurface.vti"
    image, arrays = read_vti(tmp_path / "out" / "subsurface.vti")
    depths, x, y = r["depths"], r["x"], r["y"]
    nd, ny, nx = len(depths), len(y), len(x)
    # The image: x and y the element centres, the third axis the depth into the body (m).
    assert image.GetDimensions() == (nx, ny, nd)
    sx, sy, sz = image.GetSpacing()
    ox, oy, oz = image.GetOrigin()
    assert math.isclose(ox, x[0], rel_tol=1e-8) and math.isclose(sx, x[1] - x[0], rel_tol=1e-8)
    if ny > 1:
        assert math.isclose(oy, y[0], rel_tol=1e-8) and math.isclose(sy, y[1] - y[0], rel_tol=1e-8)
    assert oz == 0.0 and math.isclose(sz, depths[1] - depths[0], rel_tol=1e-8)
    assert sorted(arrays) == ["base_displacement", "base_stress", "base_tresca", "base_von_mises"]
    base = r["bodies"]["base"]
    # Float32 in the file: the arrays' values to its precision (x fastest, then y, then depth).
    for key, shape in (("stress", (nd * ny * nx, 6)), ("displacement", (nd * ny * nx, 3)),
                       ("von_mises", (nd * ny * nx,)), ("tresca", (nd * ny * nx,))):
        got = arrays["base_" + key]
        assert got.dtype == np.float32 and got.shape == shape
        want = base[key].reshape(shape)
        assert np.allclose(got, want, rtol=2e-7, atol=1e-7 * np.abs(want).max()), key
    # summary.json's largest von Mises stress is the image's value at its point `at`.
    s = summary["subsurface"]["base"]
    at = s["at"]
    i = int(np.argmin(np.abs(x - at[0])))
    j = 0 if len(at) == 2 else int(np.argmin(np.abs(y - at[1])))
    k = int(np.argmin(np.abs(depths - at[-1])))
    vm = arrays["base_von_mises"].reshape(nd, ny, nx)
    assert math.isclose(float(vm[k, j, i]), s["max_von_mises"], rel_tol=1e-7)
    assert math.isclose(float(vm.max()), s["max_von_mises"], rel_tol=1e-7)


def test_solve_out_writes_the_blocks_files(tmp_path):
    # solve(case, out=...) writes what `dyncontact solve` writes for the block: the image and the
    # planes through each body's worst point.
    case = hertz_sphere(nx=16)
    case["subsurface"] = {"depths": "0:2e-4:5", "bodies": ["base"]}
    r = dyncontact.solve(case, out=tmp_path / "out")
    assert r["files"]["subsurface"] == "subsurface.vti"
    assert r["files"]["subsurface_planes"] == ["subsurface_base_xz.csv", "subsurface_base_yz.csv"]
    for name in ["subsurface.vti"] + r["files"]["subsurface_planes"]:
        assert (tmp_path / "out" / name).is_file()
    assert json.loads((tmp_path / "out" / "summary.json").read_text())["files"] == r["files"]


def test_a_history_writes_its_series(tmp_path):
    # A loading history (normal loads 50, 100 then 70 N on the Hertz sphere, no shear): the
    # arrays are the final state's, the series of every state is written as by `dyncontact solve`
    # (subsurface_<step>.vti in subsurface.pvd), and the largest stress is the 100 N state's.
    case = hertz_sphere(nx=16)
    case["problem"] = "tangential"
    case["friction"] = {"law": "coulomb", "mu": 0.3}
    case["tangential"] = {"regime": "shift", "history": [
        {"force": [0.0, 0.0], "normal": {"force": f}} for f in (50.0, 100.0, 70.0)]}
    r = dyncontact.subsurface(case, depths="0:3e-4:7", bodies=["base"], out=tmp_path / "out")
    files = r["summary"]["files"]
    assert files["subsurface_series"] == "subsurface.pvd"
    assert (tmp_path / "out" / "subsurface.pvd").is_file()
    assert len(list((tmp_path / "out").glob("subsurface_*.vti"))) == 3
    assert r["bodies"]["base"]["stress"].shape == (7, 16, 16, 6)
    final = r["bodies"]["base"]["von_mises"].max()
    assert r["summary"]["subsurface"]["base"]["max_von_mises"] > final  # the worst state: 100 N
