#pragma once
// The tangential problem on one finite body by the condensed program (native) and by the sparse
// saddle form (a given backend), and the test that they reached the same certified point.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "fe_body_spec.hpp"
#include "elastic_stiffness.hpp"
#include "finite_contact.hpp"

namespace dc::fe::testing {

constexpr double kR = 0.01, kE = 2.1e11, kNu = 0.3, kP = 3000.0, kMu = 0.3;
constexpr double kHalfWidth = 1.2e-3;  // of the grid (m)
constexpr double kCertificateTol = 1e-6;  // SolverOptions's default

inline FeBodySpec hemisphere(const std::string& program, std::array<int, 3> elements, double contact_size = 5e-4) {
  FeBodySpec s;
  s.shape = FeShape::hemisphere;
  s.radius = kR;
  s.elements = elements;
  s.contact_size = contact_size;
  s.material = {isotropic_stiffness(kE, kNu, "test"), 7800.0};
  s.program = program;
  return s;
}

struct Pair {
  TangentialSolution condensed, sparse;
  std::size_t dofs = 0;
};

/// The same load on the condensed program (native) and on the sparse form (`backend`).
inline Pair solve_both(const TangentialLoad& load, int cells, std::array<int, 3> elements, Backend backend,
                       double contact_size = 5e-4) {
  const double L = kHalfWidth;
  const Grid g = Grid::make(3, cells, cells, -L, L, -L, L);
  const Elastic base = Elastic::from_E_nu(kE, kNu);
  FiniteContact b(hemisphere("condensed", elements, contact_size), g, base);
  FiniteContact a(hemisphere("sparse", elements, contact_size), g, base);
  SolverOptions native, sparse;
  native.backend = Backend::native;
  sparse.backend = backend;
  Pair out;
  out.dofs = a.body().dofs();
  out.condensed = b.tangential_problem(FrictionLaw::coulomb(kMu)).step(load, native);
  out.sparse = a.tangential_problem(FrictionLaw::coulomb(kMu)).step(load, sparse);
  return out;
}

/// Two certified points of a strictly convex program: within the square root of the
/// certificate's tolerance of each other, relative to the traction level f(p_max).
inline void expect_same_point(const Pair& r) {
  const TangentialSolution& a = r.sparse;
  const TangentialSolution& b = r.condensed;
  ASSERT_EQ(b.report.status, SolveStatus::converged) << b.report.message;
  ASSERT_EQ(a.report.status, SolveStatus::converged) << a.report.message;
  EXPECT_LE(a.report.certificate.worst(), kCertificateTol);
  EXPECT_GT(a.n_slip, 0) << "partial slip: the friction disks are active";
  EXPECT_GT(a.n_stick, 0);
  const double tol = std::sqrt(kCertificateTol);
  double t_max = 0.0, diff = 0.0, dp = 0.0, p_max = 0.0;
  for (std::size_t i = 0; i < b.tx.size(); ++i) {
    t_max = std::max(t_max, std::hypot(b.tx[i], b.ty[i]));
    diff = std::max(diff, std::hypot(a.tx[i] - b.tx[i], a.ty[i] - b.ty[i]));
    p_max = std::max(p_max, b.normal.pressure[i]);
    dp = std::max(dp, std::abs(a.normal.pressure[i] - b.normal.pressure[i]));
  }
  EXPECT_LT(diff / t_max, tol);
  EXPECT_LT(dp / p_max, tol);
  // The resultants against what friction can carry (mu P; times the grid's half-width, the
  // largest lever, for the moment), as the tractions against their level.
  for (int k = 0; k < 3; ++k) {
    const double lever = k == 2 ? kHalfWidth : 1.0;
    EXPECT_NEAR(a.resultants[k], b.resultants[k], tol * kMu * kP * lever) << "resultant " << k;
  }
  const double shift = std::max(std::abs(b.amplitudes[0]), std::abs(b.amplitudes[1]));
  EXPECT_NEAR(a.amplitudes[0], b.amplitudes[0], tol * shift + 1e-12 * kR);
  EXPECT_NEAR(a.amplitudes[1], b.amplitudes[1], tol * shift + 1e-12 * kR);
  EXPECT_NEAR(a.amplitudes[2], b.amplitudes[2], tol * std::abs(b.amplitudes[2]) + 1e-12);
}

inline TangentialLoad shift_by_force(double fraction) {
  TangentialLoad load;
  load.normal = {Control::force, kP};
  load.modes = {ModeControl{ModeControl::Kind::resultant, fraction * kMu * kP},
                ModeControl{ModeControl::Kind::resultant, 0.0}, ModeControl{ModeControl::Kind::amplitude, 0.0}};
  return load;
}

inline TangentialLoad twist_by_angle(double beta) {
  TangentialLoad load;
  load.normal = {Control::force, kP};
  load.modes = {ModeControl{ModeControl::Kind::resultant, 0.0}, ModeControl{ModeControl::Kind::resultant, 0.0},
                ModeControl{ModeControl::Kind::amplitude, beta}};
  return load;
}

}  // namespace dc::fe::testing
