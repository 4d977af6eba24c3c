// A ball launched sliding without spin on a rough half-space (problem "dynamic"): while it
// slides the friction force is mu P, so V = v0 - mu g t and R Omega = 5/2 mu g t (solid ball,
// I = 2/5 m R^2); they meet at t_r = 2 v0 / (7 mu g), after which the ball rolls at 5/7 v0
// (the angular momentum about the contact point is conserved), whatever the microslip.
// Checked with the steady contact model (steps much longer than the contact) and with the
// transient one (steps shorter than a quarter of the contact), each with its stated tolerance.
#include <gtest/gtest.h>

#include <cmath>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"

namespace dc::dynamics {
namespace {

void expect_sliding_then_rolling(nlohmann::json doc, double speed_tol, double onset_tol, const char* model) {
  const Case c = build_case(doc);
  const DynamicSpec& s = *c.dynamic;
  const double v0 = s.velocity[0], g = -s.force[2].value / s.mass, mu = c.friction->mu, R = s.radius;
  const double t_roll = 2.0 * v0 / (7.0 * mu * g);
  DynamicSimulation sim(c);
  double first_stick = -1.0, sliding_error = 0.0;
  const DynamicResult r = sim.run([&](const DynamicSample& x) {
    const double t = x.state.time;
    if (first_stick < 0.0 && x.contact_state.n_stick > 0) first_stick = t;
    if (t < 0.8 * t_roll) sliding_error = std::max(sliding_error, std::abs(x.state.velocity.x() - (v0 - mu * g * t)) / v0);
  });
  ASSERT_TRUE(r.completed) << r.status;
  EXPECT_STREQ(r.contact_model.c_str(), model);
  EXPECT_LE(sliding_error, 1e-3) << "sliding phase: V = v0 - mu g t";
  EXPECT_NEAR(r.final.velocity.x() / (5.0 / 7.0 * v0), 1.0, speed_tol) << "rolling speed";
  EXPECT_NEAR(R * r.final.omega.y() / r.final.velocity.x(), 1.0, speed_tol) << "rolling without sliding";
  EXPECT_NEAR(first_stick, t_roll, onset_tol * t_roll) << "end of sliding";
  EXPECT_LE(r.worst_certificate, c.solver.certificate_tol);
}

nlohmann::json coarse_bowling_ball() {
  nlohmann::json doc = dc::test::example_json("bowling-ball");
  doc["grid"]["nx"] = doc["grid"]["ny"] = 12;
  return doc;
}

TEST(DynamicRolling, BowlingBallSteadyModel) {
  // Steps of 5 ms travel 15 mm, ten contact radii: auto picks the steady model.
  nlohmann::json doc = coarse_bowling_ball();
  doc["time"]["dt"] = 5e-3;
  expect_sliding_then_rolling(doc, 2e-3, 0.02, "steady");
}

TEST(DynamicRolling, SlowBallTransientModel) {
  // 0.3 m/s: t_r = 43.7 ms; steps of 0.2 ms travel 60 um, a twentieth of the contact radius.
  nlohmann::json doc = coarse_bowling_ball();
  doc["body"]["initial"]["velocity"] = {0.3, 0, 0};
  doc["time"] = {{"dt", 2e-4}, {"t_end", 0.06}, {"scheme", "bdf2"}};
  doc["contact_model"] = "auto";
  expect_sliding_then_rolling(doc, 2e-3, 0.02, "transient");
}

}  // namespace
}  // namespace dc::dynamics
