// The normal problem (4.7) against Hertz, elliptic Hertz, the 2-D cylinder and Boussinesq's
// flat punch; the error must fall as the grid is refined.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hertz.hpp"
#include "normal_problem.hpp"
#include "profile.hpp"
#include "solver_support.hpp"

namespace dc {
namespace {

constexpr double kPi = std::numbers::pi;


SolverOptions native_normal_solver() { return test::native_solver_spec(5000); }

struct HertzErrors {
  double approach, radius, peak;
};

/// Sphere on a grid of n x n over +-extent * a_Hertz: relative errors of the results.
HertzErrors sphere_errors(int n, double extent, const MaterialPair& m, double R, double P) {
  const auto hz = hertz::sphere(R, P, m.E_star());
  const double L = extent * hz.a;
  const Grid g = Grid::make(3, n, n, -L, L, -L, L);
  ProfileSpec prof;
  prof.type = ProfileType::sphere;
  prof.radius = R;
  NormalProblem problem(g, m, profile_heights(prof, g));
  const NormalSolution s = problem.solve({Control::force, P}, native_normal_solver());
  EXPECT_EQ(s.report.status, SolveStatus::converged) << s.report.message;
  EXPECT_LT(s.report.certificate.complementarity, 1e-6);
  double area = 0.0, peak = 0.0;
  for (double p : s.pressure) {
    area += p > 0.0 ? g.area() : 0.0;
    peak = std::max(peak, p);
  }
  EXPECT_NEAR(s.force, P, 1e-8 * P);
  return {std::abs(s.approach / hz.approach - 1.0), std::abs(std::sqrt(area / kPi) / hz.a - 1.0),
          std::abs(peak / hz.p0 - 1.0)};
}

TEST(NormalHertz, SphereMatchesHertzAndConvergesUnderRefinement) {
  const auto m = test::steel_on_aluminium();
  const HertzErrors coarse = sphere_errors(32, 1.25, m, 0.01, 100.0);
  const HertzErrors fine = sphere_errors(96, 1.25, m, 0.01, 100.0);
  // Tolerances the 96^2 grid (dx = a/38) meets: approach 0.5 %, radius 2 %, peak 1 %.
  EXPECT_LT(fine.approach, 5e-3);
  EXPECT_LT(fine.radius, 2e-2);
  EXPECT_LT(fine.peak, 1e-2);
  EXPECT_LT(fine.approach, coarse.approach);
  EXPECT_LT(fine.peak, coarse.peak);
  EXPECT_LT(fine.radius, coarse.radius);
}

TEST(NormalHertz, OtherMaterialAndLoad) {
  // A rubber-like sphere on glass, 1000x softer and a different load: same relative accuracy.
  const MaterialPair m{Elastic::from_E_nu(5e6, 0.45), Elastic::from_E_nu(7e10, 0.22)};
  const HertzErrors e = sphere_errors(64, 1.3, m, 0.005, 0.2);
  EXPECT_LT(e.approach, 1e-2);
  EXPECT_LT(e.peak, 2e-2);
  EXPECT_LT(e.radius, 3e-2);
}

TEST(NormalHertz, EllipticContactMatchesHertzEllipticIntegrals) {
  const auto m = test::steel_on_aluminium();
  const double Rx = 0.01, Ry = 0.04, P = 200.0;
  const auto hz = hertz::elliptic(1.0 / (2 * Rx), 1.0 / (2 * Ry), P, m.E_star());
  ASSERT_LT(hz.a, hz.b);
  const Grid g = Grid::make(3, 48, 96, -1.25 * hz.a, 1.25 * hz.a, -1.25 * hz.b, 1.25 * hz.b);
  ProfileSpec prof;
  prof.type = ProfileType::ellipsoid;
  prof.radius_x = Rx;
  prof.radius_y = Ry;
  NormalProblem problem(g, m, profile_heights(prof, g));
  const NormalSolution s = problem.solve({Control::force, P}, native_normal_solver());
  ASSERT_EQ(s.report.status, SolveStatus::converged);
  double peak = 0.0, x_extent = 0.0, y_extent = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double p = s.pressure[g.index(i, j)];
      peak = std::max(peak, p);
      if (p > 0) {
        x_extent = std::max(x_extent, std::abs(g.xc(i)) + 0.5 * g.dx);
        y_extent = std::max(y_extent, std::abs(g.yc(j)) + 0.5 * g.dy);
      }
    }
  EXPECT_NEAR(s.approach / hz.approach, 1.0, 5e-3);
  EXPECT_NEAR(peak / hz.p0, 1.0, 1.5e-2);
  // Semi-axes from the outermost loaded element edges: within one element.
  EXPECT_NEAR(x_extent, hz.a, 1.01 * g.dx);
  EXPECT_NEAR(y_extent, hz.b, 1.01 * g.dy);
}

TEST(NormalHertz, Cylinder2dHalfWidthAndPressure) {
  const auto m = test::steel_on_aluminium();
  const double R = 0.02, P = 1e5;
  const auto hz = hertz::cylinder2d(R, P, m.E_star());
  double last_error = 1.0;
  for (int n : {64, 256}) {
    const Grid g = Grid::make(2, n, 1, -1.5 * hz.a, 1.5 * hz.a, 0, 0);
    ProfileSpec prof;
    prof.type = ProfileType::cylinder;
    prof.radius = R;
    NormalProblem problem(g, m, profile_heights(prof, g));
    const NormalSolution s = problem.solve({Control::force, P}, native_normal_solver());
    ASSERT_EQ(s.report.status, SolveStatus::converged);
    double peak = 0.0, width = 0.0, pressure_error = 0.0;
    for (int i = 0; i < g.nx; ++i) {
      const double p = s.pressure[i], x = g.xc(i);
      peak = std::max(peak, p);
      width += p > 0 ? g.dx : 0.0;
      const double exact = std::abs(x) < hz.a ? hz.p0 * std::sqrt(1 - x * x / (hz.a * hz.a)) : 0.0;
      pressure_error = std::max(pressure_error, std::abs(p - exact) / hz.p0);
    }
    EXPECT_NEAR(0.5 * width / hz.a, 1.0, 2.0 * g.dx / hz.a);
    EXPECT_NEAR(peak / hz.p0, 1.0, n == 256 ? 2e-3 : 1e-2);
    EXPECT_LT(pressure_error, last_error);
    last_error = pressure_error;
  }
  EXPECT_LT(last_error, 0.08);  // largest pointwise error sits at the edge (square-root profile)
}

TEST(NormalHertz, FlatPunchLoadApproachMatchesBoussinesq) {
  // Rigid punch on one elastic half-space: P = 2 a E* delta (E* = E/(1-nu^2)).
  const MaterialPair m{Elastic::make_rigid(), Elastic::from_E_nu(7e10, 0.33)};
  const double a = 1e-3, delta = 1e-6;
  double last_error = 1.0;
  for (int n : {32, 96}) {
    const Grid g = Grid::make(3, n, n, -1.1 * a, 1.1 * a, -1.1 * a, 1.1 * a);
    ProfileSpec prof;
    prof.type = ProfileType::flat_punch;
    prof.radius = a;
    const auto h = profile_heights(prof, g);
    NormalProblem problem(g, m, h);
    const NormalSolution s = problem.solve({Control::approach, delta}, native_normal_solver());
    ASSERT_EQ(s.report.status, SolveStatus::converged) << s.report.message;
    // Compare with the punch of the same loaded area (the grid's staircase edge).
    double area = 0.0;
    for (double v : h) area += std::isfinite(v) ? g.area() : 0.0;
    const double a_eff = std::sqrt(area / kPi);
    const double error = std::abs(s.force / hertz::flat_punch_force(a_eff, delta, m.E_star()) - 1.0);
    EXPECT_LT(error, last_error);
    last_error = error;
    // The gap vanishes under the punch.
    for (std::size_t i = 0; i < h.size(); ++i)
      if (std::isfinite(h[i])) {
        EXPECT_NEAR(s.gap[i], 0.0, 1e-6 * delta);
      }
  }
  EXPECT_LT(last_error, 0.01);
}

}  // namespace
}  // namespace dc
