// A dynamic run's peaks and their discretisation error (issue 28, docs/accuracy.md), run as a
// program: Hertz's impact (Johnson 11.4: the largest approach (15 m v0^2 / (16 E* R^1/2))^(2/5),
// the contact time 2.9432 of it over v0, the largest force 4/3 E* R^1/2 of it^(3/2)) against
// summary.json "peaks"; the grid estimate not below the true error; a target met against Hertz.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "hertz.hpp"

namespace {

using json = nlohmann::json;
using dc::test::example_json;
using dc::test::slurp;

struct HertzImpact {
  double approach, contact_time, force;
};

/// The closed form of the bundled ball-impact example with its mass, radius, materials, speed.
HertzImpact hertz_impact(const json& c) {
  const double m = c["body"]["mass"], R = c["profile"]["radius"];
  const double v0 = -c["body"]["initial"]["velocity"][2].get<double>();
  const double E = c["materials"]["body"]["E"], nu = c["materials"]["body"]["nu"];
  const dc::hertz::ImpactSolution h = dc::hertz::sphere_impact(R, m, v0, E / (2.0 * (1.0 - nu * nu)));
  return {h.approach, h.duration, h.force};
}

class CliDynamicAccuracy : public dc::test::CliTest {
 protected:
  /// ball-impact with `n` x `n` elements and 280 steps per contact (the time steps' error well
  /// below the grid's), no plots.
  static json impact(int n) {
    json c = example_json("ball-impact");
    c["grid"]["nx"] = c["grid"]["ny"] = n;
    c["time"]["dt"] = 2.5e-7;
    c["output"] = {{"plots", false}};
    return c;
  }
  json solve(const json& c, int expected_exit = 0) const {
    const auto r = run("solve " + write_case(c) + " --out out -q");
    EXPECT_EQ(r.code, expected_exit) << r.err;
    return json::parse(slurp(dir_ / "out" / "summary.json"));
  }
};

TEST_F(CliDynamicAccuracy, PeaksAreHertzsAndTheEstimateIsNotBelowTheirError) {
  for (int n : {32, 48}) {
    json c = impact(n);
    c["accuracy"] = {{"estimate", true}};
    const json s = solve(c);
    const HertzImpact h = hertz_impact(c);
    const json& peaks = s.at("peaks");
    const json& q = s.at("accuracy").at("quantities");
    for (const json& g : s.at("accuracy").at("grids")) EXPECT_EQ(g.at("status"), "completed") << n;
    for (const auto& [name, reference] :
         {std::pair{"max_normal_force", h.force}, {"max_approach", h.approach}, {"contact_time", h.contact_time}}) {
      const double value = peaks.at(name).get<double>(), truth = std::abs(value - reference) / reference;
      // The grid resolves the impact; the contact time (the lowest point's crossings) to 3e-4.
      EXPECT_LT(truth, std::string(name) == "contact_time" ? 3e-4 : 2e-3) << name << " on " << n;
      const double estimate = q.at(name).at("error_estimate").get<double>();
      EXPECT_GE(estimate, truth) << name << " on " << n;
      std::printf("%2d: %-16s true %.2e estimate %.2e (%s)\n", n, name, truth, estimate,
                  q.at(name).at("method").get<std::string>().c_str());
    }
    EXPECT_NEAR(peaks.at("rebound_velocity").get<double>(), 1.0, 2e-3);  // elastic: v0
    EXPECT_EQ(peaks.at("first_touch").get<double>(), 0.0);                // starts touching
  }
}

TEST_F(CliDynamicAccuracy, ATargetChoosesTheGridOfTheWholeRun) {
  json c = impact(16);
  c["accuracy"] = {{"target", 1e-3}, {"quantities", {"max_normal_force", "contact_time"}}};
  const json s = solve(c);
  const json& a = s.at("accuracy");
  ASSERT_TRUE(a.at("met").get<bool>()) << a.dump();
  EXPECT_GT(a.at("refinements").get<int>(), 0);
  EXPECT_EQ(s.at("grid").at("nx"), a.at("grid").at("nx"));
  const HertzImpact h = hertz_impact(c);
  EXPECT_LE(std::abs(s.at("peaks").at("max_normal_force").get<double>() - h.force) / h.force, 1e-3);
  EXPECT_LE(std::abs(s.at("peaks").at("contact_time").get<double>() - h.contact_time) / h.contact_time, 1e-3);
}

TEST_F(CliDynamicAccuracy, TheEstimateIsOptInAndAMissedTargetSaysWhyAndExitsThree) {
  const json plain = solve(impact(16));
  EXPECT_FALSE(plain.contains("accuracy"));
  EXPECT_TRUE(plain.at("peaks").at("contact_time").is_number());
  json c = impact(16);
  c["accuracy"] = {{"target", 3e-4}, {"max_elements", 3000}};
  const json s = solve(c, 3);
  EXPECT_FALSE(s.at("accuracy").at("met").get<bool>());
  EXPECT_EQ(s.at("accuracy").at("stopped_by"), "max_elements");
  // Below the time steps' own error no grid helps: the refinement says so.
  c["accuracy"] = {{"target", 1e-6}};
  const json t = solve(c, 3);
  EXPECT_EQ(t.at("accuracy").at("stopped_by"), "time_steps");
  EXPECT_GT(t.at("accuracy").at("quantities").at("max_normal_force").at("time_error_estimate").get<double>(), 1e-6);
  c["accuracy"] = {{"target", 1e-3}, {"quantities", {"max_pressure"}}};  // a static result
  expect_input_error("solve " + write_case(c) + " --out out2 -q", "accuracy.quantities");
}

/// A sweep's runs each get their estimate, and a target one of them misses exits 3 naming it.
TEST_F(CliDynamicAccuracy, ASweepEstimatesEveryRunAndAMissedTargetExitsThree) {
  json c = example_json("ball-impact-speeds");
  c["grid"]["nx"] = c["grid"]["ny"] = 24;
  c["output"] = {{"plots", false}};
  c["accuracy"] = {{"estimate", true}};
  const json s = solve(c);
  ASSERT_EQ(s.at("runs").size(), c["sweep"]["body.initial.velocity"].size());
  for (const json& run : s.at("runs")) {
    const json& q = run.at("accuracy").at("quantities");
    EXPECT_GT(q.at("contact_time").at("error_estimate").get<double>(), 0.0) << run.at("label");
    EXPECT_GT(q.at("max_normal_force").at("error_estimate").get<double>(), 0.0) << run.at("label");
  }
  c["accuracy"] = {{"target", 1e-7}, {"max_elements", 2304}};  // 48^2 at most: out of reach
  const json missed = solve(c, 3);
  for (const json& run : missed.at("runs")) EXPECT_FALSE(run.at("accuracy").at("met").get<bool>()) << run.at("label");
}

}  // namespace
