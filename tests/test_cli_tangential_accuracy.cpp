// The error estimate of a tangential history given by heights (apps/runs/tangential_accuracy.hpp;
// the Python tests take it through TangentialProblem): the recorded calls are bounded, and a
// stretch of the history longer than the bound makes the estimate unavailable, saying why, until
// reset(); a coarse history that breaks off (every backend failing there) leaves the fine answer
// and says which call on which grid, until reset(). (In cli_tests: it is part of dyncontact_runs.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fault_injection.hpp"
#include "tangential_accuracy.hpp"

namespace cli_tangential_accuracy_test {  // named: the unity build shares one translation unit

/// Cattaneo on a steel sphere (R = 10 mm, 100 N, a = 0.187 mm, mu 0.3) on 32^2 elements over
/// +-0.26 mm, given by its heights.
struct SteelSphere {
  dc::Grid g = dc::Grid::make(3, 32, 32, -2.6e-4, 2.6e-4, -2.6e-4, 2.6e-4);
  std::vector<double> h = heights(g);
  dc::MaterialPair steel{dc::Elastic::from_E_nu(2.1e11, 0.3), dc::Elastic::from_E_nu(2.1e11, 0.3)};
  dc::FrictionLaw friction = dc::FrictionLaw::coulomb(0.3);
  static std::vector<double> heights(const dc::Grid& g) {
    std::vector<double> h(g.size());
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) h[g.index(i, j)] = (g.xc(i) * g.xc(i) + g.yc(j) * g.yc(j)) / 0.02;
    return h;
  }
};

TEST(TangentialAccuracy, AHistoryLongerThanTheRecordedCallsSaysWhyItHasNoEstimateUntilReset) {
  const SteelSphere sphere;
  dc::TangentialProblem fine(sphere.g, sphere.steel, sphere.h, sphere.friction);
  dc::runs::TangentialAccuracy accuracy(sphere.g, sphere.steel, sphere.h, sphere.friction, dc::OperatorKind::automatic, 3);
  const dc::SolverOptions solver;
  const auto step = [&](double q) {
    dc::runs::TangentialCall call;
    call.step_load.normal = {dc::Control::force, 100.0};
    call.step_load.modes[0] = {dc::ModeControl::Kind::resultant, -q};
    call.solver = solver;
    const dc::TangentialSolution s = fine.step(call.step_load, solver);
    accuracy.record(call, s.report.backend);
    return s;
  };
  for (double q : {3.0, 6.0, 9.0}) step(q);
  const nlohmann::json kept = accuracy.estimate(step(12.0), 1.0);  // the 4th call: one more than kept
  ASSERT_TRUE(kept.contains("unavailable"));
  EXPECT_NE(kept["unavailable"].get<std::string>().find("more than 3 calls"), std::string::npos) << kept.dump();
  fine.reset();
  accuracy.reset();
  const nlohmann::json again = accuracy.estimate(step(12.0), 1.0);
  ASSERT_FALSE(again.contains("unavailable")) << again.dump();
  ASSERT_EQ(again["grids"].size(), 3u);
  EXPECT_EQ(again["quantities"]["rigid_shift"]["method"], "band");
  // Estimates every call keep the record empty: a history of any length.
  for (double q : {9.0, 6.0, 3.0, 6.0, 9.0}) EXPECT_FALSE(accuracy.estimate(step(q), 1.0).contains("unavailable"));
}

TEST(TangentialAccuracy, ACoarseHistoryThatBreaksOffSaysWhichCallUntilReset) {
  const SteelSphere sphere;
  dc::TangentialProblem fine(sphere.g, sphere.steel, sphere.h, sphere.friction);
  dc::runs::TangentialAccuracy accuracy(sphere.g, sphere.steel, sphere.h, sphere.friction, dc::OperatorKind::automatic);
  dc::runs::TangentialCall call;
  call.step_load.normal = {dc::Control::force, 100.0};
  call.step_load.modes[0] = {dc::ModeControl::Kind::resultant, -15.0};
  const dc::TangentialSolution s = fine.step(call.step_load, call.solver);
  ASSERT_EQ(s.report.status, dc::SolveStatus::converged);
  accuracy.record(call, s.report.backend);
  // Every backend fails on the coarse grids (the fine step was solved before).
  dc::set_fault_source([](const std::string& target) { return target == "outer" ? dc::Fault::none : dc::Fault::fail; });
  const nlohmann::json broken = accuracy.estimate(s, 1.0);
  dc::set_fault_source(nullptr);
  ASSERT_TRUE(broken.contains("unavailable")) << broken.dump();
  EXPECT_NE(broken["unavailable"].get<std::string>().find("call 1 of the history on the grid of 16 x 16"),
            std::string::npos)
      << broken["unavailable"];
  EXPECT_TRUE(accuracy.estimate(s, 1.0).contains("unavailable")) << "until reset";
  fine.reset();
  accuracy.reset();
  const dc::TangentialSolution again = fine.step(call.step_load, call.solver);
  accuracy.record(call, again.report.backend);
  const nlohmann::json mended = accuracy.estimate(again, 1.0);
  EXPECT_FALSE(mended.contains("unavailable")) << mended.dump();
}

}  // namespace cli_tangential_accuracy_test
