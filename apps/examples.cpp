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
      {"cattaneo-sphere", "Cattaneo-Mindlin: steel sphere, 100 N, tangential force 0.5 mu P (3-D, shift)",
       R"json({
  "schema": "dyncontact/1",
  "name": "cattaneo-sphere",
  "description": "Cattaneo-Mindlin: steel sphere (R = 10 mm) on steel under 100 N, then a tangential force of half the friction limit (Q = 0.5 mu P = 15 N, Coulomb mu = 0.3): a central stick circle of radius c = a (1 - Q/(mu P))^(1/3) = 0.79 a inside a slip annulus. The force is the traction ON THE BODY (-x: the body is pushed towards +x).",
  "problem": "tangential",
  "dimension": 3,
  "materials": {
    "body": {"E": 2.1e11, "nu": 0.3},
    "base": {"E": 2.1e11, "nu": 0.3}
  },
  "profile": {"type": "sphere", "radius": 0.01},
  "grid": {"nx": 32, "ny": 32, "extent": 1.2},
  "normal": {"force": 100.0},
  "friction": {"law": "coulomb", "mu": 0.3},
  "tangential": {"regime": "shift", "force": [-15.0, 0.0]},
  "solver": {"backend": "auto", "tol": 1e-9}
}
)json"},
      {"torsion-sphere", "Lubkin: steel sphere, 100 N, twisting moment half the full-slip value (3-D, torsion)",
       R"json({
  "schema": "dyncontact/1",
  "name": "torsion-sphere",
  "description": "Lubkin: steel sphere (R = 10 mm) on steel under 100 N, twisted by half the full-slip moment 3 pi mu P a / 16 (mu = 0.3, a = 0.1866 mm): M = 1.649e-3 N m, a stick core inside a slip annulus.",
  "problem": "tangential",
  "dimension": 3,
  "materials": {
    "body": {"E": 2.1e11, "nu": 0.3},
    "base": {"E": 2.1e11, "nu": 0.3}
  },
  "profile": {"type": "sphere", "radius": 0.01},
  "grid": {"nx": 32, "ny": 32, "extent": 1.2},
  "normal": {"force": 100.0},
  "friction": {"law": "coulomb", "mu": 0.3},
  "tangential": {"regime": "torsion", "moment": 1.64897e-3},
  "solver": {"backend": "auto", "tol": 1e-9}
}
)json"},
      {"carter-2d", "Carter: steel cylinder rolling on steel, 100 kN/m, force 0.5 mu P (2-D, rolling)",
       R"json({
  "schema": "dyncontact/1",
  "name": "carter-2d",
  "description": "Carter: steel cylinder (R = 20 mm) rolling steadily on steel, plane strain, 100 kN/m, tangential force 0.5 mu P = 15 kN/m on the body (mu = 0.3): stick zone of half-length a sqrt(1 - |F|/(mu P)) at the leading edge, creepage |xi| = (mu a / R)(1 - sqrt(1 - |F|/(mu P))) = 6.53e-4.",
  "problem": "tangential",
  "dimension": 2,
  "materials": {
    "body": {"E": 2.1e11, "nu": 0.3},
    "base": {"E": 2.1e11, "nu": 0.3}
  },
  "profile": {"type": "cylinder", "radius": 0.02},
  "grid": {"nx": 100, "extent": 1.2},
  "normal": {"force": 1.0e5},
  "friction": {"law": "coulomb", "mu": 0.3},
  "tangential": {"regime": "rolling", "force": [-15000.0], "velocity": 1.0},
  "solver": {"backend": "auto", "tol": 1e-9}
}
)json"},
      {"rolling-sphere", "steady rolling of a steel sphere, 100 N, creepage 1e-3 (3-D, rolling)",
       R"json({
  "schema": "dyncontact/1",
  "name": "rolling-sphere",
  "description": "Steady rolling of a steel sphere (R = 10 mm) on steel under 100 N with a longitudinal creepage of 1e-3 (mu = 0.3): stick at the leading edge, slip at the trailing edge, F_x about -11 N on the body (Kalker's linear theory, no slip: -G a^2 C11 xi = -12.2 N). Marching to the steady state takes about 200 steps (about 1 s with the native solver on this 24 x 24 grid).",
  "problem": "tangential",
  "dimension": 3,
  "materials": {
    "body": {"E": 2.1e11, "nu": 0.3},
    "base": {"E": 2.1e11, "nu": 0.3}
  },
  "profile": {"type": "sphere", "radius": 0.01},
  "grid": {"nx": 24, "ny": 24, "extent": 1.2},
  "normal": {"force": 100.0},
  "friction": {"law": "coulomb", "mu": 0.3},
  "tangential": {"regime": "rolling", "creepage": [1.0e-3, 0.0], "spin": 0.0, "velocity": 1.0},
  "solver": {"backend": "auto", "tol": 1e-9}
}
)json"},
      {"spence-sphere", "Spence: rigid sphere pressed into aluminium in 3 load steps, mu = 0.2 (3-D, history)",
       R"json({
  "schema": "dyncontact/1",
  "name": "spence-sphere",
  "description": "Spence: a rigid sphere (R = 10 mm) pressed into aluminium in three load steps (50, 100, 150 N), no tangential force, Coulomb mu = 0.2. The dissimilar materials (kappa != 0) make the surfaces slip radially under the growing load: a central stick circle of a fixed fraction c/a of the contact (|beta|/mu = 1.27) inside a slip annulus.",
  "problem": "tangential",
  "dimension": 3,
  "materials": {
    "body": {"rigid": true},
    "base": {"E": 7.0e10, "nu": 0.33}
  },
  "profile": {"type": "sphere", "radius": 0.01},
  "grid": {"nx": 24, "ny": 24, "extent": 1.3},
  "normal": {"force": 150.0},
  "friction": {"law": "coulomb", "mu": 0.2},
  "tangential": {
    "regime": "shift",
    "force": [0.0, 0.0],
    "history": [
      {"normal": {"force": 50.0}},
      {"normal": {"force": 100.0}},
      {"normal": {"force": 150.0}}
    ]
  },
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
