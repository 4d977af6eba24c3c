// The in-step Newton with the contact's exact linearisation (contact_sensitivity: stick and
// slip sets fixed, the pressure following the traction for dissimilar materials, kappa != 0)
// converges quadratically: from the last step's state a step under partial slip takes at most
// two iterations (the first leaves the linearisation error, O(step change^2), the second
// reaches the tolerance). The polyurethane bowling ball on maple (kappa != 0) rolling with a
// small creepage, transient contact model.
#include <gtest/gtest.h>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"

namespace dc::dynamics {
namespace {

TEST(DynamicNewton, PartialSlipStepsConvergeInTwoIterationsWithDissimilarMaterials) {
  nlohmann::json doc = dc::test::example_json("bowling-ball");
  doc["grid"]["nx"] = doc["grid"]["ny"] = 12;
  const double V = 0.3, R = doc["body"]["radius"].get<double>();
  doc["body"]["initial"]["velocity"] = {V, 0, 0};
  doc["body"]["initial"]["omega"] = {0, (1.0 - 3e-3) * V / R, 0};  // creepage 0.3%: partial slip
  doc["time"] = {{"dt", 2e-4}, {"t_end", 6e-3}, {"scheme", "bdf2"}};
  doc["contact_model"] = "transient";
  const Case c = build_case(doc);
  ASSERT_NE(c.materials.kappa(), 0.0);
  DynamicSimulation sim(c);
  int partial = 0, worst = 0;
  const DynamicResult r = sim.run([&](const DynamicSample& s) {
    if (s.contact_state.n_stick > 0 && s.contact_state.n_slip > 0) {
      ++partial;
      worst = std::max(worst, s.newton_iterations);
    }
  });
  ASSERT_TRUE(r.completed) << r.status;
  EXPECT_GT(partial, r.steps / 2) << "partial slip";
  EXPECT_LE(worst, 2) << "Newton iterations of a partial-slip step";
  EXPECT_EQ(r.rejected_steps, 0);
}

}  // namespace
}  // namespace dc::dynamics
