// The result limits of problem "dynamic" (dynamics/dynamic_limits.hpp): what is known wrong before
// the run is refused with exit 2 naming the key (validate says so too), what a run shows at any
// step is in summary.json's "limits" with exit 2, and what the case accepts is recorded as such.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {
namespace {

using nlohmann::json;

class CliDynamicLimits : public CliTest {
 protected:
  /// coarse_ball_impact (R = 10 mm steel ball at 1 m/s: Hertz contact time 69 us, peak force
  /// 1.74 kN) with `edit` applied.
  std::string ball(const std::function<void(json&)>& edit = {}) const {
    json doc = coarse_ball_impact();
    if (edit) edit(doc);
    return write_case(doc);
  }
  /// The summary's limits entry for `key` at `level` (null when none).
  static json find_limit(const json& summary, const std::string& key, const std::string& level) {
    for (const json& l : summary["limits"])
      if (l["key"] == key && l["level"] == level) return l;
    return json();
  }
};

TEST_F(CliDynamicLimits, TheExampleHasNoLimits) {
  const CliResult r = run("solve " + ball() + " -q --out ok");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "ok" / "summary.json"));
  EXPECT_TRUE(s["limits"].is_array());
  EXPECT_TRUE(s["limits"].empty()) << s["limits"].dump();
  EXPECT_LT(s["balances"]["energy"].get<double>(), 0.05);
}

TEST_F(CliDynamicLimits, AGridSmallerThanTheHertzContactIsRefusedBeforeTheRun) {
  // extent 0.4: the grid spans 0.8 of the Hertz contact's width (all elements in contact, peak
  // force 26 % low before this check).
  const std::string file = ball([](json& d) { d["grid"]["extent"] = 0.4; });
  expect_input_error("validate " + file, "grid");
  expect_input_error("solve " + file + " -q --out cut", "grid");
  const CliResult r = run("solve " + ball([](json& d) {
                            d["grid"]["extent"] = 0.4;
                            d["grid"]["allow_edge_contact"] = true;
                          }) + " -q --out accepted");
  EXPECT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "accepted" / "summary.json"));
  const json l = find_limit(s, "grid", "warning");
  ASSERT_FALSE(l.is_null()) << s["limits"].dump();
  EXPECT_TRUE(l["accepted"].get<bool>());
}

TEST_F(CliDynamicLimits, AContactThatOutgrowsTheGridDuringTheRunIsAnError) {
  // A ball pressed by 100 N growing at 2e7 N/s: the grid is sized for 100 N (Hertz), the load
  // reaches 100 + 2e7 x 8e-5 = 1700 N, whose contact (a x 2.6) passes the grid's edge (1.3 a).
  const std::string file = ball([](json& d) {
    d["body"]["initial"]["velocity"] = {0.0, 0.0, 0.0};
    d["loads"] = {{"force", {{"z", {{"value", -100.0}, {"rate", -2e7}}}}}};
  });
  const CliResult r = run("solve " + file + " -q --out grown");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("error: grid: at t = "), std::string::npos) << r.err;
  const json s = json::parse(slurp(dir_ / "grown" / "summary.json"));
  EXPECT_FALSE(find_limit(s, "grid", "error").is_null()) << s["limits"].dump();
}

TEST_F(CliDynamicLimits, ABodyStartedPressedIntoTheHalfSpaceIsReleasedAsHertzSays) {
  // The ball at rest, 20 um inside the half-space: its stored Hertz energy U = 0.4 K d0^2.5
  // (K = 4/3 E* sqrt(R)) throws it off at sqrt(2U/m) after the second half of a Hertz impact,
  // 1.4716 d0 / v (Johnson 11.4: the whole impact lasts 2.9432 d_max / v0), from the force
  // K d0^1.5. Tolerances hold on 12 x 12 elements with dt = 5e-7 (72 steps in contact).
  const double R = 0.01, m = 0.032673, d0 = 2e-5;
  const double E_star = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));
  const double K = 4.0 / 3.0 * E_star * std::sqrt(R);
  const double v = std::sqrt(2.0 * 0.4 * K * std::pow(d0, 2.5) / m);
  const auto released = [&](double dt) {
    return ball([&](json& d) {
      d["body"]["initial"]["position"] = {0.0, 0.0, R - d0};
      d["body"]["initial"]["velocity"] = {0.0, 0.0, 0.0};
      d["time"]["t_end"] = 6e-5;
      d["time"]["dt"] = dt;
    });
  };
  CliResult r = run("solve " + released(5e-7) + " -q --out release");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "release" / "summary.json"));
  EXPECT_TRUE(s["limits"].empty()) << s["limits"].dump();
  const json& peaks = s["peaks"];
  EXPECT_NEAR(peaks["rebound_velocity"].get<double>() / v, 1.0, 3e-3);
  EXPECT_NEAR(peaks["contact_time"].get<double>() / (1.4716 * d0 / v), 1.0, 2e-3);
  EXPECT_NEAR(peaks["max_normal_force"].get<double>() / (K * std::pow(d0, 1.5)), 1.0, 3e-3);
  // BDF2's momentum balance (the trapezoidal impulse) is second order in dt.
  const double momentum = s["balances"]["momentum"].get<double>();
  EXPECT_LT(momentum, 1e-4);
  r = run("solve " + released(2.5e-7) + " -q --out finer");
  ASSERT_EQ(r.code, 0) << r.err;
  const json f = json::parse(slurp(dir_ / "finer" / "summary.json"));
  EXPECT_LT(f["balances"]["momentum"].get<double>(), momentum / 3.0);
  // At z = 0 the ball's centre is on the surface: its contact (a = R) is no half-space contact.
  const std::string sunk = ball([](json& d) {
    d["body"]["initial"]["position"] = {0.0, 0.0, 0.0};
    d["body"]["initial"]["velocity"] = {0.0, 0.0, 0.0};
  });
  expect_input_error("validate " + sunk, "materials");
  expect_input_error("solve " + sunk + " -q --out sunk", "materials");
}

TEST_F(CliDynamicLimits, ALoadAppliedAtRestOnTheSurfaceSizesTheGridForItsOvershoot) {
  // 1 kN applied at once to the ball resting on the surface: it swings to U(d) = P d, the force
  // 2.5 P (Hertz), a contact 2.5^(1/3) = 1.36 times the static one's: the grid sized for P would
  // be cut by its edge (extent 1.3); sized for the motion's deepest approach it holds the contact.
  // Tolerance on 12 x 12 elements with dt = 5e-7 (bdf2); at 1e-6 the energy balance (0.11) fails.
  const std::string file = ball([](json& d) {
    d["body"]["initial"]["velocity"] = {0.0, 0.0, 0.0};
    d["loads"] = {{"force", {{"z", {{"value", -1000.0}}}}}};
    d["time"]["t_end"] = 1.2e-4;
    d["time"]["dt"] = 5e-7;
  });
  const CliResult r = run("solve " + file + " -q --out swing");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "swing" / "summary.json"));
  EXPECT_TRUE(s["limits"].empty()) << s["limits"].dump();
  EXPECT_NEAR(s["peaks"]["max_normal_force"].get<double>() / 2500.0, 1.0, 1e-2);
}

TEST_F(CliDynamicLimits, ATimeStepTooCoarseForTheImpactIsRefusedOrAccepted) {
  // dt = 5e-5: 1.4 steps in the 69 us contact (peak 517 N against 1.74 kN, rebound 0.17 m/s).
  const std::string coarse = ball([](json& d) { d["time"]["dt"] = 5e-5; });
  expect_input_error("validate " + coarse, "time.dt");
  expect_input_error("solve " + coarse + " -q --out coarse", "time.dt");
  // dt = 1e-5 accepted by the case: the run goes on, its energy balance (0.2) is then an error
  // unless the tolerance is raised too.
  const auto accepted = [](double energy_tolerance) {
    return [energy_tolerance](json& d) {
      d["time"]["dt"] = 1e-5;
      d["time"]["allow_coarse_dt"] = true;
      if (energy_tolerance > 0.0) d["time"]["energy_tolerance"] = energy_tolerance;
    };
  };
  CliResult r = run("solve " + ball(accepted(0.0)) + " -q --out energy");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("energy balance"), std::string::npos) << r.err;
  json s = json::parse(slurp(dir_ / "energy" / "summary.json"));
  const double imbalance = s["balances"]["energy"].get<double>();
  EXPECT_GT(imbalance, 0.05);
  EXPECT_FALSE(find_limit(s, "time.dt", "error").is_null()) << s["limits"].dump();
  r = run("solve " + ball(accepted(0.9)) + " -q --out loose");
  EXPECT_EQ(r.code, 0) << r.err;
  s = json::parse(slurp(dir_ / "loose" / "summary.json"));
  const json l = find_limit(s, "time.dt", "warning");
  ASSERT_FALSE(l.is_null()) << s["limits"].dump();
  EXPECT_TRUE(l["accepted"].get<bool>());
  expect_input_error("validate " + ball([](json& d) { d["time"]["energy_tolerance"] = 2.0; }),
                     "time.energy_tolerance");
}

TEST_F(CliDynamicLimits, AHeavyBallWhoseContactIsAsLargeAsItIsRefused) {
  // 1e12 kg at 1 m/s: the Hertz contact of the impact is larger than the ball (a/R > 1).
  const std::string heavy = ball([](json& d) { d["body"]["mass"] = 1e12; });
  expect_input_error("validate " + heavy, "materials");
  expect_input_error("solve " + heavy + " -q --out heavy", "materials");
  expect_input_error("validate " + ball([](json& d) { d["body"]["mass"] = 1e30; }), "body.mass");
}

TEST_F(CliDynamicLimits, PenetrationThatNoElementSeesIsAnError) {
  // 2 x 2 elements over three Hertz half-widths each way: the element centres lie where the
  // ball's gap (52 um) exceeds its deepest approach (23 um), so the ball passes through the
  // half-space with no force at all.
  const std::string coarse = ball([](json& d) {
    d["grid"] = {{"nx", 2}, {"ny", 2}, {"x", {-1.45e-3, 1.45e-3}}, {"y", {-1.45e-3, 1.45e-3}}};
  });
  const CliResult r = run("solve " + coarse + " -q --out through");
  EXPECT_EQ(r.code, 2) << r.err;
  const json s = json::parse(slurp(dir_ / "through" / "summary.json"));
  bool unseen = false;
  for (const json& l : s["limits"])
    unseen = unseen || (l["key"] == "grid" && l["level"] == "error" &&
                        l["message"].get<std::string>().find("no element") != std::string::npos);
  EXPECT_TRUE(unseen) << s["limits"].dump();
}

TEST_F(CliDynamicLimits, ASweepChecksEveryRun) {
  // The speeds example with a step fine enough for the slowest ball only.
  json doc = example_json("ball-impact-speeds");
  doc["grid"]["nx"] = doc["grid"]["ny"] = 12;
  doc["output"] = {{"plots", false}};
  doc["time"]["dt"] = 4e-6;
  const std::string file = write_case(doc);
  expect_input_error("validate " + file, "time.dt");
  const CliResult refused = run("solve " + file + " -q --out refused");
  EXPECT_EQ(refused.code, 2) << refused.err;
  EXPECT_NE(refused.err.find("sweep run"), std::string::npos) << refused.err;
  // Every run with an energy tolerance it cannot meet: exit 2, each run's limits labelled.
  doc["time"]["dt"] = 1e-6;
  doc["time"]["energy_tolerance"] = 1e-9;
  const CliResult r = run("solve " + write_case(doc, "tight.json") + " -q --out tight");
  EXPECT_EQ(r.code, 2) << r.err;
  const json s = json::parse(slurp(dir_ / "tight" / "summary.json"));
  ASSERT_EQ(s["limits"].size(), s["runs"].size()) << s["limits"].dump();
  for (const json& l : s["limits"]) {
    EXPECT_EQ(l["level"], "error");
    EXPECT_TRUE(l.contains("run"));
  }
}

}  // namespace
}  // namespace dc::test
