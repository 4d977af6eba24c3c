// `dyncontact solve` of a dynamic body whose profile is defined upright only (docs/dynamics.md,
// "Body shapes"): spun about a horizontal axis it is rejected with exit 2, the key and the time;
// the same ball given as an ellipsoid (which can tilt) runs.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {
namespace {

using nlohmann::json;

class CliTiltedBody : public CliTest {
 protected:
  /// The ball-impact example, coarse and short, spinning about y, with the profile `profile`.
  std::string case_file(const json& profile) const {
    json doc = example_json("ball-impact");
    doc["grid"]["nx"] = doc["grid"]["ny"] = 12;
    doc["time"]["dt"] = 2e-6;
    doc["time"]["t_end"] = 2e-5;
    doc["output"] = {{"plots", false}};
    doc["profile"] = profile;
    doc["body"]["initial"]["omega"] = {0.0, 50.0, 0.0};
    return write_case(doc);
  }
};

TEST_F(CliTiltedBody, UprightOnlyProfileThatTiltsIsAnInputErrorAtThatTime) {
  const double R = 0.01;
  const std::string quadratic = case_file({{"type", "quadratic"}, {"a", 0.5 / R}, {"b", 0.5 / R}});
  const CliResult r = run("solve " + quadratic + " --out out -q");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("error: profile.type: at t = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ellipsoid"), std::string::npos) << r.err;
  // The run stopped cleanly at that step: the steps before it written, the summary says why.
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(s["status"], "stopped");
  EXPECT_NE(s["message"].get<std::string>().find("profile.type"), std::string::npos) << s["message"];
  EXPECT_EQ(slurp(dir_ / "out" / "timeseries.csv").empty(), false);
  const std::string ellipsoid = case_file({{"type", "ellipsoid"}, {"radius_x", R}, {"radius_y", R}});
  const CliResult ok = run("solve " + ellipsoid + " --out ok -q");
  EXPECT_EQ(ok.code, 0) << ok.err;
}

}  // namespace
}  // namespace dc::test
