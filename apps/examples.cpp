// Bundled example cases. Keep each text identical to examples/<name>.json (tests/test_cli.cpp
// compares `dyncontact example NAME` with the file).
#include "examples.hpp"

namespace dc::cli {

const std::vector<BundledExample>& bundled_examples() {
  static const std::vector<BundledExample> examples = {
      {"hertz-sphere", "steel sphere on steel, 100 N: Hertz (3-D, force control)",
       R"json({
  "schema": "dyncontact/1",
  "name": "hertz-sphere",
  "description": "Steel sphere (R = 10 mm) pressed onto a steel half-space by 100 N: the classical Hertz contact (a = 0.187 mm, p0 = 1.37 GPa).",
  "problem": "normal",
  "dimension": 3,
  "materials": {
    "body": {"E": 2.1e11, "nu": 0.3},
    "base": {"E": 2.1e11, "nu": 0.3}
  },
  "profile": {"type": "sphere", "radius": 0.01},
  "grid": {"nx": 64, "ny": 64, "extent": 1.3},
  "normal": {"force": 100.0},
  "solver": {"backend": "auto", "tol": 1e-9}
}
)json"},
      {"hertz-cylinder-2d", "steel cylinder on steel, plane strain, 100 kN/m: 2-D Hertz",
       R"json({
  "schema": "dyncontact/1",
  "name": "hertz-cylinder-2d",
  "description": "Plane strain: steel cylinder (R = 20 mm) on a steel half-plane, 100 kN per metre of length (Hertz half-width a = 0.149 mm, p0 = 0.43 GPa).",
  "problem": "normal",
  "dimension": 2,
  "materials": {
    "body": {"E": 2.1e11, "nu": 0.3},
    "base": {"E": 2.1e11, "nu": 0.3}
  },
  "profile": {"type": "cylinder", "radius": 0.02},
  "grid": {"nx": 256, "extent": 1.5},
  "normal": {"force": 1.0e5},
  "solver": {"backend": "auto", "tol": 1e-9}
}
)json"},
      {"flat-punch", "rigid flat punch on aluminium, approach 1 um: Boussinesq (approach control)",
       R"json({
  "schema": "dyncontact/1",
  "name": "flat-punch",
  "description": "Rigid flat circular punch (radius 1 mm) pushed 1 micrometre into aluminium: Boussinesq, P = 2 a E* d, pressure singular at the rim.",
  "problem": "normal",
  "dimension": 3,
  "materials": {
    "body": {"rigid": true},
    "base": {"E": 7.0e10, "nu": 0.33}
  },
  "profile": {"type": "flat_punch", "radius": 1.0e-3},
  "grid": {"nx": 64, "ny": 64, "x": [-1.2e-3, 1.2e-3], "y": [-1.2e-3, 1.2e-3]},
  "normal": {"approach": 1.0e-6},
  "solver": {"backend": "auto", "tol": 1e-9}
}
)json"},
      {"hertz-ellipse", "steel ellipsoid Rx = 10 mm, Ry = 40 mm on steel: elliptic Hertz",
       R"json({
  "schema": "dyncontact/1",
  "name": "hertz-ellipse",
  "description": "Steel ellipsoid (radii 10 mm along x, 40 mm along y) on steel under 100 N: an elliptic Hertz contact elongated along y.",
  "problem": "normal",
  "dimension": 3,
  "materials": {
    "body": {"E": 2.1e11, "nu": 0.3},
    "base": {"E": 2.1e11, "nu": 0.3}
  },
  "profile": {"type": "ellipsoid", "radius_x": 0.01, "radius_y": 0.04},
  "grid": {"nx": 64, "ny": 64, "extent": 1.3},
  "normal": {"force": 100.0},
  "solver": {"backend": "auto", "tol": 1e-9}
}
)json"},
  };
  return examples;
}

const BundledExample* find_example(const std::string& name) {
  for (const auto& e : bundled_examples())
    if (name == e.name) return &e;
  return nullptr;
}

}  // namespace dc::cli
