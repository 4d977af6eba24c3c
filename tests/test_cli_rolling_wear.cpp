// Wear in steady rolling (CASES.md "wear", docs/wear_energy.md "Wear in steady rolling"): one
// pass wears the track and the body's circumference along each row by the row's integral of the
// law. Archard's volume per pass against k/(mu H) x the frictional work of the pass (round-off),
// Carter's cylinder against its closed-form creep power (Johnson 8.4), a sphere in full slip
// against the lateral closed form of its row integrals, repeated passes with profile updates,
// and the block's input errors for rolling cases.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "hertz.hpp"

namespace cli_rolling_wear_test {  // named: the unity build shares one translation unit

using json = nlohmann::json;
using dc::test::slurp;

constexpr double kK = 1e-4, kH = 2e9, kMu = 0.3;

class CliRollingWear : public dc::test::CliTest {
 protected:
  json solve(const json& c) const {
    const auto r = run("solve " + write_case(c) + " --out out -q");
    EXPECT_EQ(r.code, 0) << r.err;
    return json::parse(slurp(dir_ / "out" / "summary.json"));
  }
  static json quiet(json c) {
    c["accuracy"] = {{"estimate", false}};
    c["output"] = {{"plots", false}};
    return c;
  }
  /// wear.csv's base column: depth by the row's y (every element of a row must agree).
  std::map<double, double> base_rows() const {
    std::istringstream rows(slurp(dir_ / "out" / "wear.csv"));
    std::string line;
    std::getline(rows, line);
    EXPECT_EQ(line.rfind("x,y,base", 0), 0u) << line;
    std::map<double, double> out;
    while (std::getline(rows, line)) {
      double x = 0, y = 0, d = 0;
      char comma = 0;
      std::istringstream(line) >> x >> comma >> y >> comma >> d;
      auto [it, fresh] = out.emplace(y, d);
      if (!fresh) {
        EXPECT_EQ(it->second, d) << "row y = " << y << " not uniform along x";
      }
    }
    return out;
  }
};

TEST_F(CliRollingWear, ArchardsVolumePerPassIsKOverMuHTimesTheFrictionalWorkOfThePass) {
  // rolling-sphere (48^2, steel R = 10 mm, 100 N, xi = 1e-3, mu = 0.3): partial slip. Coulomb:
  // in slip -tau . ds = mu p |ds|, in stick both vanish, so per pass (travel 2 pi R at speed V)
  // volume = k / (mu H) x frictional_power x 2 pi R / V, to the solver's tolerance.
  json c = quiet(dc::test::example_json("rolling-sphere"));
  c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}};
  const json s = solve(c);
  const double R = 0.01, V = c["tangential"]["velocity"].get<double>();
  const double work = s.at("energy").at("frictional_power").get<double>() * 2.0 * M_PI * R / V;
  ASSERT_GT(work, 0.0);
  const json& w = s.at("wear");
  for (const char* body : {"base", "body"})
    EXPECT_NEAR(w.at(body).at("volume").get<double>() / (kK / (kMu * kH) * work), 1.0, 1e-9) << body;
  EXPECT_EQ(w.at("cycles"), 1);
  EXPECT_EQ(w.at("updates"), 1);
  EXPECT_DOUBLE_EQ(w.at("rolling_radius").get<double>(), R);
  EXPECT_NEAR(w.at("travel").get<double>(), 2.0 * M_PI * R, 1e-15);
  EXPECT_EQ(s.at("files").at("wear"), "wear.csv");
  const std::map<double, double> rows = base_rows();
  EXPECT_EQ(rows.size(), 48u);
  // The energy law with alpha = k / (mu H) wears the same; only the base listed.
  c["wear"] = {{"law", "energy"}, {"coefficient", kK / (kMu * kH)}, {"bodies", {"base"}}};
  const json e = solve(c);
  EXPECT_NEAR(e.at("wear").at("base").at("volume").get<double>() / (kK / (kMu * kH) * work), 1.0, 1e-9);
  EXPECT_FALSE(e.at("wear").contains("body"));
}

TEST_F(CliRollingWear, CartersCylinderWearsItsCreepPowerOverKOverMuH) {
  // carter-2d (steel R = 20 mm, 100 kN/m, F = 0.5 mu P): the depth of one pass is
  // k/(mu H) |F| xi, xi = (mu a / R)(1 - c/a), c/a = sqrt(1 - F/(mu P)) (Johnson 8.4): the creep
  // power over V, all dissipated in the continuum. The stick zone (x > a - 2c) wears nothing, the
  // slip zone all of it. On the grid the upwind scheme keeps O(dx) of the creep power
  // (docs/wear_energy.md: 4.1 % on 100 strips, 2.0 % on 200), so the depth (0.950 and 0.979 of
  // Carter's) is extrapolated linearly from 100 and 200 strips (1.0089); the creep power itself
  // carries the creepage's grid error (1.5 %, as in test_cli_energy.cpp).
  const double E = 2.1e11, nu = 0.3, R = 0.02, P = 1e5, F = 0.5 * kMu * P;
  const auto h = dc::hertz::cylinder2d(R, P, E / (2.0 * (1.0 - nu * nu)));
  const double c_over_a = std::sqrt(1.0 - F / (kMu * P));
  const double carter = kK / (kMu * kH) * F * (kMu * h.a / R) * (1.0 - c_over_a);
  double depth[2] = {};
  for (int k = 0; k < 2; ++k) {
    json c = quiet(dc::test::example_json("carter-2d"));
    c["grid"]["nx"] = 100 << k;
    c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"bodies", {"base"}}};
    const json s = solve(c);
    depth[k] = s.at("wear").at("base").at("max_depth").get<double>();
    // 2-D: the volume per unit length of one revolution is the depth times 2 pi R.
    EXPECT_NEAR(s.at("wear").at("base").at("volume").get<double>() / (2.0 * M_PI * R * depth[k]), 1.0, 1e-12);
    // Archard's depth of the pass is k/(mu H) x the frictional power over V (every strip's).
    const double V = c["tangential"]["velocity"].get<double>();
    EXPECT_NEAR(depth[k] / (kK / (kMu * kH) * s.at("energy").at("frictional_power").get<double>() / V), 1.0, 1e-9);
  }
  EXPECT_LT(depth[0], depth[1]);
  EXPECT_NEAR((2.0 * depth[1] - depth[0]) / carter, 1.0, 0.015);
}

TEST_F(CliRollingWear, ASphereInFullSlipWearsTheRowIntegralOfItsHertzPressure) {
  // nu = 0 (a tangential traction makes only a parallel tangential displacement, no pressure
  // change: Johnson 3.2) and a creepage xi = 0.03, five times the elastic strain's largest
  // pi mu p0 / (2 G) = 6e-3 of full sliding (q = mu p: u = pi mu p0 (2a^2 - r^2)/(4 G a)), so the
  // slip s = xi + du/dx never changes sign. Along a row du/dx = -pi mu p0 x/(2 G a) is odd and
  // p even: int p |s| dx = xi int p dx, and the row's depth per pass is
  //   d(y) = (k/H) xi p0 pi (a^2 - y^2) / (2a),
  // the total per unit travel (k/H) xi P. On 48^2 over 1.2 a.
  const double E = 2.1e11, R = 0.01, P = 100.0, xi = 0.03;
  const auto h = dc::hertz::sphere(R, P, E / 2.0);
  json c = quiet(dc::test::example_json("rolling-sphere"));
  c["materials"] = {{"body", {{"E", E}, {"nu", 0.0}}}, {"base", {{"E", E}, {"nu", 0.0}}}};
  c["tangential"]["creepage"] = {xi, 0.0};
  c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}};
  const json s = solve(c);
  EXPECT_EQ(s.at("n_stick"), 0);
  const std::map<double, double> rows = base_rows();
  double per_travel = 0.0;
  const double dy = 2.4 * h.a / 48;
  for (const auto& [y, d] : rows) {
    per_travel += d * dy;
    if (std::abs(y) < 0.8 * h.a) {
      const double closed = kK / kH * xi * h.p0 * M_PI * (h.a * h.a - y * y) / (2.0 * h.a);
      EXPECT_NEAR(d / closed, 1.0, 0.02) << "y/a = " << y / h.a;
    }
  }
  // The total: the closed form less the upwind scheme's first-order share of the creep power
  // (0.92 %, 0.47 %, 0.24 % on 24^2, 48^2, 96^2): the wear is the frictional power's exactly.
  const json& e = s.at("energy");
  const double share = e.at("scheme_power").get<double>() / e.at("creep_power").get<double>();
  EXPECT_NEAR(per_travel / (kK / kH * xi * P), 1.0, 0.01);
  EXPECT_NEAR(per_travel / (kK / kH * xi * P), 1.0 - share, 1e-6);
  // wear.csv's 10 digits against the summary's volume.
  EXPECT_NEAR(s.at("wear").at("base").at("volume").get<double>() / (per_travel * 2.0 * M_PI * R), 1.0, 1e-9);
}

TEST_F(CliRollingWear, RepeatedPassesWearAGrooveThatWidensTheContactAndKeepTheLoad) {
  // The sphere of rolling-sphere in full slip (xi = 0.03), 32^2 over 1.6 a, k = 1e-3, 60 passes,
  // the profile updated every 20 nm of the deepest wear (about 6 nm a pass: jumps of 3): the
  // track's groove (depth ~ the row's pressure integral, (a^2 - y^2)) conforms to the body, so
  // the peak pressure falls from update to update (1.37 -> 1.22 GPa) and the contact widens (by
  // whole elements: compared first to last); every update's solve carries the 100 N; the worn
  // volume adds up over the jumps.
  json c = quiet(dc::test::example_json("rolling-sphere"));
  c["grid"] = {{"nx", 32}, {"ny", 32}, {"extent", 1.6}};
  c["tangential"]["creepage"] = {0.03, 0.0};
  c["wear"] = {{"law", "archard"}, {"k", 1e-3}, {"hardness", kH}, {"cycles", 60}, {"update", {{"max_depth", 2e-8}}}};
  const json s = solve(c);
  const json& hist = s.at("wear").at("history");
  ASSERT_GE(hist.size(), 3u);
  double volume = 0.0;
  for (std::size_t k = 0; k < hist.size(); ++k) {
    const json& u = hist[k];
    EXPECT_NEAR(u.at("normal_force")[0].get<double>(), 100.0, 1e-9 * 100.0);
    volume += u.at("jump").get<double>() * u.at("cycle_volume").get<double>();
    EXPECT_NEAR(u.at("volume").get<double>(), volume, 1e-12 * volume);
    if (k > 0) {
      EXPECT_LT(u.at("max_pressure").get<double>(), hist[k - 1].at("max_pressure").get<double>()) << k;
    }
  }
  EXPECT_EQ(s.at("wear").at("cycles"), 60);
  EXPECT_LT(hist.back().at("max_pressure").get<double>(), 0.9 * hist.front().at("max_pressure").get<double>());
  EXPECT_GT(hist.back().at("contact_area").get<double>(), hist.front().at("contact_area").get<double>());
}

TEST_F(CliRollingWear, BadRollingWearBlocksAreInputErrorsNamingTheKey) {
  json base = quiet(dc::test::example_json("rolling-sphere"));
  const json law = {{"law", "archard"}, {"k", kK}, {"hardness", kH}};
  auto with = [&](const json& patch) {
    json w = law;
    w.merge_patch(patch);
    return w;
  };
  const std::vector<std::pair<json, std::string>> bad = {
      {with({{"cycle_from_step", 0}}), "wear.cycle_from_step"},
      {with({{"rolling_radius", -1.0}}), "wear.rolling_radius"},
  };
  for (const auto& [w, key] : bad) {
    json doc = base;
    doc["wear"] = w;
    SCOPED_TRACE(w.dump());
    expect_input_error("validate " + write_case(doc), key);
  }
  // A profile without a curvature along x needs the radius.
  json punch = base;
  punch["profile"] = {{"type", "flat_punch"}, {"radius", 2e-4}};
  punch["wear"] = law;
  expect_input_error("validate " + write_case(punch), "wear.rolling_radius");
  // A rolling history (transient rolling) is not yet worn.
  json history = quiet(dc::test::example_json("cattaneo-carter-2d"));
  history["wear"] = law;
  expect_input_error("validate " + write_case(history), "wear");
  // A shift history takes no rolling radius.
  json shift = quiet(dc::test::example_json("cattaneo-sphere"));
  shift["tangential"] = {{"regime", "shift"}, {"history", {{{"force", {-15.0, 0.0}}}, {{"force", {15.0, 0.0}}}}}};
  shift["wear"] = with({{"rolling_radius", 0.01}});
  expect_input_error("validate " + write_case(shift), "wear.rolling_radius");
}

}  // namespace cli_rolling_wear_test
