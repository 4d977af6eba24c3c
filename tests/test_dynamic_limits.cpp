// The installed library's dynamic run keeps the command line's result limits
// (dynamics/dynamic_limits.hpp): DynamicSimulation refuses what is known wrong before the run
// (InputError naming the key) and returns the limits of the steps it ran in DynamicResult::limits.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_limits.hpp"
#include "dynamic_simulation.hpp"
#include "errors.hpp"

namespace dc::dynamics {
namespace {

bool has_error(const DynamicResult& r, const std::string& key) {
  for (const ResultLimit& l : r.limits)
    if (l.key == key && l.error) return true;
  return false;
}

TEST(DynamicLimits, TheHertzEstimateOfAnImpact) {
  // Johnson 11.4: the 10 mm steel ball at 1 m/s, contact time 2.94 delta_max / v0 = 69 us.
  const Case c = build_case(test::coarse_ball_impact());
  const auto e = estimate_dynamic_contact(c);
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR(e->contact_time, 6.89e-5, 0.01e-5);
  EXPECT_NEAR(e->load, 1744.0, 5.0);
  EXPECT_NEAR(e->steps_per_contact, e->contact_time / 2e-6, 1e-9);
  EXPECT_EQ(e->start_inside, 0.0);
}

TEST(DynamicLimits, ABodyStartedInsideIsSizedAsTheImpactItsEnergyMakes) {
  // At rest 20 um inside: the load is the Hertz force K d0^1.5 (K = 4/3 E* sqrt(R)) and the
  // contact time the whole impact's 2.9432 d0 / v, v = sqrt(2 x 0.4 K d0^2.5 / m).
  nlohmann::json inside = test::coarse_ball_impact();
  inside["body"]["initial"]["position"] = {0.0, 0.0, 0.01 - 2e-5};
  inside["body"]["initial"]["velocity"] = {0.0, 0.0, 0.0};
  const Case c = build_case(inside);
  const auto e = estimate_dynamic_contact(c);
  ASSERT_TRUE(e.has_value());
  const double K = 4.0 / 3.0 * 210e9 / (2.0 * (1.0 - 0.09)) * std::sqrt(0.01);
  const double v = std::sqrt(0.8 * K * std::pow(2e-5, 2.5) / 0.032673);
  EXPECT_NEAR(e->start_inside, 2e-5, 1e-12);
  EXPECT_NEAR(e->load / (K * std::pow(2e-5, 1.5)), 1.0, 1e-3);
  EXPECT_NEAR(e->contact_time / (2.9432 * 2e-5 / v), 1.0, 1e-3);
  DynamicSimulation sim(c);  // taken: the run releases it
}

TEST(DynamicLimits, APressedStartUnderAStaticLoadIsReleasedOnlyWithEnoughEnergy) {
  // Under P = 100 N the ball rests at d_s = (P/K)^(2/3) and is thrown off only when its stored
  // energy 2/5 K d0^2.5 exceeds the work P d0 of lifting it out, d0 > (2.5 P/K)^(2/3) = 1.84 d_s;
  // below that it stays in contact, its deepest approach where U(d) - P d = U(d0) - P d0.
  const double K = 4.0 / 3.0 * 210e9 / (2.0 * (1.0 - 0.09)) * std::sqrt(0.01), P = 100.0;
  const double d_s = std::pow(P / K, 2.0 / 3.0), d_release = std::pow(2.5 * P / K, 2.0 / 3.0);
  const auto start = [&](double d0) {
    nlohmann::json doc = test::coarse_ball_impact();
    doc["body"]["initial"]["position"] = {0.0, 0.0, 0.01 - d0};
    doc["body"]["initial"]["velocity"] = {0.0, 0.0, 0.0};
    doc["loads"] = {{"force", {{"z", {{"value", -P}}}}}};
    return *estimate_dynamic_contact(build_case(doc));
  };
  const DynamicContactEstimate rest = start(d_s);
  EXPECT_NEAR(rest.load / P, 1.0, 1e-9);
  EXPECT_EQ(rest.contact_time, 0.0);
  const DynamicContactEstimate kept = start(0.99 * d_release);
  EXPECT_NEAR(kept.load / (K * std::pow(0.99 * d_release, 1.5)), 1.0, 1e-9);
  EXPECT_EQ(kept.contact_time, 0.0);
  // From d_s / 2 at rest it swings beyond d_s to d with d^2.5 - 2.5 d_s^1.5 d = the same at d_s / 2.
  const DynamicContactEstimate swing = start(0.5 * d_s);
  const double d = std::pow(swing.load / K, 2.0 / 3.0);
  const auto g = [&](double x) { return std::pow(x, 2.5) - 2.5 * std::pow(d_s, 1.5) * x; };
  EXPECT_GT(d, d_s);
  EXPECT_NEAR(g(d) / g(0.5 * d_s), 1.0, 1e-9);
  EXPECT_GT(start(1.01 * d_release).contact_time, 0.0);
}

TEST(DynamicLimits, ALoadAppliedAtOnceSizesTheContactForItsOvershoot) {
  // At rest on the surface, P applied at once: the body swings to U(d) = P d, the force
  // K d^1.5 = 2.5 P (twice the static approach's energy), and oscillates in contact (no release).
  const double K = 4.0 / 3.0 * 210e9 / (2.0 * (1.0 - 0.09)) * std::sqrt(0.01), P = 1000.0, m = 0.032673;
  const auto start = [&](double gap) {
    nlohmann::json doc = test::coarse_ball_impact();
    doc["body"]["initial"]["position"] = {0.0, 0.0, 0.01 + gap};
    doc["body"]["initial"]["velocity"] = {0.0, 0.0, 0.0};
    doc["loads"] = {{"force", {{"z", {{"value", -P}}}}}};
    return *estimate_dynamic_contact(build_case(doc));
  };
  const DynamicContactEstimate touching = start(0.0);
  EXPECT_NEAR(touching.load / P, 2.5, 1e-9);
  EXPECT_EQ(touching.contact_time, 0.0);
  // Falling from a gap h at rest: the load's work P h is the impact's energy at first touch;
  // the deepest approach has 2/5 K d^2.5 - P d = P h, the contact time Hertz's at sqrt(2 P h / m).
  const double h = 1e-5;
  const DynamicContactEstimate falling = start(h);
  const double d = std::pow(falling.load / K, 2.0 / 3.0);
  EXPECT_NEAR((0.4 * K * std::pow(d, 2.5) - P * d) / (P * h), 1.0, 1e-9);
  const double v = std::sqrt(2.0 * P * h / m), d_star = std::pow(1.25 * m * v * v / K, 0.4);
  EXPECT_NEAR(falling.contact_time / (2.9432 * d_star / v), 1.0, 1e-3);
}

TEST(DynamicLimits, RefusedBeforeTheRun) {
  nlohmann::json coarse = test::coarse_ball_impact();
  coarse["time"]["dt"] = 5e-5;
  const Case d = build_case(coarse);
  try {
    DynamicSimulation sim(d);
    ADD_FAILURE() << "1.4 steps per contact were taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "time.dt");
  }
}

TEST(DynamicLimits, TheRunsLimitsAreInItsResult) {
  const Case resolved = build_case(test::coarse_ball_impact());  // outlives the simulation, which refers to it
  DynamicSimulation fine(resolved);
  const DynamicResult good = fine.run({});
  EXPECT_TRUE(good.completed);
  EXPECT_TRUE(good.limits.empty());
  // A step of 7 per contact, accepted: the energy balance (0.2) is a limit error naming time.dt.
  nlohmann::json doc = test::coarse_ball_impact();
  doc["time"]["dt"] = 1e-5;
  doc["time"]["allow_coarse_dt"] = true;
  const Case c = build_case(doc);
  DynamicSimulation coarse(c);
  const DynamicResult r = coarse.run({});
  EXPECT_GT(r.energy_imbalance, 0.05);
  EXPECT_TRUE(has_error(r, "time.dt"));
}

}  // namespace
}  // namespace dc::dynamics
