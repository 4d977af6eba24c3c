#pragma once
// Shared by the tangential-problem tests: the native solver settings they run with, rigid-mode
// controls, and the certificate check of a converged step.
#include <gtest/gtest.h>

#include "profile.hpp"
#include "solver_support.hpp"
#include "tangential_problem.hpp"

namespace dc::test {

/// The native backend alone (no fallback), tol 1e-10, at most 2000 iterations.
inline SolverSpec native_tangential_solver() { return native_solver_spec(2000); }

inline ModeControl amplitude(double v) { return {ModeControl::Kind::amplitude, v}; }
inline ModeControl resultant(double v) { return {ModeControl::Kind::resultant, v}; }

/// Converged, friction law (2.4)-(2.5) to 1e-6 of max f(p), gap function (4.24) to 1e-5.
inline void expect_certified(const TangentialSolution& s) {
  EXPECT_EQ(s.report.status, SolveStatus::converged) << s.report.message;
  EXPECT_LT(s.report.certificate.friction_law, 1e-6);
  EXPECT_LT(s.report.certificate.gap_function, 1e-5);
}

/// The problem of a round body on `g`: a sphere (3-D) or a cylinder (2-D) of radius R, Coulomb mu.
inline TangentialProblem round_body_problem(const Grid& g, const MaterialPair& m, double R, double mu) {
  ProfileSpec prof;
  prof.type = g.dimension == 2 ? ProfileType::cylinder : ProfileType::sphere;
  prof.radius = R;
  return TangentialProblem(g, m, profile_heights(prof, g), FrictionLaw::coulomb(mu));
}

}  // namespace dc::test
