// Hertz impact of a sphere on a half-space through problem "dynamic" (Johnson, Contact
// Mechanics, 11.4): with delta_m = (15 m v0^2 / (16 E* R^1/2))^(2/5), the contact lasts
// 2.9432 delta_m / v0, the peak force is 4/3 E* R^1/2 delta_m^3/2 and an elastic impact
// rebounds at v0. The grid (24 elements across 2.6 contact radii) is the error budget: the
// static Hertz force-approach law on it is a few tenths of a percent off, so 2 % on the
// duration and the peak force, 0.5 % on the rebound speed; the energy audit within the rebound's
// loss.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"

namespace dc::dynamics {
namespace {

struct Impact {
  double duration = 0.0, peak = 0.0, rebound = 0.0;
  DynamicResult result;
};

Impact run_impact(nlohmann::json doc) {
  const Case c = build_case(doc);
  DynamicSimulation sim(c);
  Impact out;
  const double R = c.dynamic->radius;
  double t_prev = 0.0, z_prev = c.dynamic->position[2];
  bool left = false;
  out.result = sim.run([&](const DynamicSample& s) {
    out.peak = std::max(out.peak, s.contact.force.z());
    const double z = s.state.position.z();
    if (!left && s.state.time > 0.0 && z > R && z_prev <= R) {
      // The ball leaves the half-space where z crosses R again (linear between steps).
      out.duration = t_prev + (R - z_prev) / (z - z_prev) * (s.state.time - t_prev);
      left = true;
    }
    t_prev = s.state.time;
    z_prev = z;
    out.rebound = s.state.velocity.z();
  });
  return out;
}

struct HertzImpact {
  double duration, peak;
};

HertzImpact hertz_impact(const Case& c, double v0) {
  const double E = c.materials.E_star(), R = c.profile.radius, m = c.dynamic->mass;
  const double delta = std::pow(15.0 * m * v0 * v0 / (16.0 * E * std::sqrt(R)), 0.4);
  return {2.9432 * delta / v0, 4.0 / 3.0 * E * std::sqrt(R) * std::pow(delta, 1.5)};
}

nlohmann::json impact_case(double E_base, double nu_base, double radius, double density, double v0, double steps,
                           const char* scheme) {
  nlohmann::json doc = dc::test::example_json("ball-impact");
  const double m = density * 4.0 / 3.0 * M_PI * radius * radius * radius, I = 0.4 * m * radius * radius;
  doc["materials"]["base"] = {{"E", E_base}, {"nu", nu_base}};
  doc["profile"]["radius"] = radius;
  doc["grid"]["nx"] = doc["grid"]["ny"] = 24;
  doc["body"] = {{"mass", m}, {"inertia", {I, I, I}}, {"radius", radius},
                 {"initial", {{"position", {0, 0, radius}}, {"velocity", {0, 0, -v0}}}}};
  const Case c = build_case(doc);
  const HertzImpact h = hertz_impact(c, v0);
  doc["time"] = {{"dt", h.duration / steps}, {"t_end", 1.1 * h.duration}, {"scheme", scheme}};
  return doc;
}

void expect_hertz(const nlohmann::json& doc, double v0) {
  const Case c = build_case(doc);
  const HertzImpact h = hertz_impact(c, v0);
  const Impact got = run_impact(doc);
  ASSERT_TRUE(got.result.completed) << got.result.status;
  EXPECT_NEAR(got.duration / h.duration, 1.0, 0.02) << "contact time " << got.duration << " vs Hertz " << h.duration;
  EXPECT_NEAR(got.peak / h.peak, 1.0, 0.02) << "peak force " << got.peak << " vs Hertz " << h.peak;
  EXPECT_NEAR(got.rebound / v0, 1.0, 0.005) << "rebound speed";
  // The energy audit: the contact force of an elastic impact does no net work, so the kinetic
  // energy the run reports lost is the scheme's own dissipation, 1 - (rebound / v0)^2, plus the
  // work quadrature's error (trapezoidal: O(dt^2), a few 1e-4 here; the end-of-step force alone
  // made it 4 %).
  const double lost = std::abs(1.0 - std::pow(got.rebound / v0, 2));
  EXPECT_LE(got.result.energy_imbalance, lost + 0.002) << "energy audit vs rebound loss " << lost;
  EXPECT_LE(got.result.worst_certificate, c.solver.certificate_tol);
}

TEST(DynamicImpact, SteelBallOnSteelMatchesHertzImpact) {
  expect_hertz(impact_case(2.1e11, 0.3, 0.01, 7800.0, 1.0, 60, "bdf2"), 1.0);
}

TEST(DynamicImpact, SmallBallOnAluminiumMatchesHertzImpact) {
  expect_hertz(impact_case(7.0e10, 0.33, 0.004, 7800.0, 0.3, 60, "bdf2"), 0.3);
}

TEST(DynamicImpact, Bdf1KeepsMomentumStepByStep) {
  // m (V_end - V_0) = sum dt F_{K+1} exactly for (3.9); the contact impulse reverses the ball.
  const nlohmann::json doc = impact_case(2.1e11, 0.3, 0.01, 7800.0, 1.0, 40, "bdf1");
  const Impact got = run_impact(doc);
  ASSERT_TRUE(got.result.completed) << got.result.status;
  EXPECT_LE(got.result.momentum_imbalance, 1e-8);
  EXPECT_GT(got.rebound, 0.5);  // bdf1 dissipates (O(dt)) but the ball rebounds
  EXPECT_LT(got.rebound, 1.0);
}

}  // namespace
}  // namespace dc::dynamics
