#include "tangential_fixtures.hpp"

#include <gtest/gtest.h>

#include "profile.hpp"

namespace dc::testing {

SolverSpec native_solver() {
  SolverSpec s;
  s.backend = "native";
  s.fallback = false;
  s.tol = 1e-10;
  s.max_iter = 2000;
  return s;
}

MaterialPair steel_on_steel() { return {Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)}; }

SphereSetup sphere_setup(int n, double extent, const MaterialPair& m, double R, double P) {
  const auto hz = hertz::sphere(R, P, m.E_star());
  const double L = extent * hz.a;
  const Grid g = Grid::make(3, n, n, -L, L, -L, L);
  ProfileSpec prof;
  prof.type = ProfileType::sphere;
  prof.radius = R;
  return {g, profile_heights(prof, g), hz};
}

void expect_certified(const TangentialSolution& s) {
  EXPECT_EQ(s.report.status, SolveStatus::converged) << s.report.message;
  EXPECT_LT(s.report.certificate.friction_law, 1e-6);
  EXPECT_LT(s.report.certificate.gap_function, 1e-5);
}

}  // namespace dc::testing
