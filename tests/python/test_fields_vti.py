"""fields.vti (CASES.md "Files"): the surface fields as VTK image data, read back with VTK's XML
reader as ParaView's Python opens it (skipped only without python3-vtk9): one point per element
centre, the arrays those of fields.csv (Float32: to its precision), the pressure's integral the
normal force and the traction's the tangential force, a history's steps and a dynamic run's
snapshots as a series in fields.pvd, a wear run's worn depths; and an output folder that a later
run clears of every file an earlier one wrote (energy.csv, wear.csv, the images)."""
import json
import math
import os
import subprocess
import xml.etree.ElementTree as ElementTree

import numpy as np
import pytest

import dyncontact

from example_cases import SOURCE, example
from vtk_files import read_vti


def binary():
    """The command line (ctest sets DYNCONTACT_BINARY; else the source tree's build/)."""
    return os.environ.get("DYNCONTACT_BINARY", os.path.join(SOURCE, "build", "bin", "dyncontact"))


def read_csv(path):
    with open(path) as f:
        names = f.readline().strip().split(",")
    values = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {n: values[:, k] for k, n in enumerate(names)}


def solve_cli(case, out):
    path = out.parent / (out.name + ".json")
    path.write_text(json.dumps(case))
    run = subprocess.run([binary(), "solve", str(path), "--out", str(out), "-q"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return json.loads((out / "summary.json").read_text())


def assert_image_is_csv(image_path, csv_path, grid_3d=True):
    """The image's arrays are the csv's columns to Float32 precision, on the element centres."""
    image, arrays = read_vti(image_path)
    csv = read_csv(csv_path)
    n = len(csv["x"])
    xs = np.unique(csv["x"])
    ys = np.unique(csv["y"])
    nx, ny = len(xs), len(ys)
    assert image.GetDimensions() == (nx, ny, 1)
    ox, oy, oz = image.GetOrigin()
    sx, sy, _ = image.GetSpacing()
    assert math.isclose(ox, xs[0], rel_tol=1e-8, abs_tol=1e-15) and math.isclose(sx, xs[1] - xs[0], rel_tol=1e-6)
    if grid_3d:
        assert math.isclose(oy, ys[0], rel_tol=1e-8) and math.isclose(sy, ys[1] - ys[0], rel_tol=1e-6)
    assert oz == 0.0
    scale = {"p": max(np.abs(csv["p"]).max(), 1.0)}
    tmax = max(np.abs(csv["tx"]).max(), np.abs(csv["ty"]).max(), 1e-300)
    smax = max(np.abs(csv["sx"]).max(), np.abs(csv["sy"]).max(), 1e-300)
    assert np.allclose(arrays["pressure"], csv["p"], rtol=1e-6, atol=1e-7 * scale["p"])
    assert arrays["traction"].shape == (n, 3) and arrays["slip"].shape == (n, 3)
    assert np.allclose(arrays["traction"][:, 0], csv["tx"], rtol=1e-6, atol=1e-7 * tmax)
    assert np.allclose(arrays["traction"][:, 1], csv["ty"], rtol=1e-6, atol=1e-7 * tmax)
    assert np.allclose(arrays["slip"][:, 0], csv["sx"], rtol=1e-6, atol=1e-7 * smax)
    assert np.allclose(arrays["slip"][:, 1], csv["sy"], rtol=1e-6, atol=1e-7 * smax)
    assert np.all(arrays["traction"][:, 2] == 0) and np.all(arrays["slip"][:, 2] == 0)
    assert np.array_equal(arrays["state"], csv["state"])
    return image, arrays


def test_a_shift_writes_its_fields_as_an_image_with_the_forces_integrals(tmp_path):
    # Cattaneo's sphere (32^2): through solve(out=...), the Python path.
    case = example("cattaneo-sphere")
    r = dyncontact.solve(case, out=tmp_path / "out")
    out = tmp_path / "out"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["files"]["fields_vti"] == "fields.vti"
    image, arrays = assert_image_is_csv(out / "fields.vti", out / "fields.csv")
    sx, sy, _ = image.GetSpacing()
    area = sx * sy
    # Float32 sums of the element values: the normal force to 1e-6, the tangential force too.
    assert math.isclose(arrays["pressure"].astype(np.float64).sum() * area, summary["normal_force"], rel_tol=1e-6)
    fx = arrays["traction"][:, 0].astype(np.float64).sum() * area
    assert math.isclose(fx, summary["tangential_force"][0], rel_tol=1e-5)
    # The friction bound f(p) = mu p where in contact.
    assert "friction_bound" in arrays
    assert np.allclose(arrays["friction_bound"], 0.3 * arrays["pressure"], rtol=1e-6, atol=1e-7 * arrays["pressure"].max())
    assert np.array_equal(arrays["pressure"].reshape(32, 32), r["fields"]["p"].astype(np.float32))


def test_a_history_writes_a_series_of_its_steps(tmp_path):
    case = example("cattaneo-sphere")
    case["grid"] = {"nx": 24, "ny": 24, "extent": 1.2}
    case["accuracy"] = {"estimate": False}
    case["tangential"] = {"regime": "shift", "history": [{"force": [-10.0, 0.0]}, {"force": [-20.0, 0.0]},
                                                         {"force": [5.0, 0.0]}]}
    out = tmp_path / "out"
    summary = solve_cli(case, out)
    assert summary["files"]["fields_series"] == "fields.pvd"
    entries = ElementTree.parse(out / "fields.pvd").getroot().find("Collection").findall("DataSet")
    assert [e.get("file") for e in entries] == ["fields_0.vti", "fields_1.vti", "fields_2.vti"]
    assert [float(e.get("timestep")) for e in entries] == [0.0, 1.0, 2.0]
    for k in range(3):
        image, arrays = assert_image_is_csv(out / f"fields_{k}.vti", out / f"fields_{k}.csv")
        sx, sy, _ = image.GetSpacing()
        fx = arrays["traction"][:, 0].astype(np.float64).sum() * sx * sy
        assert math.isclose(fx, summary["steps"][k]["tangential_force"][0], rel_tol=1e-5, abs_tol=1e-6)
    _, last = read_vti(out / "fields.vti")
    _, step2 = read_vti(out / "fields_2.vti")
    assert np.array_equal(last["traction"], step2["traction"])


def test_a_dynamic_run_writes_its_snapshots_as_a_series(tmp_path):
    case = example("ball-impact")
    case["grid"] = {"nx": 16, "ny": 16, "extent": 1.3}
    case["output"] = {"snapshot_every": 40, "plots": False}
    out = tmp_path / "out"
    summary = solve_cli(case, out)
    snapshots = summary["files"]["snapshots"]
    assert summary["files"]["fields_series"] == "fields.pvd"
    entries = ElementTree.parse(out / "fields.pvd").getroot().find("Collection").findall("DataSet")
    assert [e.get("file") for e in entries] == [s["image"] for s in snapshots]
    assert [float(e.get("timestep")) for e in entries] == pytest.approx([s["time"] for s in snapshots], rel=1e-10)
    series = read_csv(out / "timeseries.csv")
    force_column = next(k for k in ("Fz", "contact_fz", "fz") if k in series)
    for s in snapshots:
        image, arrays = assert_image_is_csv(out / s["image"], out / s["file"])
        sx, sy, _ = image.GetSpacing()
        force = arrays["pressure"].astype(np.float64).sum() * sx * sy
        row = int(np.argmin(np.abs(series["t"] - s["time"])))
        assert math.isclose(force, abs(series[force_column][row]), rel_tol=1e-5, abs_tol=1e-6)


def test_a_line_contact_is_a_row_of_points(tmp_path):
    out = tmp_path / "out"
    case = example("hertz-cylinder-2d")
    case["accuracy"] = {"estimate": False}
    summary = solve_cli(case, out)
    image, arrays = assert_image_is_csv(out / "fields.vti", out / "fields.csv", grid_3d=False)
    sx, _, _ = image.GetSpacing()
    assert math.isclose(arrays["pressure"].astype(np.float64).sum() * sx, summary["normal_force"], rel_tol=1e-6)


def test_worn_depths_are_in_the_image_and_a_later_run_clears_what_it_does_not_write(tmp_path):
    case = example("fretting-wear")
    case["grid"] = {"nx": 24, "ny": 24, "extent": 1.3}
    case["wear"]["cycles"] = 1000
    out = tmp_path / "out"
    solve_cli(case, out)
    _, arrays = read_vti(out / "fields.vti")
    wear = read_csv(out / "wear.csv")
    for body in ("base", "body"):
        assert np.allclose(arrays["wear_" + body], wear[body], rtol=1e-6, atol=1e-7 * wear[body].max())
        assert wear[body].max() > 0
    # The same folder: whatever the earlier runs wrote (wear, a dynamic run's snapshots, energy
    # and wear maps, heat), a later run leaves exactly the files a run into an empty folder writes.
    plain = example("cattaneo-sphere")
    plain["output"] = {"plots": True}
    solve_cli(plain, tmp_path / "fresh")
    fresh = sorted(p.name for p in (tmp_path / "fresh").iterdir())
    assert "fields.vti" in fresh
    impact = example("ball-impact")
    impact["grid"] = {"nx": 16, "ny": 16, "extent": 1.3}
    impact["output"] = {"snapshot_every": 80, "plots": False}
    wheel = example("wheel-wear")
    wheel["output"] = dict(wheel.get("output", {}), plots=True)
    for earlier in (impact, wheel):
        solve_cli(earlier, out)
        written = {p.name for p in out.iterdir()}
        solve_cli(plain, out)
        assert sorted(p.name for p in out.iterdir()) == fresh, sorted(written)
