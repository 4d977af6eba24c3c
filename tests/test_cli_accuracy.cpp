// The accuracy block (issue 28, docs/accuracy.md) run as a program: the estimated discretisation
// error of each result against its true error (the closed forms of Hertz, Carter, Kalker and Spence, with
// materials, loads and shapes other than the bundled examples'), accuracy targets met against
// the closed form, a target missed (exit 3), the extent grown where the contact reaches the edge,
// and bad accuracy input (exit 2 naming the key).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_run.hpp"
#include "case_model.hpp"
#include "cli_runner.hpp"
#include "contact_closed_forms.hpp"
#include "material.hpp"
#include "resource_estimate.hpp"

namespace {

using json = nlohmann::json;
using dc::test::slurp;

/// A bronze sphere (R = 6 mm) on steel under 40 N, or an ellipsoidal body (radii 8 and 20 mm).
json hertz_case(bool ellipse) {
  json c = {{"schema", "dyncontact/1"},
            {"name", ellipse ? "ellipse" : "sphere"},
            {"problem", "normal"},
            {"materials", {{"body", {{"E", 1.17e11}, {"nu", 0.34}}}, {"base", {{"E", 2.1e11}, {"nu", 0.3}}}}},
            {"normal", {{"force", 40.0}}},
            {"output", {{"plots", false}, {"fields", false}}}};
  c["profile"] = ellipse ? json{{"type", "ellipsoid"}, {"radius_x", 0.008}, {"radius_y", 0.02}} : json{{"type", "sphere"}, {"radius", 0.006}};
  return c;
}

/// An aluminium cylinder (R = 15 mm) on steel, 2-D, 2e5 N/m.
json line_case() {
  return {{"schema", "dyncontact/1"},
          {"name", "line"},
          {"problem", "normal"},
          {"dimension", 2},
          {"materials", {{"body", {{"E", 7.0e10}, {"nu", 0.33}}}, {"base", {{"E", 2.1e11}, {"nu", 0.3}}}}},
          {"profile", {{"type", "cylinder"}, {"radius", 0.015}}},
          {"normal", {{"force", 2.0e5}}},
          {"output", {{"plots", false}, {"fields", false}}}};
}

/// Carter's rolling cylinder of the line case with mu = 0.25 and a tangential force of 0.6 mu P.
json carter_case() {
  json c = line_case();
  c["name"] = "carter";
  c["problem"] = "tangential";
  c["materials"]["body"] = {{"E", 2.1e11}, {"nu", 0.3}};  // equal materials: no coupling (kappa = 0)
  c["friction"] = {{"law", "coulomb"}, {"mu", 0.25}};
  c["tangential"] = {{"regime", "rolling"}, {"force", {-0.6 * 0.25 * 2.0e5}}, {"velocity", 1.0}};
  return c;
}

struct Estimated {
  double estimate = 0.0, truth = 0.0;
  std::string method;
  double ratio() const { return estimate / truth; }
};

class CliAccuracy : public dc::test::CliTest {
 protected:
  json solve(const json& c, int expected_exit = 0) const {
    const auto r = run("solve " + write_case(c) + " --out out -q");
    EXPECT_EQ(r.code, expected_exit) << r.err;
    return json::parse(slurp(dir_ / "out" / "summary.json"));
  }
  /// The estimate of `q` against its difference to Hertz (the summary's "hertz" block).
  static Estimated against_hertz(const json& s, const std::string& q) {
    const json& e = s.at("accuracy").at("quantities").at(q);
    return {e.at("error_estimate").get<double>(), std::abs(s.at("hertz").at("relative_difference").at(q).get<double>()),
            e.at("method").get<std::string>()};
  }
};

/// The Hertz sphere and ellipse on five grids each (extent 1.3): the peak pressure's estimate is
/// within 1x to 3x its true error in at least 9 of the 10 cases (issue 28), and the approach's is
/// never below its true error.
TEST_F(CliAccuracy, HertzPeakPressureEstimatesAreWithinThreeTimesTheTrueError) {
  int within = 0, cases = 0;
  for (bool ellipse : {false, true})
    for (int n : {40, 56, 72, 88, 104}) {
      json c = hertz_case(ellipse);
      c["grid"] = {{"nx", n}, {"ny", n}, {"extent", 1.3}};
      const json s = solve(c);
      const Estimated p = against_hertz(s, "max_pressure");
      within += p.ratio() >= 1.0 && p.ratio() <= 3.0;
      ++cases;
      const Estimated d = against_hertz(s, "approach");
      EXPECT_GE(d.ratio(), 1.0) << (ellipse ? "ellipse " : "sphere ") << n << ": approach estimate " << d.estimate
                                << ", true error " << d.truth;
      std::printf("%s %3d: max_pressure estimate/true %.2f (%s), approach %.2f (%s)\n", ellipse ? "ellipse" : "sphere ",
                  n, p.ratio(), p.method.c_str(), d.ratio(), d.method.c_str());
    }
  EXPECT_GE(within, 9) << "of " << cases;
}

/// The line contact's peak pressure depends on where the contact edge falls in an element; with
/// the grids shifted by thirds of an element the estimate is within 1x to 3x the true error in at
/// least 9 of 10 grids.
TEST_F(CliAccuracy, LineContactPeakPressureEstimatesAreWithinThreeTimesTheTrueError) {
  int within = 0;
  for (int n : {80, 110, 140, 170, 200, 230, 260, 290, 320, 350}) {
    json c = line_case();
    c["grid"] = {{"nx", n}, {"extent", 1.25}};
    const Estimated p = against_hertz(solve(c), "max_pressure");
    within += p.ratio() >= 1.0 && p.ratio() <= 3.0;
    EXPECT_EQ(p.method, "richardson_shifted");
    std::printf("line %3d: max_pressure estimate/true %.2f (%s)\n", n, p.ratio(), p.method.c_str());
  }
  EXPECT_GE(within, 9);
}

/// Carter's creepage (force given): the estimate is not below the true error in at least 9 of 10
/// grids (within 3 x in 6: where the contact edge falls by chance, the error is 50 x smaller
/// than on the neighbouring grids).
TEST_F(CliAccuracy, CarterCreepageEstimateIsNotBelowTheTrueError) {
  const json base = carter_case();
  const dc::MaterialPair m{dc::Elastic::from_E_nu(2.1e11, 0.3), dc::Elastic::from_E_nu(2.1e11, 0.3)};
  const double P = 2.0e5, R = 0.015, mu = 0.25;
  const double a = std::sqrt(4.0 * P * R / (std::numbers::pi * m.E_star()));
  const double xi = dc::closed_form::carter_creepage(a, R, mu, 0.6);
  int not_below = 0;
  for (int n : {90, 120, 150, 180, 210, 240, 270, 300, 330, 360}) {
    json c = base;
    c["grid"] = {{"nx", n}, {"extent", 1.3}};
    const json s = solve(c);
    const json& e = s.at("accuracy").at("quantities").at("creepage");
    const double truth = std::abs(std::abs(e.at("value").get<double>()) - std::abs(xi)) / std::abs(xi);
    not_below += e.at("error_estimate").get<double>() >= truth;
    std::printf("carter %3d: creepage estimate %.2e, true error %.2e\n", n, e.at("error_estimate").get<double>(), truth);
  }
  EXPECT_GE(not_below, 9);
}

/// Kalker's linear theory (Johnson Table 8.1, nu = 0: C11 = 3.40): aluminium on aluminium, a
/// sphere of R = 20 mm under 50 N rolling at a creepage of 1e-5 with mu = 10 (full stick). The
/// force is a band (docs/accuracy.md); on the convergence script's ten grids it is never below.
TEST_F(CliAccuracy, KalkerCreepForceEstimateIsNotBelowTheTrueError) {
  const double E = 7.0e10, R = 0.02, P = 50.0, xi = 1e-5, G = E / 2.0;
  const double a = std::cbrt(3.0 * P * R / (4.0 * (E / 2.0)));
  json base = {{"schema", "dyncontact/1"},
               {"name", "kalker"},
               {"problem", "tangential"},
               {"materials", {{"body", {{"E", E}, {"nu", 0.0}}}, {"base", {{"E", E}, {"nu", 0.0}}}}},
               {"profile", {{"type", "sphere"}, {"radius", R}}},
               {"normal", {{"force", P}}},
               {"friction", {{"law", "coulomb"}, {"mu", 10.0}}},
               {"tangential", {{"regime", "rolling"}, {"creepage", {xi, 0.0}}, {"spin", 0.0}, {"velocity", 1.0}}},
               {"output", {{"plots", false}, {"fields", false}}}};
  int not_below = 0;
  for (int n : {24, 32, 40, 48, 56, 64, 72, 80, 88, 96}) {
    json c = base;
    c["grid"] = {{"nx", n}, {"ny", n}, {"extent", 1.25}};
    const json s = solve(c);
    const json& e = s.at("accuracy").at("quantities").at("Fx");
    const double c11 = -e.at("value").get<double>() / (G * a * a * xi);
    const double truth = std::abs(c11 / 3.40 - 1.0);
    not_below += e.at("error_estimate").get<double>() >= truth;
    std::printf("kalker %3d: C11 %.4f, estimate %.2e, true error %.2e\n", n, c11, e.at("error_estimate").get<double>(),
                truth);
  }
  EXPECT_GE(not_below, 9);
}

/// Spence's frictional indentation (Johnson 5.4): a rigid sphere pressed into a nearly
/// incompressible substrate (nu = 0.47, |beta|/mu = 2, c/a = 0.485) in 48 load steps; the stick
/// fraction (c/a)^2 is a band. Not below the true error on any grid (and conservative: the
/// coarse grids' stick counts move by whole elements).
TEST_F(CliAccuracy, SpenceStickFractionEstimateIsNotBelowTheTrueError) {
  const dc::MaterialPair m{dc::Elastic::make_rigid(), dc::Elastic::from_E_nu(1.1e11, 0.47)};
  const double mu = std::abs(dc::closed_form::dundurs_beta(m)) / 2.0;
  const double ratio = dc::closed_form::spence_stick_ratio(2.0);
  json history = json::array();
  for (int k = 0; k <= 48; ++k) history.push_back({{"normal", {{"force", 100.0 * std::pow(0.5 + 0.5 * k / 48.0, 3)}}}});
  json base = {{"schema", "dyncontact/1"},
               {"name", "spence"},
               {"problem", "tangential"},
               {"materials", {{"body", {{"rigid", true}}}, {"base", {{"E", 1.1e11}, {"nu", 0.47}}}}},
               {"profile", {{"type", "sphere"}, {"radius", 0.01}}},
               {"normal", {{"force", 100.0}}},
               {"friction", {{"law", "coulomb"}, {"mu", mu}}},
               {"tangential", {{"regime", "shift"}, {"force", {0.0, 0.0}}, {"history", history}}},
               {"output", {{"plots", false}, {"fields", false}}}};
  for (int n : {40, 48, 56, 64}) {
    json c = base;
    c["grid"] = {{"nx", n}, {"ny", n}, {"extent", 1.2}};
    const json s = solve(c);
    const json& e = s.at("accuracy").at("quantities").at("stick_fraction");
    for (const json& g : s.at("accuracy").at("grids")) {  // each grid's answer certified
      EXPECT_EQ(g.at("status"), "converged") << n;
      EXPECT_LT(g.at("certificate").at("complementarity").get<double>(), 1e-6) << n;
    }
    const double truth = std::abs(e.at("value").get<double>() / (ratio * ratio) - 1.0);
    EXPECT_GE(e.at("error_estimate").get<double>(), truth) << n;
    std::printf("spence %3d: c/a %.4f (Spence %.4f), estimate %.2e, true error %.2e\n", n,
                std::sqrt(e.at("value").get<double>()), ratio, e.at("error_estimate").get<double>(), truth);
  }
}

/// Spence's indentation has no tangential load and is symmetric: its rigid shift is zero in the
/// continuum and round-off on a grid (1e-18 m on the 48^2 grid of 2h). It is not estimated against
/// its own round-off (a relative error of 1.25, or none, where the other results have 1e-3).
TEST_F(CliAccuracy, AShiftThatIsZeroInTheContinuumIsLeftOut) {
  json c = json::parse(run("example spence-sphere").out);
  c["grid"]["nx"] = 48;
  c["grid"]["ny"] = 48;
  c["output"] = {{"plots", false}, {"fields", false}};
  const json s = solve(c);
  const json& q = s.at("accuracy").at("quantities");
  ASSERT_TRUE(q.contains("stick_fraction"));
  EXPECT_FALSE(q.contains("rigid_shift")) << q.at("rigid_shift").dump();
  const double shift = std::hypot(s.at("rigid_shift")[0].get<double>(), s.at("rigid_shift")[1].get<double>());
  EXPECT_LT(shift, 1e-9 * s.at("approach").get<double>());
}

/// A rigid flat punch (R = 2 mm, 0.5 um into steel): the pressure peaks at the rim, where it is
/// singular. The peak pressure is never extrapolated ("diverging" where its values grow, else a
/// band), the force converges by whole elements (a band; not below Boussinesq's P = 2 a E* d on
/// 4 of these 5 grids: on 56^2 the three grids agree by chance within 0.1 %, 0.8 % from the
/// closed form), and a target on the peak stops at once (exit 3, stopped_by "diverging").
TEST_F(CliAccuracy, APunchsPeakPressureIsNotExtrapolatedAndItsForceGetsABand) {
  const double R = 0.002, d = 5e-7, E = 2.1e11, nu = 0.3;
  const double force = 2.0 * R * E / (1.0 - nu * nu) * d;
  json base = {{"schema", "dyncontact/1"},
               {"name", "punch"},
               {"problem", "normal"},
               {"materials", {{"body", {{"rigid", true}}}, {"base", {{"E", E}, {"nu", nu}}}}},
               {"profile", {{"type", "flat_punch"}, {"radius", R}}},
               {"normal", {{"approach", d}}},
               {"output", {{"plots", false}, {"fields", false}}}};
  int not_below = 0, diverging = 0;
  for (int n : {40, 56, 72, 88, 104}) {
    json c = base;
    c["grid"] = {{"nx", n}, {"ny", n}, {"x", {-1.15 * R, 1.15 * R}}, {"y", {-1.15 * R, 1.15 * R}}};
    const json s = solve(c);
    EXPECT_GE(s.at("contact_rim_pressure_ratio").get<double>(), 0.9) << n;
    const json& q = s.at("accuracy").at("quantities");
    const std::string peak = q.at("max_pressure").at("method");
    EXPECT_TRUE(peak == "diverging" || peak == "band") << n << ": " << peak;
    if (peak == "diverging") {
      EXPECT_TRUE(q.at("max_pressure").at("error_estimate").is_null()) << n;
    }
    diverging += peak == "diverging";
    const json& f = q.at("normal_force");
    EXPECT_EQ(f.at("method"), "band") << n;
    const double truth = std::abs(f.at("value").get<double>() / force - 1.0);
    not_below += f.at("error_estimate").get<double>() >= truth;
    std::printf("punch %3d: peak %s, force estimate %.2e, true error %.2e\n", n, peak.c_str(),
                f.at("error_estimate").get<double>(), truth);
  }
  EXPECT_GE(not_below, 4);
  EXPECT_GE(diverging, 3);
  json c = base;
  c["grid"] = {{"nx", 48}, {"ny", 48}, {"x", {-1.15 * R, 1.15 * R}}, {"y", {-1.15 * R, 1.15 * R}}};
  c["accuracy"] = {{"target", 1e-3}, {"quantities", {"max_pressure"}}};
  const json s = solve(c, 3);
  EXPECT_EQ(s.at("accuracy").at("stopped_by"), "diverging");
  EXPECT_FALSE(s.at("accuracy").at("met").get<bool>());
}

/// accuracy.target 1e-2, 1e-3 and 1e-4 without grid counts: met, and met against Hertz.
TEST_F(CliAccuracy, TargetsAreMetAgainstTheClosedForm) {
  for (double target : {1e-2, 1e-3, 1e-4}) {
    json c = hertz_case(false);
    c["accuracy"] = {{"target", target}, {"quantities", {"max_pressure", "approach"}}};
    const json s = solve(c);
    const json& a = s.at("accuracy");
    EXPECT_TRUE(a.at("met").get<bool>()) << target;
    EXPECT_EQ(a.at("stopped_by"), "target");
    EXPECT_EQ(s.at("grid").at("nx"), a.at("grid").at("nx"));  // the summary describes the grid solved
    for (const char* q : {"max_pressure", "approach"}) {
      const Estimated e = against_hertz(s, q);
      EXPECT_LE(e.estimate, target) << q;
      EXPECT_LE(e.truth, target) << q << " at target " << target;
    }
  }
  json line = line_case();
  line["accuracy"] = {{"target", 1e-3}};
  const json s = solve(line);
  EXPECT_TRUE(s.at("accuracy").at("met").get<bool>());
  EXPECT_LE(against_hertz(s, "max_pressure").truth, 1e-3);
}

/// The Hertz sphere given as a measured table at the element centres of a 24 x 24 grid (the
/// form a profile written from a grid has): a target refines below the table's spacing, where
/// the table is interpolated (exactly for a quadratic) and reaches half a spacing beyond its outer
/// nodes to the grid's edge; the target is met against Hertz (p0 of the sphere).
TEST_F(CliAccuracy, ATargetOnATableAtTheElementCentresIsMetAgainstHertz) {
  json sphere = hertz_case(false);
  sphere["grid"] = {{"nx", 24}, {"ny", 24}, {"extent", 1.3}};
  const json reference = solve(sphere);
  const json& g = reference.at("grid");
  const int n = 24;
  const double x0 = g.at("x")[0].get<double>(), dx = g.at("dx").get<double>(), R = 0.006;
  std::string table = "x,y,h\n";
  char line[128];
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = x0 + (i + 0.5) * dx, y = x0 + (j + 0.5) * dx;
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", x, y, (x * x + y * y) / (2.0 * R));
      table += line;
    }
  std::FILE* f = std::fopen((dir_ / "sphere.csv").c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs(table.c_str(), f);
  std::fclose(f);
  json c = hertz_case(false);
  c["profile"] = {{"type", "table"}, {"file", (dir_ / "sphere.csv").string()}};
  c["grid"] = {{"nx", n}, {"ny", n}, {"x", g.at("x")}, {"y", g.at("y")}};
  c["accuracy"] = {{"target", 1e-3}, {"quantities", {"max_pressure", "approach"}}};
  const json s = solve(c);
  const json& a = s.at("accuracy");
  EXPECT_TRUE(a.at("met").get<bool>()) << a.dump();
  EXPECT_GE(a.at("refinements").get<int>(), 1);
  const json& hertz = reference.at("hertz");
  // A table's heights are taken from its lowest point, here 2 (dx/2)^2 / (2R) above the sphere's.
  const double lowest = 0.5 * dx * dx / (2.0 * R);
  for (const char* q : {"max_pressure", "approach"}) {
    const double value = s.at(q).get<double>() + (std::string(q) == "approach" ? lowest : 0.0);
    const double truth = std::abs(value / hertz.at(q).get<double>() - 1.0);
    EXPECT_LE(truth, 1e-3) << q;
    EXPECT_LE(a.at("quantities").at(q).at("error_estimate").get<double>(), 1e-3) << q;
  }
}

/// A measured-like table: the Hertz sphere with a waviness of 1 % of its approach, 2.3 to 3.1
/// samples long, tabulated every a / 8 over +-1.5 a. Its interpolation has a continuous slope, so
/// the peak pressure converges as the grid refines below the spacing (element sizes s / 4, s / 8,
/// s / 16: measured steps 0.15, 0.021, -0.005 p0). A kink at the nodes (the bilinear table of
/// before, or a linear fall-back where the second differences change sign) makes the pressure
/// log-singular there and the peak grow by a like amount at every halving (measured 0.12, 0.14,
/// 0.14 p0).
TEST_F(CliAccuracy, AWavyTablesPeakPressureConvergesBelowItsSpacing) {
  const dc::MaterialPair m{dc::Elastic::from_E_nu(1.17e11, 0.34), dc::Elastic::from_E_nu(2.1e11, 0.3)};
  const double R = 0.006, P = 40.0, E = m.E_star();
  const double a = std::cbrt(3.0 * P * R / (4.0 * E)), delta = a * a / R, p0 = 1.5 * P / (std::numbers::pi * a * a);
  const int half = 12;  // samples over the half-extent
  const double L = 1.5 * a, s = L / half;
  std::string table = "x,y,h\n";
  char line[128];
  for (int j = -half; j <= half; ++j)
    for (int i = -half; i <= half; ++i) {
      const double x = i * s, y = j * s, k = 2.0 * std::numbers::pi / s;
      const double wave = 0.01 * delta *
                          (std::cos(k * x / 2.3 + 0.7) * std::cos(k * y / 3.1 + 1.9) + 0.6 * std::sin(k * (x + 0.4 * y) / 2.7 + 0.3));
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", x, y, (x * x + y * y) / (2.0 * R) + wave);
      table += line;
    }
  std::FILE* f = std::fopen((dir_ / "wavy.csv").c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs(table.c_str(), f);
  std::fclose(f);
  std::vector<double> peak;
  for (int refine : {4, 8, 16}) {
    json c = hertz_case(false);
    c["profile"] = {{"type", "table"}, {"file", (dir_ / "wavy.csv").string()}};
    const int n = 2 * half * refine;
    c["grid"] = {{"nx", n}, {"ny", n}, {"x", {-L, L}}, {"y", {-L, L}}};
    c["accuracy"] = {{"estimate", false}};
    peak.push_back(solve(c).at("max_pressure").get<double>() / p0);
  }
  const double coarse_step = peak[1] - peak[0], fine_step = peak[2] - peak[1];
  EXPECT_LT(std::abs(fine_step), 0.5 * std::abs(coarse_step)) << peak[0] << " " << peak[1] << " " << peak[2];
  EXPECT_LT(std::abs(fine_step), 0.02) << peak[1] << " " << peak[2];
}

TEST_F(CliAccuracy, TangentialTargetIsMetAgainstCarter) {
  json c = carter_case();
  c["accuracy"] = {{"target", 3e-3}, {"quantities", {"creepage"}}};
  const json s = solve(c);
  const dc::MaterialPair m{dc::Elastic::from_E_nu(2.1e11, 0.3), dc::Elastic::from_E_nu(2.1e11, 0.3)};
  const double a = std::sqrt(4.0 * 2.0e5 * 0.015 / (std::numbers::pi * m.E_star()));
  const double xi = std::abs(dc::closed_form::carter_creepage(a, 0.015, 0.25, 0.6));
  ASSERT_TRUE(s.at("accuracy").at("met").get<bool>());
  const double value = std::hypot(s.at("creepage")[0].get<double>(), s.at("creepage")[1].get<double>());
  EXPECT_LE(std::abs(value - xi) / xi, 3e-3);
}

/// Mindlin's shift (nu = 0: no coupling, Mindlin exact) with a target the 20^2 start grid's two-grid
/// band (the 4h grid has too few elements across) claimed met at 0.8 x the true error: a target
/// is met only on three grids, and then holds against the closed form.
TEST_F(CliAccuracy, ATargetIsNotMetOnTwoGrids) {
  const dc::MaterialPair m{dc::Elastic::from_E_nu(1.0e11, 0.0), dc::Elastic::from_E_nu(1.0e11, 0.0)};
  json c = {{"schema", "dyncontact/1"},
            {"name", "mindlin"},
            {"problem", "tangential"},
            {"materials", {{"body", {{"E", 1.0e11}, {"nu", 0.0}}}, {"base", {{"E", 1.0e11}, {"nu", 0.0}}}}},
            {"profile", {{"type", "sphere"}, {"radius", 0.02}}},
            {"grid", {{"extent", 1.2}}},
            {"normal", {{"force", 500.0}}},
            {"friction", {{"law", "coulomb"}, {"mu", 0.5}}},
            {"tangential", {{"regime", "shift"}, {"force", {-175.0, 0.0}}}},
            {"accuracy", {{"target", 6e-4}, {"quantities", {"rigid_shift"}}}},
            {"output", {{"plots", false}, {"fields", false}}}};
  const json s = solve(c);
  const json& a = s.at("accuracy");
  ASSERT_TRUE(a.at("met").get<bool>());
  EXPECT_EQ(a.at("grids").size(), 3u);
  const double a_hertz = std::cbrt(3.0 * 500.0 * 0.02 / (4.0 * m.E_star()));
  const double mindlin = dc::closed_form::mindlin_shift(0.5, 500.0, a_hertz, m.mindlin_compliance(), 0.7);
  const double value = std::hypot(s.at("rigid_shift")[0].get<double>(), s.at("rigid_shift")[1].get<double>());
  EXPECT_LE(std::abs(value - mindlin) / mindlin, 6e-4);
  EXPECT_GE(a.at("quantities").at("rigid_shift").at("error_estimate").get<double>(), std::abs(value - mindlin) / mindlin);
}

/// A line contact whose half-width covers the same elements on the nested grids (extent 1.37):
/// it was left out as if prescribed, and a target on it claimed met 3.6 x above; now its band is
/// the spread of the shifted placements, and the target holds against Hertz.
TEST_F(CliAccuracy, AHalfWidthTargetHoldsAgainstHertz) {
  json c = line_case();
  c["grid"] = {{"extent", 1.37}};
  c["accuracy"] = {{"target", 1e-2}, {"quantities", {"contact_half_width"}}};
  const json s = solve(c);
  const json& a = s.at("accuracy");
  ASSERT_TRUE(a.at("met").get<bool>());
  const dc::MaterialPair m{dc::Elastic::from_E_nu(7.0e10, 0.33), dc::Elastic::from_E_nu(2.1e11, 0.3)};
  const double b = std::sqrt(4.0 * 2.0e5 * 0.015 / (std::numbers::pi * m.E_star()));
  const double truth = std::abs(s.at("contact_half_width").get<double>() - b) / b;
  EXPECT_LE(truth, 1e-2);
  const json& q = a.at("quantities").at("contact_half_width");
  EXPECT_GT(q.at("error_estimate").get<double>(), 0.0);
  std::printf("[ info ] half-width on %d strips: true error %.2e, band %.2e\n", a.at("grid").at("nx").get<int>(), truth,
              q.at("error_estimate").get<double>());
  // The refined grid is solved by the case's own (automatic) choice of backend for that grid, not
  // by the one the small start grid got (Ipopt: 20 s on 5632 strips against the native 0.03 s).
  json direct = c;
  direct["grid"]["nx"] = a.at("grid").at("nx");
  direct["accuracy"] = {{"estimate", false}};
  EXPECT_EQ(s.at("solver").at("backend"), solve(direct).at("solver").at("backend"));
}

/// The refinement's last grid, warm-started from the grid before it, gives the answer of a cold
/// solve on that grid (to the solver's tolerance), in no more iterations.
TEST_F(CliAccuracy, AWarmStartedRefinementGivesTheColdAnswer) {
  json c = hertz_case(false);
  c["grid"] = {{"extent", 1.3}};
  c["accuracy"] = {{"target", 1e-4}};
  c["solver"] = {{"backend", "native"}};
  const json refined = solve(c);
  ASSERT_GT(refined.at("accuracy").at("refinements").get<int>(), 0);
  json cold = c;
  cold["grid"]["nx"] = refined.at("grid").at("nx");
  cold["grid"]["ny"] = refined.at("grid").at("ny");
  cold["accuracy"] = {{"estimate", false}};
  const json direct = solve(cold);
  for (const char* q : {"max_pressure", "approach"})
    EXPECT_NEAR(refined.at(q).get<double>() / direct.at(q).get<double>(), 1.0, 1e-7) << q;
  EXPECT_LE(refined.at("solver").at("iterations").get<int>(), direct.at("solver").at("iterations").get<int>());
}

/// A target the budget cannot reach: the finest grid's results, met false, exit 3.
TEST_F(CliAccuracy, AMissedTargetSaysWhyAndExitsThree) {
  json c = hertz_case(false);
  c["accuracy"] = {{"target", 1e-6}, {"max_elements", 20000}};
  const auto r = run("solve " + write_case(c) + " --out out -q");
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("largest estimate: max_pressure"), std::string::npos) << r.err;  // what kept it from the target
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  EXPECT_FALSE(s.at("accuracy").at("met").get<bool>());
  EXPECT_EQ(s.at("accuracy").at("stopped_by"), "max_elements");
  EXPECT_LE(s.at("grid").at("elements").get<double>(), 20000.0);
}

/// The memory available stops a refinement before the grid that would not fit (the default
/// max_elements, 2048^2, is above it here): the finest grid that fits, met false, exit 3.
TEST_F(CliAccuracy, TheMemoryAvailableStopsARefinement) {
  if (DYNCONTACT_SANITIZED) GTEST_SKIP() << "an address-space limit is not for a sanitizer build";
  json c = hertz_case(false);
  c["accuracy"] = {{"target", 1e-6}, {"quantities", {"contact_area"}}};
  // 600 MB of address space: 512^2 (about 80 MB by the estimate) fits twice over, 1024^2 does not.
  const auto r = run_prefixed("ulimit -v 600000;", "solve " + write_case(c) + " --out out -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("stopped by max_memory"), std::string::npos) << r.err;
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  EXPECT_FALSE(s.at("accuracy").at("met").get<bool>());
  EXPECT_EQ(s.at("accuracy").at("stopped_by"), "max_memory");
  EXPECT_LT(s.at("grid").at("elements").get<double>(), 1024.0 * 1024.0);
  EXPECT_GT(s.at("grid").at("elements").get<double>(), 64.0 * 64.0);
}

/// The memory budget's arithmetic: twice the case's memory estimate (the one validate prints).
TEST(AccuracyBudget, AGridFitsWhenTwiceItsEstimateIsAvailable) {
  json doc = hertz_case(false);
  doc["grid"] = {{"nx", 64}, {"ny", 64}, {"extent", 1.3}};
  const dc::Case c = dc::build_case(doc);
  const double bytes = dc::runs::estimate_resources(c).memory_bytes;
  ASSERT_GT(bytes, 0.0);
  EXPECT_TRUE(dc::runs::grid_fits_in_memory(c, c.grid, 2.01 * bytes));
  EXPECT_FALSE(dc::runs::grid_fits_in_memory(c, c.grid, 1.99 * bytes));
  // 32 times the elements along each axis: about 1000 times the memory.
  EXPECT_FALSE(dc::runs::grid_fits_in_memory(c, dc::runs::refined(c.grid, 32), 100.0 * bytes));
}

/// A grid whose extent cuts the contact: the target grows it (the element size kept) instead of
/// failing.
TEST_F(CliAccuracy, ATargetGrowsAnExtentThatCutsTheContact) {
  json c = hertz_case(false);
  c["grid"] = {{"extent", 0.8}};
  c["accuracy"] = {{"target", 1e-2}};
  const json s = solve(c);
  const json& a = s.at("accuracy");
  EXPECT_TRUE(a.at("met").get<bool>());
  EXPECT_GE(a.at("extent_growths").get<int>(), 1);
  EXPECT_FALSE(s.at("contact_touches_boundary").get<bool>());
  EXPECT_LE(against_hertz(s, "max_pressure").truth, 1e-2);
}

TEST_F(CliAccuracy, EstimateFalseLeavesTheBlockOut) {
  json c = hertz_case(false);
  c["grid"] = {{"nx", 32}, {"ny", 32}, {"extent", 1.3}};
  c["accuracy"] = {{"estimate", false}};
  EXPECT_FALSE(solve(c).contains("accuracy"));
}

TEST_F(CliAccuracy, BadAccuracyInputNamesTheKey) {
  auto expect_error = [&](const json& accuracy, const std::string& key, const json& base) {
    json c = base;
    c["accuracy"] = accuracy;
    expect_input_error("solve " + write_case(c) + " --out out -q", key);
  };
  json sphere = hertz_case(false);
  sphere["grid"] = {{"nx", 32}, {"ny", 32}, {"extent", 1.3}};
  expect_error({{"target", -1e-3}}, "accuracy.target", sphere);
  expect_error({{"target", 0.7}}, "accuracy.target", sphere);
  expect_error({{"target", 1e-3}, {"quantities", {"max_presure"}}}, "accuracy.quantities", sphere);
  expect_error({{"target", 1e-3}, {"quantities", {"Fx"}}}, "accuracy.quantities", sphere);  // not a normal result
  // 3-D contacts have contact_half_width_x / _y, no one half-width to estimate.
  expect_error({{"target", 1e-3}, {"quantities", {"contact_half_width"}}}, "accuracy.quantities", sphere);
  expect_error({{"target", 1e-3}, {"max_elements", 10}}, "accuracy.max_elements", sphere);
  expect_error({{"max_seconds", 10}}, "accuracy.max_seconds", sphere);  // a budget without a target
  expect_error({{"target", 1e-3}, {"estimate", false}}, "accuracy.estimate", sphere);
  expect_error({{"estimate", "yes"}}, "accuracy.estimate", sphere);
  expect_error({{"tolerance", 1e-3}}, "accuracy.tolerance", sphere);
  json no_grid = hertz_case(false);  // without a target the grid's element counts are required
  no_grid["grid"] = {{"extent", 1.3}};
  expect_input_error("solve " + write_case(no_grid) + " --out out -q", "grid.nx");
}

}  // namespace
