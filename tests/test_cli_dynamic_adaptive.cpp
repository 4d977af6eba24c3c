// `dyncontact solve` with time.adaptive: summary.json's time_steps (CASES.md) and the stdout
// line, time_steps for a fixed-step run too, a tolerance that cannot be met at time.dt_min
// stopping with exit 3 and the reason, and a bad tolerance exit 2 naming the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {
namespace {

using nlohmann::json;

class CliDynamicAdaptive : public CliTest {
 protected:
  /// The coarse ball impact (12^2, from touching at 1 m/s) with adaptive steps at `rtol`.
  std::string adaptive_case(double rtol, double dt_min = 0.0) const {
    json doc = coarse_ball_impact();
    doc["time"] = {{"dt", 1e-6}, {"t_end", 8e-5}, {"scheme", "bdf2"}, {"adaptive", true}, {"rtol", rtol}};
    if (dt_min > 0.0) doc["time"]["dt_min"] = dt_min;
    return write_case(doc);
  }
};

TEST_F(CliDynamicAdaptive, SummaryAndStdoutReportTheSteps) {
  const CliResult r = run("solve " + adaptive_case(1e-3) + " --out out");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("adaptive time steps: "), std::string::npos) << r.out;
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  const json& ts = s["time_steps"];
  EXPECT_EQ(ts["adaptive"], true);
  EXPECT_EQ(ts["accepted"], s["steps"]);
  EXPECT_EQ(ts["rejected"], s["rejected_steps"]);
  EXPECT_EQ(ts["rejected"].get<int>(), ts["error_rejections"].get<int>() + ts["event_rejections"].get<int>());
  EXPECT_EQ(ts["events"], 2);  // the touch and the release
  EXPECT_GT(ts["dt_min"].get<double>(), 0.0);
  EXPECT_LT(ts["dt_min"].get<double>(), ts["dt_max"].get<double>());
  EXPECT_LE(ts["dt_max"].get<double>(), 8e-6);  // the default dt_max, t_end / 10
  EXPECT_GT(s["final"]["velocity"][2].get<double>(), 0.99);  // rebounded
}

TEST_F(CliDynamicAdaptive, FixedStepsReportTheirStepsToo) {
  const CliResult r = run("solve " + write_case(coarse_ball_impact()) + " --out out -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json ts = json::parse(slurp(dir_ / "out" / "summary.json"))["time_steps"];
  EXPECT_EQ(ts["adaptive"], false);
  EXPECT_EQ(ts["accepted"], 40);
  EXPECT_EQ(ts["rejected"], 0);
  EXPECT_NEAR(ts["dt_min"].get<double>(), 2e-6, 1e-18);
  EXPECT_NEAR(ts["dt_max"].get<double>(), 2e-6, 1e-18);
  EXPECT_FALSE(ts.contains("events"));
}

TEST_F(CliDynamicAdaptive, AToleranceUnreachableAtDtMinStopsWithExit3) {
  const CliResult r = run("solve " + adaptive_case(1e-8, 1e-6) + " --out out -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("time.dt_min"), std::string::npos) << r.err;
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(s["status"], "stopped");
  EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / "timeseries.csv"));
}

TEST_F(CliDynamicAdaptive, BadToleranceIsAnInputErrorNamingTheKey) {
  expect_input_error("validate " + adaptive_case(0.5), "time.rtol");
  expect_input_error("solve " + adaptive_case(-1.0) + " --out bad -q", "time.rtol");
}

}  // namespace
}  // namespace dc::test
