"""The "wear" block from Python: the worn depth maps in r['fields'] (wear_base, wear_body, m) and
wear.csv in the output folder, as `dyncontact solve` writes it; the summary's volume is the
map's sum times the element area."""
import numpy as np
import pytest

import dyncontact

from example_cases import example


def test_fretting_wear_maps_and_wear_csv(tmp_path):
    case = example("cattaneo-sphere")
    case["grid"] = {"nx": 24, "ny": 24, "extent": 1.1}
    case["accuracy"] = {"estimate": False}
    case["output"] = {"plots": False}
    case["tangential"] = {"regime": "shift",
                          "history": [{"force": [-15.0, 0.0]}, {"force": [15.0, 0.0]}, {"force": [-15.0, 0.0]}]}
    case["wear"] = {"law": "archard", "k": 1e-4, "hardness": 2e9, "bodies": ["base"], "cycles": 10,
                    "cycle_from_step": 1, "update": {"cycles": 5}}
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
