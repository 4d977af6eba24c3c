// A dynamic run with the native solver failing (DYNCONTACT_FAULT=native:fail, read by the tests'
// fault source: tests/support/fault_from_environment.hpp): with
// backend "auto" every contact solve falls back to another backend, the run completes, the
// summary counts the steps that fell back and the backends that solved them, and the motion is
// the one the native solver gives (both solve the same program to the same certificate).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"
#include "fault_from_environment.hpp"

namespace dc::dynamics {
namespace {

/// Sets DYNCONTACT_FAULT for the scope.
struct Fault {
  explicit Fault(const char* value) {
    dc::test::install_faults_from_environment();
    setenv("DYNCONTACT_FAULT", value, 1);
  }
  ~Fault() { unsetenv("DYNCONTACT_FAULT"); }
};

/// The slow bowling ball of test_dynamic_rolling (transient model), coarse and a few steps long:
/// sliding, so every step's contact solve is a full program.
nlohmann::json sliding_ball() {
  nlohmann::json doc = dc::test::example_json("bowling-ball");
  doc["grid"]["nx"] = doc["grid"]["ny"] = 10;
  doc["body"]["initial"]["velocity"] = {0.3, 0, 0};
  doc["time"] = {{"dt", 2e-4}, {"t_end", 2e-3}, {"scheme", "bdf2"}};
  doc["output"] = {{"plots", false}};
  return doc;
}

TEST(DynamicFallback, NativeFailingFallsBackAndSaysSo) {
  const Case c = build_case(sliding_ball());
  ASSERT_EQ(c.solver.backend, Backend::automatic);
  DynamicResult native;
  {
    DynamicSimulation sim(c);
    native = sim.run({});
  }
  ASSERT_TRUE(native.completed) << native.status;
  EXPECT_EQ(native.fallback_steps, 0);
  EXPECT_EQ(native.backends.at("native"), native.steps);
  DynamicResult fallen;
  {
    const Fault fault("native:fail");
    DynamicSimulation sim(c);
    fallen = sim.run({});
  }
  ASSERT_TRUE(fallen.completed) << fallen.status;
  EXPECT_EQ(fallen.fallback_steps, fallen.steps) << "every step in contact fell back";
  EXPECT_EQ(fallen.backends.count("native"), 0u);
  EXPECT_LE(fallen.worst_certificate, c.solver.certificate_tol);
  // The same motion: the velocity change over the run agrees to the solver's accuracy.
  const double dv_native = native.final.velocity.x() - native.initial.velocity.x();
  const double dv_fallen = fallen.final.velocity.x() - fallen.initial.velocity.x();
  EXPECT_NEAR(dv_fallen / dv_native, 1.0, 1e-4);
}

class CliDynamicFallback : public dc::test::CliTest {};

TEST_F(CliDynamicFallback, SummaryNamesTheBackendsUsed) {
  std::ofstream(dir_ / "case.json") << sliding_ball().dump(2);
  use_program_with_faults();
  const Fault fault("native:fail");
  const dc::test::CliResult r = run("solve case.json --out out -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(dc::test::slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(s["solver"]["backend"], "auto");
  EXPECT_EQ(s["solver"]["fallback_steps"], s["steps"]);
  EXPECT_FALSE(s["solver"]["backends_used"].contains("native")) << s["solver"];
  EXPECT_FALSE(s["solver"]["backends_used"].empty());
}

}  // namespace
}  // namespace dc::dynamics
