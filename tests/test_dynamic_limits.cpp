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

TEST(DynamicLimits, RefusedBeforeTheRun) {
  nlohmann::json inside = test::coarse_ball_impact();
  inside["body"]["initial"]["position"] = {0.0, 0.0, 0.0099};
  const Case c = build_case(inside);
  try {
    DynamicSimulation sim(c);
    ADD_FAILURE() << "a body starting 100 um inside the half-space was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "body.initial.position");
  }
  nlohmann::json coarse = test::coarse_ball_impact();
  coarse["time"]["dt"] = 5e-5;
  const Case d = build_case(coarse);
  EXPECT_THROW(DynamicSimulation{d}, InputError);
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
