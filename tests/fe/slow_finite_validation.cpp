// Slow finite-contact validations: a very stiff flat-ended cylinder is Boussinesq's rigid
// punch; a soft layer (nonhomogeneous body) changes approach and pressure as expected.
#include <cmath>

#include <gtest/gtest.h>

#include "fe_test_bodies.hpp"
#include "finite_contact.hpp"
#include "hertz.hpp"

namespace dc {
namespace {

constexpr double kE = 2.1e11, kNu = 0.3;

FeBodySpec stiff_flat_cylinder(double a) { return fe::testing::stiff_flat_cylinder(a, kE, kNu); }

/// 40 x 40 elements over +-1.25 a: the punch as a staircase of 32 elements across.
Grid punch_grid(double a) { return Grid::make(3, 40, 40, -1.25 * a, 1.25 * a, -1.25 * a, 1.25 * a); }

TEST(FiniteValidation, StiffFlatCylinderIsBoussinesqPunch) {
  // Rigid flat punch of radius a: P = 2 a E* d (E* of the half-space alone). The grid holds
  // the disk as a staircase of 32 elements across; tolerance 3 % on the approach.
  const double a = 0.005, P = 1e5;
  const Grid g = punch_grid(a);
  FiniteContact fc(stiff_flat_cylinder(a), g, Elastic::from_E_nu(kE, kNu));
  SolverOptions solver;
  solver.backend = Backend::native;
  const FiniteNormalSolution sol = fc.solve_normal({Control::force, P}, solver);
  ASSERT_EQ(sol.contact.report.status, SolveStatus::converged) << sol.contact.report.message;
  const double Es = kE / (1.0 - kNu * kNu);
  const double d = P / (2.0 * a * Es);
  EXPECT_NEAR(sol.contact.approach, d, 0.03 * d);
  // The pressure at the centre: P / (2 pi a^2), within 5 % (the mean over the central elements).
  double centre = 0.0;
  int n = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (std::hypot(g.xc(i), g.yc(j)) < 0.2 * a) {
        centre += sol.contact.pressure[g.index(i, j)];
        ++n;
      }
  centre /= n;
  const double p_centre = hertz::flat_punch_pressure(a, P, 0.0);
  EXPECT_NEAR(centre, p_centre, 0.05 * p_centre);
}

TEST(FiniteValidation, SoftLayerLowersPressureAndIncreasesApproach) {
  const double R = 0.01, P = 2000.0;
  FeBodySpec s;
  s.shape = FeShape::hemisphere;
  s.radius = R;
  s.elements = {8, 8, 4};
  s.material = {fe::isotropic_stiffness(kE, kNu, "test"), 7800.0};
  const auto h = hertz::sphere(R, P, kE / (2.0 * (1.0 - kNu * kNu)));
  s.contact_size = 0.4 * h.a;
  const double L = 2.0 * h.a;
  const Grid g = Grid::make(3, 16, 16, -L, L, -L, L);
  SolverOptions solver;
  solver.backend = Backend::native;
  FiniteContact uniform(s, g, Elastic::from_E_nu(kE, kNu));
  const auto u = uniform.solve_normal({Control::force, P}, solver);
  s.regions.push_back({2.0 * h.a, {fe::isotropic_stiffness(0.2 * kE, kNu, "test"), 7800.0}});
  FiniteContact layered(s, g, Elastic::from_E_nu(kE, kNu));
  const auto l = layered.solve_normal({Control::force, P}, solver);
  ASSERT_EQ(u.contact.report.status, SolveStatus::converged);
  ASSERT_EQ(l.contact.report.status, SolveStatus::converged);
  const auto peak = [](const std::vector<double>& p) { return *std::max_element(p.begin(), p.end()); };
  EXPECT_LT(peak(l.contact.pressure), 0.95 * peak(u.contact.pressure));
  EXPECT_GT(l.contact.approach, 1.05 * u.contact.approach);
}

}  // namespace
}  // namespace dc
