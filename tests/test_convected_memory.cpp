// The convected memory of a transient step (3.8): the previous relative displacement
// D = kappa B21 p + B22 tau taken at the material point that was at (x + V_x dt, y + V_y dt)
// when the step began, bilinear between whole-element shifts. A step keeps the D of the state
// it leaves (TangentialMemory::displacement), and the next step interpolates it by index shifts
// instead of applying the shifted operators; where the shift needs a value beyond the grid's
// edge and friction acts, the step takes the operators' exact memory. Checked here:
//  - the kept D is the operators' D of (tau, p) to round-off (1e-12 of its largest value);
//  - steps from a memory with its D and from the same memory without it (the operators' path)
//    reach the same state (expect_same_state: the solver's tolerance), and the same slip where
//    friction acts (1e-6 of the largest slip), over a travel of 2.6 + 0.3 elements per step,
//    kappa != 0, and with a contact that reaches into the columns whose shifted source lies
//    beyond the grid (the exact memory there: clamped values would miss by far more).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tangential_support.hpp"

namespace dc {
namespace {

/// Rubber-like body on steel-like base (the bench's bowling ball): kappa != 0.
MaterialPair dissimilar() { return {Elastic::from_G_nu(714e6, 0.4), Elastic::from_G_nu(4615e6, 0.3)}; }

/// D = kappa B21 p + B22 tau of a memory, by the problem's operators.
std::vector<double> operators_displacement(const TangentialProblem& problem, const TangentialMemory& m) {
  std::vector<double> u, w;
  problem.tangential_compliance().apply(m.tau, u);
  if (const LinearOperator* b21 = problem.tangential_from_normal()) {
    b21->apply(m.pressure, w);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] += w[i];
  }
  return u;
}

double max_abs_of(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// Steps of `travel` elements (x, y) with creepages (xi, eta) on an n x n grid over +-extent a:
/// each step once from the kept memory and once from the same memory without its D.
void compare_paths(int n, double extent, const std::array<double, 2>& travel_elements) {
  const MaterialPair m = dissimilar();
  ASSERT_NE(m.kappa(), 0.0);
  const double R = 0.1, P = 200.0, mu = 0.2;
  const test::SphereSetup s = test::sphere_setup(n, extent, m, R, P);
  TangentialProblem kept(s.grid, m, s.heights, FrictionLaw::coulomb(mu));
  TangentialProblem applied(s.grid, m, s.heights, FrictionLaw::coulomb(mu));
  const NormalSpec load{Control::force, P};
  const std::array<double, 2> travel = {travel_elements[0] * s.grid.dx, travel_elements[1] * s.grid.dy};
  const double xi = 0.2 * mu * s.hz.a / R, eta = 0.1 * mu * s.hz.a / R;
  const std::array<double, 3> increment = {travel[0] * xi, travel[0] * eta, 0.0};
  const SolverOptions solver = test::native_tangential_solver();
  for (int step = 1; step <= 8; ++step) {
    const TangentialSolution a = kept.convected_step(load, increment, travel, solver);
    TangentialMemory without = kept.memory();
    // The other problem starts each step from the same state, with its D dropped.
    TangentialMemory previous = applied.memory();
    previous.displacement.clear();
    applied.restore(previous);
    const TangentialSolution b = applied.convected_step(load, increment, travel, solver);
    test::expect_certified(a);
    test::expect_certified(b);
    const std::string where = "step " + std::to_string(step);
    test::expect_same_state(a, b, where);
    double slip_max = 0.0, slip_diff = 0.0;
    for (std::size_t e = 0; e < a.bound.size(); ++e)
      if (b.bound[e] > 0.0) {
        slip_max = std::max({slip_max, std::abs(b.sx[e]), std::abs(b.sy[e])});
        slip_diff = std::max({slip_diff, std::abs(a.sx[e] - b.sx[e]), std::abs(a.sy[e] - b.sy[e])});
      }
    EXPECT_LE(slip_diff, 1e-6 * slip_max) << where << ": the slip where friction acts";
    // The kept D is the operators' D of the state left.
    const std::vector<double> d = operators_displacement(kept, without);
    ASSERT_EQ(without.displacement.size(), d.size()) << where;
    double miss = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) miss = std::max(miss, std::abs(without.displacement[i] - d[i]));
    EXPECT_LE(miss, 1e-12 * max_abs_of(d)) << where;
    // The two problems go on from their own states (equal to the solver's tolerance).
  }
}

TEST(ConvectedMemory, InterpolatedFromTheKeptDisplacementAsTheOperatorsGiveIt) {
  compare_paths(24, 1.4, {2.6, 0.3});
}

TEST(ConvectedMemory, AContactNearTheEdgeTakesTheExactMemoryBeyondIt) {
  // The contact spans all but about one element on each side: the last columns' sources lie
  // beyond the grid by up to three elements.
  compare_paths(20, 1.08, {2.6, 0.0});
}

TEST(ConvectedMemory, AMemoryWithoutItsDisplacementIsCompletedByTheNextStep) {
  const MaterialPair m = dissimilar();
  const test::SphereSetup s = test::sphere_setup(16, 1.4, m, 0.1, 200.0);
  TangentialProblem problem(s.grid, m, s.heights, FrictionLaw::coulomb(0.2));
  const NormalSpec load{Control::force, 200.0};
  const std::array<double, 2> travel = {1.5 * s.grid.dx, 0.0};
  const std::array<double, 3> increment = {1e-4 * travel[0], 0.0, 0.0};
  test::expect_certified(problem.convected_step(load, increment, travel, test::native_tangential_solver()));
  TangentialMemory m1 = problem.memory();
  m1.displacement.clear();
  problem.restore(m1);
  EXPECT_TRUE(problem.memory().displacement.empty());
  test::expect_certified(problem.convected_step(load, increment, travel, test::native_tangential_solver()));
  const TangentialMemory m2 = problem.memory();
  const std::vector<double> d = operators_displacement(problem, m2);
  ASSERT_EQ(m2.displacement.size(), d.size());
  for (std::size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(m2.displacement[i], d[i], 1e-12 * max_abs_of(d));
}

}  // namespace
}  // namespace dc
