#pragma once
// Shared set-ups of the tangential tests: materials, solver settings, rigid-mode controls and
// a Hertz sphere on a square grid.
#include <vector>

#include "hertz.hpp"
#include "tangential_problem.hpp"

namespace dc::testing {

/// The native backend without fallback, tight tolerance.
SolverSpec native_solver();
MaterialPair steel_on_steel();
inline ModeControl amplitude(double v) { return {ModeControl::Kind::amplitude, v}; }
inline ModeControl resultant(double v) { return {ModeControl::Kind::resultant, v}; }

struct SphereSetup {
  Grid grid;
  std::vector<double> heights;
  hertz::SphereSolution hz;
};

/// n x n grid over +-extent * a_Hertz (centred on the origin: torsion is about the grid origin).
SphereSetup sphere_setup(int n, double extent, const MaterialPair& m, double R, double P);

/// Converged, and the friction law (2.4)-(2.5) and the gap function (4.24) certified.
void expect_certified(const TangentialSolution& s);

}  // namespace dc::testing
