// What one path said and another contradicted: a history's top-level status against its steps,
// validate against solve, a message naming a block the case may not have, numbers beyond any
// physical body, a fraction of a division, a limit nobody accepted reported as accepted, and
// creepages at round-off (a table through zero, creepages of 1e-12).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {
namespace {

using nlohmann::json;

using CliConsistency = CliTest;

std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

TEST_F(CliConsistency, AHistoryIsAsConvergedAsItsWorstStep) {
  // The second step's kappa loop forced to stall (test-only fault injection): exit 3, and the
  // top-level solver status is that step's, not the last step's "converged".
  use_program_with_faults();
  json doc = example_json("spence-sphere");
  doc["grid"]["nx"] = doc["grid"]["ny"] = 16;
  doc["output"] = {{"plots", false}};
  const CliResult r = run_prefixed("DYNCONTACT_FAULT=outer:stall@2", "solve " + write_case(doc) + " -q --out h");
  EXPECT_EQ(r.code, 3) << r.err;
  const json s = json::parse(slurp(dir_ / "h" / "summary.json"));
  EXPECT_FALSE(s["all_steps_converged"].get<bool>());
  EXPECT_NE(s["solver"]["status"], "converged");
  EXPECT_EQ(s["solver"]["step"], 1);
  EXPECT_EQ(s["steps"][1]["solver"]["status"], s["solver"]["status"]);
  EXPECT_EQ(s["steps"][2]["solver"]["status"], "converged");
}

TEST_F(CliConsistency, ValidateRefusesADenseOperatorSolveCouldNotBuild) {
  const std::string file = write_case(example_json("hertz-sphere"));
  expect_input_error("validate " + file + " --set grid.nx=256 --set grid.ny=256 --set solver.operator=dense",
                     "solver.operator");
  expect_input_error("solve " + file + " -q --set grid.nx=256 --set grid.ny=256 --set solver.operator=dense",
                     "solver.operator");
  const CliResult small = run("validate " + file + " --set grid.nx=32 --set grid.ny=32 --set solver.operator=dense");
  EXPECT_EQ(small.code, 0) << small.err;
}

TEST_F(CliConsistency, ADynamicCaseWithoutALoadOrImpactNamesWhatSizesItsGrid) {
  const std::string file = write_case(example_json("ball-impact"));
  const CliResult r = run("validate " + file + " --set 'body.initial.velocity=[0,0,0]'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("grid.extent"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("loads.force.z"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("normal.force"), std::string::npos) << r.err;  // a dynamic case has no normal block
}

TEST_F(CliConsistency, NumbersBeyondAnyPhysicalBodyAreBadInput) {
  const std::string ball = write_case(example_json("ball-impact"), "ball.json");
  expect_input_error("validate " + ball + " --set body.radius=1e300", "body.radius");
  expect_input_error("validate " + ball + " --set 'body.initial.omega=[0,1e300,0]'", "body.initial.omega[1]");
  expect_input_error("validate " + ball + " --set 'body.initial.velocity=[1e300,0,-1]'", "body.initial.velocity[0]");
  expect_input_error("validate " + ball + " --set body.mass=1e300", "body.mass");
  expect_input_error("validate " + ball + " --set 'loads={\"force\": {\"z\": {\"value\": -1e300}}}'",
                     "loads.force.z.value");
  const std::string sphere = write_case(example_json("hertz-sphere"), "sphere.json");
  expect_input_error("validate " + sphere + " --set profile.radius=1e300", "profile.radius");
  expect_input_error("validate " + sphere + " --set normal.force=1e300", "normal.force");
  expect_input_error("validate " + sphere + " --set solver.tol=1e300", "solver.tol");
  const std::string rolling = write_case(example_json("rolling-sphere"), "rolling.json");
  expect_input_error("validate " + rolling + " --set friction.mu=1e300", "friction.mu");
}

TEST_F(CliConsistency, FiniteBodyDivisionsAreWholeAndTheTiltSmall) {
  const std::string file = write_case(example_json("finite-hemisphere"));
  expect_input_error("validate " + file + " --set 'fe_body.elements=[8,8,4.5]'", "fe_body.elements[2]");
  expect_input_error("validate " + file + " --set 'fe_body.tilt=[0.5,0]'", "fe_body.tilt");
}

TEST_F(CliConsistency, TheReadmeTableThroughZeroCreepageConverges) {
  // -0.006:0.006:13 holds 0 (it was computed as 8.7e-19, which Newton could not certify).
  const CliResult r = run("table " + example_path("rolling-sphere") +
                          " --creepage -0.006:0.006:13 --lateral 0,0.002 -q --set grid.nx=16 --set grid.ny=16 "
                          "--set output.plots=false --out tab");
  ASSERT_EQ(r.code, 0) << r.err;
  const json t = json::parse(slurp(dir_ / "tab" / "table.json"));
  EXPECT_EQ(t["ranges"]["creepage_x"][6].get<double>(), 0.0) << t["ranges"].dump();
  EXPECT_EQ(t["ranges"]["creepage_x"][0].get<double>(), -0.006);
  EXPECT_EQ(t["ranges"]["creepage_x"][12].get<double>(), 0.006);
  EXPECT_EQ(t["points"], 26);
  EXPECT_TRUE(t["failed"].empty()) << t["failed"].dump();
}

TEST_F(CliConsistency, ATableOnAContactCutByTheGridIsRefused) {
  // The contact every point shares reaches the grid's edge: no table (exit 2 naming grid).
  const CliResult r = run("table " + example_path("rolling-sphere") +
                          " --creepage 0:0.002:3 -q --set grid.nx=16 --set grid.ny=16 --set grid.extent=0.6 "
                          "--set output.plots=false --out cut");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("error: grid: the contact of the table's load"), std::string::npos) << r.err;
  // A resolved one: its (empty) limits in table.json.
  const CliResult ok = run("table " + example_path("rolling-sphere") +
                           " --creepage 0:0.002:3 -q --set grid.nx=16 --set grid.ny=16 --set output.plots=false "
                           "--out ok");
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(json::parse(slurp(dir_ / "ok" / "table.json"))["limits"].empty());
}

TEST_F(CliConsistency, RunningOutOfMemoryNamesWhatToReduce) {
  // 2048 x 2048 elements under a 600 MB address-space limit (was: exit 4 "internal:
  // std::bad_alloc"). AddressSanitizer reserves terabytes of address space: not under it.
  if (DYNCONTACT_SANITIZED) GTEST_SKIP() << "an address-space limit is not for a sanitizer build";
  const CliResult r = run_prefixed("ulimit -v 600000;", "solve " + example_path("hertz-sphere") +
                                                            " -q --out oom --set grid.nx=2048 --set grid.ny=2048");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("more memory than this machine has"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("grid.nx"), std::string::npos) << r.err;
}

TEST_F(CliConsistency, CreepagesAtRoundOffAreSolvedAndLinear) {
  // In full stick the creep force is linear in the creepage (Kalker's C11): the force per unit
  // creepage at 1e-12 and 1e-6 agree, both certified.
  const auto force_per_creepage = [&](double xi, const std::string& out) {
    const CliResult r = run("solve " + example_path("rolling-sphere") + " -q --out " + out +
                            " --set grid.nx=16 --set grid.ny=16 --set output.plots=false --set 'tangential.creepage=[" +
                            number(xi) + ",0]'");
    EXPECT_EQ(r.code, 0) << r.err;
    const json s = json::parse(slurp(dir_ / out / "summary.json"));
    EXPECT_EQ(s["solver"]["status"], "converged");
    return s["tangential_force"][0].get<double>() / xi;
  };
  const double tiny = force_per_creepage(1e-12, "tiny"), small = force_per_creepage(1e-6, "small");
  EXPECT_LT(small, 0.0);
  EXPECT_NEAR(tiny / small, 1.0, 1e-3);
}

}  // namespace
}  // namespace dc::test
