// A sphere rolling freely on the half-space (no load but gravity, kappa != 0, transient contact
// model). The body's mass on the contact's tangential stiffness is a mode (period of a few
// milliseconds for the bowling ball) that micro-slip and the scheme damp: the creep force must
// settle, and at steady rolling it vanishes (m dV/dt = F_x, and V no longer changes). A contact
// solve whose answer depends on its start (an uncertified alternation, issue 27's stall) kicks
// that mode every few steps and keeps F_x oscillating at about a thousandth of mu F_z.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "case_model.hpp"
#include "dynamic_case_support.hpp"
#include "dynamic_simulation.hpp"

namespace dc::dynamics {
namespace {

/// max - min of F_x over steps [from, to) (1-based step numbers of the samples).
double spread(const std::vector<double>& fx, std::size_t from, std::size_t to) {
  const auto [lo, hi] = std::minmax_element(fx.begin() + static_cast<long>(from), fx.begin() + static_cast<long>(to));
  return *hi - *lo;
}

TEST(DynamicFreeRolling, TheTangentialContactModeDecaysToSteadyRolling) {
  const Case c = build_case(dc::test::free_rolling_bowling_ball(16, 0.04));
  ASSERT_NE(c.materials.kappa(), 0.0);
  DynamicSimulation sim(c);
  std::vector<double> fx;
  double mu_fz = 0.0;
  const DynamicResult r = sim.run([&](const DynamicSample& s) {
    fx.push_back(s.contact.force.x());
    mu_fz = 0.2 * s.contact.force.z();
  });
  ASSERT_TRUE(r.completed) << r.status;
  ASSERT_EQ(fx.size(), 400u);
  EXPECT_LE(r.worst_certificate, c.solver.certificate_tol);
  // The start excites the mode (the ball's creepage is not the contact's), ...
  EXPECT_GT(spread(fx, 0, 100), 1e-2 * mu_fz);
  // ... it decays, and steady rolling carries no creep force (tolerance: a millionth of mu F_z
  // for the spread, ten for the force, the Newton tolerance's share of the force over a step).
  EXPECT_LE(spread(fx, 300, 400), 1e-6 * mu_fz);
  EXPECT_LE(std::abs(fx.back()), 1e-5 * mu_fz);
}

}  // namespace
}  // namespace dc::dynamics
