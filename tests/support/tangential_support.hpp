#pragma once
// Shared by the tangential-problem tests: the native solver settings they run with, rigid-mode
// controls, and the certificate check of a converged step.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "hertz.hpp"
#include "profile.hpp"
#include "solver_support.hpp"
#include "tangential_problem.hpp"

namespace dc::test {

/// The native backend alone (no fallback), tol 1e-10, at most 2000 iterations.
inline SolverOptions native_tangential_solver() { return native_solver_spec(2000); }

inline ModeControl amplitude(double v) { return {ModeControl::Kind::amplitude, v}; }
inline ModeControl resultant(double v) { return {ModeControl::Kind::resultant, v}; }

/// Converged, friction law (2.4)-(2.5) to 1e-6 of max f(p), gap function (4.24) to 1e-5.
inline void expect_certified(const TangentialSolution& s) {
  EXPECT_EQ(s.report.status, SolveStatus::converged) << s.report.message;
  EXPECT_LT(s.report.certificate.friction_law, 1e-6);
  EXPECT_LT(s.report.certificate.gap_function, 1e-5);
}

/// a reaches b's state: the same pressure (1e-6 of its peak), traction (1e-5 of the largest
/// friction bound) and stick set: what two solves of one step agree to when their paths differ
/// (the kappa != 0 loop stops at a coupling residual of certificate_tol / 100).
inline void expect_same_state(const TangentialSolution& a, const TangentialSolution& b, const std::string& where) {
  double p_max = 0.0, f_max = 0.0;
  for (std::size_t e = 0; e < b.normal.pressure.size(); ++e) {
    p_max = std::max(p_max, b.normal.pressure[e]);
    f_max = std::max(f_max, b.bound[e]);
  }
  for (std::size_t e = 0; e < b.normal.pressure.size(); ++e) {
    EXPECT_NEAR(a.normal.pressure[e], b.normal.pressure[e], 1e-6 * p_max) << where << ", element " << e;
    EXPECT_NEAR(a.tx[e], b.tx[e], 1e-5 * f_max) << where << ", element " << e;
    EXPECT_NEAR(a.ty[e], b.ty[e], 1e-5 * f_max) << where << ", element " << e;
  }
  EXPECT_EQ(a.n_stick, b.n_stick) << where;
}

inline MaterialPair steel_on_steel() { return {Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)}; }

struct SphereSetup {
  Grid grid;
  std::vector<double> heights;
  hertz::SphereSolution hz;
};

/// n x n grid over +-extent * a_Hertz (centred on the origin: torsion is about the grid origin).
inline SphereSetup sphere_setup(int n, double extent, const MaterialPair& m, double R, double P) {
  const auto hz = hertz::sphere(R, P, m.E_star());
  const double L = extent * hz.a;
  const Grid g = Grid::make(3, n, n, -L, L, -L, L);
  ProfileSpec prof;
  prof.type = ProfileType::sphere;
  prof.radius = R;
  return {g, profile_heights(prof, g), hz};
}

/// The problem of a round body on `g`: a sphere (3-D) or a cylinder (2-D) of radius R, Coulomb mu.
inline TangentialProblem round_body_problem(const Grid& g, const MaterialPair& m, double R, double mu) {
  ProfileSpec prof;
  prof.type = g.dimension == 2 ? ProfileType::cylinder : ProfileType::sphere;
  prof.radius = R;
  return TangentialProblem(g, m, profile_heights(prof, g), FrictionLaw::coulomb(mu));
}

}  // namespace dc::test
