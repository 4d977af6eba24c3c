// Wear that changes the profile (CASES.md "wear", docs/wear_energy.md "Wear"): Archard's
// bookkeeping against the dissipated energy, Mindlin & Deresiewicz's fretting scar of a sphere
// (Johnson, Contact Mechanics 7.4) and gross slip against their closed forms, cycle jumping's
// convergence with the load kept, the run-in of a sphere in gross slip, and the wear block's
// input errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace cli_wear_test {  // named: the unity build shares one translation unit

using json = nlohmann::json;
using dc::test::slurp;

// A steel-like sphere on a flat of the same material, nu = 0: the tangential traction then makes
// only tangential displacement, parallel to it, with the kernel 1/(2 pi G rho) (Johnson 3.2), so
// Cattaneo-Mindlin's slip is exact (no nu-dependent twist of the slip direction) and both bodies'
// tractions leave the pressure alone (identical materials: kappa = 0).
constexpr double kE = 2.1e11, kR = 0.01, kP = 100.0, kMu = 0.3, kK = 1e-4, kH = 2e9;
const double kG = kE / 2.0;                                          // nu = 0
const double kEstar = kE / 2.0;                                      // E / (2 (1 - nu^2))
const double kA = std::cbrt(3.0 * kP * kR / (4.0 * kEstar));         // Hertz radius
const double kP0 = 3.0 * kP / (2.0 * M_PI * kA * kA);                // Hertz peak pressure

double hertz_pressure(double r) { return r < kA ? kP0 * std::sqrt(1.0 - r * r / (kA * kA)) : 0.0; }

/// Cattaneo's slip (m) at radius r of loading from 0 to the force whose stick radius is c (nu = 0):
/// the relative displacement of q = mu p0 sqrt(1 - r^2/a^2) - mu p0 (c/a) sqrt(1 - r^2/c^2)
/// (the Hertz potentials of Johnson 3.42 with (1 - nu^2)/E -> 1/(2G), both bodies) subtracted
/// from the rigid shift, which equals it for r <= c:
///   s(r) = mu p0 / (2 G a) [(r^2 - 2c^2) acos(c/r) + c sqrt(r^2 - c^2)],  c <= r <= a.
double cattaneo_slip(double r, double c) {
  if (r <= c) return 0.0;
  return kMu * kP0 / (2.0 * kG * kA) * ((r * r - 2.0 * c * c) * std::acos(c / r) + c * std::sqrt(r * r - c * c));
}

/// The relative elastic displacement of full sliding, q = mu p (r <= a): U(r) = pi mu p0 (2a^2 - r^2) / (4 G a).
double sliding_displacement(double r) { return M_PI * kMu * kP0 * (2.0 * kA * kA - r * r) / (4.0 * kG * kA); }

struct WornPoint {
  double r, depth;
};

class CliWear : public dc::test::CliTest {
 protected:
  json sphere(int n, double extent) const {
    json c = dc::test::example_json("cattaneo-sphere");
    c["name"] = "wear";
    c["accuracy"] = {{"estimate", false}};
    c["output"] = {{"plots", false}};
    c["materials"] = {{"body", {{"E", kE}, {"nu", 0.0}}}, {"base", {{"E", kE}, {"nu", 0.0}}}};
    c["grid"] = {{"nx", n}, {"ny", n}, {"extent", extent}};
    return c;
  }
  /// A force cycle +-Q (traction on the body): the first loading to -Q, then Q and -Q repeated.
  static json force_cycle(double Q) {
    return {{"regime", "shift"}, {"history", {{{"force", {-Q, 0.0}}}, {{"force", {Q, 0.0}}}, {{"force", {-Q, 0.0}}}}}};
  }
  json solve(const json& c) const {
    const auto r = run("solve " + write_case(c) + " --out out -q");
    EXPECT_EQ(r.code, 0) << r.err;
    return json::parse(slurp(dir_ / "out" / "summary.json"));
  }
  /// wear.csv's base column by radius.
  std::vector<WornPoint> worn_base() const {
    std::istringstream rows(slurp(dir_ / "out" / "wear.csv"));
    std::string line;
    std::getline(rows, line);
    EXPECT_EQ(line.rfind("x,y,base", 0), 0u) << line;
    std::vector<WornPoint> out;
    while (std::getline(rows, line)) {
      double x = 0, y = 0, d = 0;
      char comma = 0;
      std::istringstream(line) >> x >> comma >> y >> comma >> d;
      out.push_back({std::hypot(x, y), d});
    }
    return out;
  }
};

/// The mean of f over the elements whose r / a is within 0.015 of `r_over_a`.
double ring_mean(const std::vector<WornPoint>& pts, double r_over_a, const std::function<double(const WornPoint&)>& f) {
  double sum = 0.0;
  int count = 0;
  for (const WornPoint& p : pts)
    if (std::abs(p.r / kA - r_over_a) < 0.015) {
      sum += f(p);
      ++count;
    }
  EXPECT_GT(count, 20);
  return sum / count;
}

TEST_F(CliWear, ArchardsVolumeIsKOverMuHTimesTheDissipatedEnergy) {
  // Coulomb: in slip -tau . ds = mu p |ds|, so sum (k/H) p |ds| A = k / (mu H) x the dissipated
  // work; in stick both vanish (to the solver's tolerance). Every step is in the cycle here.
  json c = sphere(32, 1.1);
  c["tangential"] = force_cycle(0.5 * kMu * kP);
  c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"cycle_from_step", 0}};
  const json s = solve(c);
  const double work = s.at("energy").at("dissipated_total").get<double>();
  ASSERT_GT(work, 0.0);
  for (const char* body : {"base", "body"})
    EXPECT_NEAR(s.at("wear").at(body).at("volume").get<double>() / (kK / (kMu * kH) * work), 1.0, 1e-9) << body;
  EXPECT_EQ(s.at("wear").at("cycles"), 1);
  EXPECT_EQ(s.at("wear").at("updates"), 1);
  EXPECT_EQ(s.at("files").at("wear"), "wear.csv");
  EXPECT_EQ(slurp(dir_ / "out" / "wear.csv").substr(0, 14), "x,y,base,body\n");
  // The energy law with alpha = k / (mu H) wears the same.
  c["wear"] = {{"law", "energy"}, {"coefficient", kK / (kMu * kH)}, {"bodies", {"base"}}};
  const json e = solve(c);
  EXPECT_NEAR(e.at("wear").at("base").at("volume").get<double>() / (kK / (kMu * kH) * work), 1.0, 1e-9);
  EXPECT_FALSE(e.at("wear").contains("body"));
  EXPECT_EQ(slurp(dir_ / "out" / "wear.csv").substr(0, 9), "x,y,base\n");
}

TEST_F(CliWear, FrettingWearsTheMindlinDeresiewiczSlipRingAndNotTheStickCircle) {
  // Q* = 0.5 and 0.8 mu P on 64^2 elements over 1.1 a. The steady cycle Q* -> -Q* -> Q*: each
  // half is the Cattaneo problem of twice the force change with 2 mu (Johnson 7.4), its stick
  // radius c = a (1 - Q*/(mu P))^(1/3), the slip monotonic over it: 2 s(r, c) per half, 4 s per
  // cycle; the first loading to Q* slips s(r, c) once. Depth after it and one cycle:
  // 5 (k/H) p(r) s(r, c). Observed: ring volume within 0.15 %, depths within 1 %.
  for (const double ratio : {0.5, 0.8}) {
    const double Q = ratio * kMu * kP, c_stick = kA * std::cbrt(1.0 - ratio);
    json c = sphere(64, 1.1);
    c["tangential"] = force_cycle(Q);
    c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"bodies", {"base"}}, {"cycle_from_step", 1}};
    const json s = solve(c);
    const std::vector<WornPoint> pts = worn_base();
    // The steady cycle's ring volume, integral of 4 (k/H) p s 2 pi r dr over c < r < a (midpoints).
    double ring = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double r = c_stick + (kA - c_stick) * (i + 0.5) / n;
      ring += 4.0 * kK / kH * hertz_pressure(r) * cattaneo_slip(r, c_stick) * 2.0 * M_PI * r * (kA - c_stick) / n;
    }
    const double cycle_volume = s.at("wear").at("history").at(0).at("cycle_volume").get<double>();
    EXPECT_NEAR(cycle_volume / ring, 1.0, 0.01) << "Q*/(mu P) = " << ratio;
    // No wear inside the stick circle (r < 0.9 c; the solver's round-off only).
    double deepest = 0.0, stick = 0.0;
    for (const WornPoint& p : pts) {
      deepest = std::max(deepest, p.depth);
      if (p.r < 0.9 * c_stick) stick = std::max(stick, p.depth);
    }
    EXPECT_LT(stick, 1e-6 * deepest) << ratio;
    for (const double r_over_a : {0.85, 0.9, 0.95}) {
      const double computed = ring_mean(pts, r_over_a, [](const WornPoint& p) { return p.depth; });
      const double closed = ring_mean(pts, r_over_a, [&](const WornPoint& p) {
        return 5.0 * kK / kH * hertz_pressure(p.r) * cattaneo_slip(p.r, c_stick);
      });
      EXPECT_NEAR(computed / closed, 1.0, 0.03) << "Q*/(mu P) = " << ratio << ", r/a = " << r_over_a;
    }
  }
}

TEST_F(CliWear, GrossSlipWearsTheWholeContact) {
  // Shifts +-delta = 3 U(0) (beyond full sliding): every point slips 2 delta - 2 U(r) per half
  // cycle and delta - U(r) in the first loading, depth 5 (k/H) p (delta - U(r)); 48^2 elements
  // over 1.1 a, within 1 % (observed 0.1 %).
  json c = sphere(48, 1.1);
  const double delta = 3.0 * sliding_displacement(0.0);
  c["tangential"] = {{"regime", "shift"},
                     {"history", {{{"shift", {delta, 0.0}}}, {{"shift", {-delta, 0.0}}}, {{"shift", {delta, 0.0}}}}}};
  c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"bodies", {"base"}}, {"cycle_from_step", 1}};
  const json s = solve(c);
  ASSERT_EQ(s.at("steps").size(), 2u);  // the cycle's steps, named by their step of the history
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(s.at("steps")[k].at("n_stick"), 0);
    EXPECT_EQ(s.at("steps")[k].at("history_step"), k + 1);
  }
  const std::vector<WornPoint> pts = worn_base();
  for (const WornPoint& p : pts)
    if (p.r < 0.95 * kA) {
      EXPECT_GT(p.depth, 0.0) << "r/a = " << p.r / kA;
    }
  for (const double r_over_a : {0.3, 0.6, 0.9}) {
    const double computed = ring_mean(pts, r_over_a, [](const WornPoint& p) { return p.depth; });
    const double closed = ring_mean(pts, r_over_a, [&](const WornPoint& p) {
      return 5.0 * kK / kH * hertz_pressure(p.r) * (delta - sliding_displacement(p.r));
    });
    EXPECT_NEAR(computed / closed, 1.0, 0.01) << "r/a = " << r_over_a;
  }
}

TEST_F(CliWear, ATorsionCycleWearsAnAxisymmetricRingAndKeepsTheBookkeeping) {
  // Moments +-0.5 of Lubkin's full-slip moment 3 pi mu P a / 16 (Johnson 7.4): the slip ring's
  // wear is axisymmetric (on this symmetric grid: the map's transpose, to the solver's tolerance),
  // the stick core unworn, and Archard's volume k/(mu H) x the dissipated work (32^2, 1.1 a).
  const double M = 0.5 * 3.0 * M_PI * kMu * kP * kA / 16.0;
  json c = sphere(32, 1.1);
  c["tangential"] = {{"regime", "torsion"},
                     {"history", {{{"moment", -M}}, {{"moment", M}}, {{"moment", -M}}}}};
  c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"bodies", {"base"}}};
  const json s = solve(c);
  const double work = s.at("energy").at("dissipated_total").get<double>();
  EXPECT_NEAR(s.at("wear").at("base").at("volume").get<double>() / (kK / (kMu * kH) * work), 1.0, 1e-9);
  for (const json& step : s.at("steps")) EXPECT_GT(step.at("n_stick").get<int>(), 0);
  const std::vector<WornPoint> pts = worn_base();
  ASSERT_EQ(pts.size(), 32u * 32u);
  double deepest = 0.0, asymmetry = 0.0, core = 0.0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const double d = pts[i + 32 * j].depth;
      deepest = std::max(deepest, d);
      asymmetry = std::max(asymmetry, std::abs(d - pts[j + 32 * i].depth));
      if (pts[i + 32 * j].r < 0.2 * kA) core = std::max(core, d);
    }
  EXPECT_GT(deepest, 0.0);
  EXPECT_LT(asymmetry, 1e-9 * deepest);
  EXPECT_LT(core, 1e-6 * deepest);
}

TEST_F(CliWear, CycleJumpingConvergesAndKeepsTheLoad) {
  // 1000 fretting cycles at Q* = 0.5 mu P, k = 1e-2 (the scar's depth ~ 0.1 x the approach: the
  // profile changes), 32^2 elements over 1.6 a, the profile updated every 1e-7, 5e-8, 2.5e-8 m
  // of the deepest wear: the volumes' differences shrink and the finest two agree within 1 %
  // (observed 3 %, then 0.4 %).
  double volume[3] = {};
  for (int k = 0; k < 3; ++k) {
    json c = sphere(32, 1.6);
    c["tangential"] = force_cycle(0.5 * kMu * kP);
    c["wear"] = {{"law", "archard"}, {"k", 1e-2}, {"hardness", kH}, {"bodies", {"base"}},
                 {"cycles", 1000}, {"cycle_from_step", 1}, {"update", {{"max_depth", 1e-7 / (1 << k)}}}};
    const json s = solve(c);
    const json& w = s.at("wear");
    EXPECT_EQ(w.at("cycles"), 1000);
    EXPECT_EQ(w.at("history").back().at("cycles"), 1000);
    EXPECT_GT(w.at("updates").get<int>(), 3 * (k + 1) - 1);
    EXPECT_EQ(w.at("updates").get<std::size_t>(), w.at("history").size());
    long long jumped = 0;
    for (const json& u : w.at("history")) {
      jumped += u.at("jump").get<long long>();
      // The load is kept: every step's normal force is the given one.
      for (const json& f : u.at("normal_force")) EXPECT_NEAR(f.get<double>(), kP, 1e-9 * kP);
      // An update wears at most max_depth at the deepest element (a jump of one cycle may wear more).
      if (u.at("jump").get<long long>() > 1) {
        EXPECT_LE(u.at("jump").get<double>() * u.at("cycle_max_depth").get<double>(), 1e-7 / (1 << k) * (1 + 1e-12));
      }
    }
    EXPECT_EQ(jumped, 1000);
    volume[k] = w.at("base").at("volume").get<double>();
  }
  EXPECT_LT(std::abs(volume[2] - volume[1]), std::abs(volume[1] - volume[0]));
  EXPECT_NEAR(volume[2] / volume[1], 1.0, 0.01);
}

TEST_F(CliWear, UpdateCyclesBoundsTheJumpsAndTheWornVolumeAddsUp) {
  // 10 cycles updated every 3 (jumps 3, 3, 3, 1), and without an update block every cycle: the
  // worn volume is the sum of each solved cycle's volume times its jump, to round-off (32^2).
  json c = sphere(32, 1.1);
  c["tangential"] = force_cycle(0.5 * kMu * kP);
  for (const bool every_three : {true, false}) {
    c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"bodies", {"body"}}, {"cycles", every_three ? 10 : 3}};
    if (every_three) c["wear"]["update"] = {{"cycles", 3}};
    const json s = solve(c);
    const json& w = s.at("wear");
    const std::vector<long long> jumps = every_three ? std::vector<long long>{3, 3, 3, 1} : std::vector<long long>{1, 1, 1};
    ASSERT_EQ(w.at("history").size(), jumps.size());
    double sum = 0.0;
    for (std::size_t k = 0; k < jumps.size(); ++k) {
      EXPECT_EQ(w.at("history")[k].at("jump").get<long long>(), jumps[k]);
      sum += jumps[k] * w.at("history")[k].at("cycle_volume").get<double>();
    }
    EXPECT_EQ(w.at("updates").get<std::size_t>(), jumps.size());
    EXPECT_NEAR(w.at("body").at("volume").get<double>() / sum, 1.0, 1e-12);
    EXPECT_FALSE(w.contains("base"));
  }
}

TEST_F(CliWear, TheWornProfilesEvolutionIsWrittenAfterTheUpdatesThinnedToSixtyFour) {
  // 100 cycles of +-0.5 mu P updated every cycle (32^2): 100 updates, of which every second one's
  // worn depth is kept once 64 would be passed (updates 0, 2, ..., 98) and the last (99): 51
  // images in wear.pvd at 1, 3, ..., 99 and 100 cycles. The profile along the centre line only
  // deepens from one to the next (fretting removes material), the last is wear.csv's, and wear.pvd
  // lists the images in order with the cycles as time.
  json c = sphere(32, 1.1);
  c["tangential"] = force_cycle(0.5 * kMu * kP);
  c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"bodies", {"base"}}, {"cycles", 100},
               {"cycle_from_step", 1}, {"update", {{"cycles", 1}}}};
  c["output"] = {{"plots", true}};
  const json s = solve(c);
  ASSERT_EQ(s.at("wear").at("updates").get<int>(), 100);
  const json& files = s.at("files");
  EXPECT_EQ(files.at("wear_series"), "wear.pvd");
  EXPECT_EQ(files.at("wear_profiles"), "wear_profiles.csv");
  const std::string pvd = slurp(dir_ / "out" / "wear.pvd");
  std::vector<long long> times;
  for (std::size_t at = pvd.find("timestep=\""); at != std::string::npos; at = pvd.find("timestep=\"", at + 1))
    times.push_back(std::stoll(pvd.substr(at + 10)));
  ASSERT_EQ(times.size(), 51u);
  for (std::size_t k = 0; k + 1 < times.size(); ++k) EXPECT_EQ(times[k], 2 * static_cast<long long>(k) + 1) << k;
  EXPECT_EQ(times.back(), 100);
  for (std::size_t k = 0; k < times.size(); ++k)
    EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / ("wear_" + std::to_string(k) + ".vti"))) << k;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "wear_51.vti"));
  // wear_profiles.csv: cycles,x,base; 32 points per state.
  std::istringstream rows(slurp(dir_ / "out" / "wear_profiles.csv"));
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line, "cycles,x,base");
  std::map<long long, std::vector<double>> profiles;
  std::vector<double> xs;
  while (std::getline(rows, line)) {
    long long cycles = 0;
    double x = 0, d = 0;
    char comma = 0;
    std::istringstream(line) >> cycles >> comma >> x >> comma >> d;
    profiles[cycles].push_back(d);
    if (profiles.size() == 1) xs.push_back(x);
  }
  ASSERT_EQ(profiles.size(), 51u);
  const std::vector<double>* before = nullptr;
  for (const auto& [cycles, profile] : profiles) {
    ASSERT_EQ(profile.size(), 32u) << cycles;
    if (before) {
      for (std::size_t i = 0; i < profile.size(); ++i) EXPECT_GE(profile[i], (*before)[i]) << cycles << " at " << i;
    }
    before = &profile;
  }
  EXPECT_GT(*std::max_element(before->begin(), before->end()), 0.0);
  // The last profile is wear.csv's row nearest y = 0 (row 16 of 32: y = +dy / 2).
  std::istringstream worn(slurp(dir_ / "out" / "wear.csv"));
  std::getline(worn, line);
  std::vector<double> centre;
  double y_row = 1e9;
  std::vector<std::pair<double, double>> cells;
  while (std::getline(worn, line)) {
    double x = 0, y = 0, d = 0;
    char comma = 0;
    std::istringstream(line) >> x >> comma >> y >> comma >> d;
    if (y >= 0.0 && y < y_row) y_row = y;
    cells.push_back({y, d});
  }
  for (const auto& [y, d] : cells)
    if (y == y_row) centre.push_back(d);
  ASSERT_EQ(centre.size(), 32u);
  for (std::size_t i = 0; i < 32; ++i) EXPECT_NEAR(centre[i], (*before)[i], 1e-9 * (*before)[i] + 1e-30) << i;
  const json& plots = files.at("plots");
  EXPECT_NE(std::find(plots.begin(), plots.end(), "wear_evolution.svg"), plots.end());
}

TEST_F(CliWear, AnAnnularPunchTwistedInFullSlipWearsToTheSteadyPressure) {
  // A flat annular punch b <= r < a (b = a/2 = 0.5 mm; profile flat_punch with inner_radius)
  // under P = 1 kN, twisted +-0.05 rad (full slip: the rigid slip 4 theta r per cycle is 60 x the
  // elastic displacement) under Archard wear. Uniform wear needs p |ds| = const, so the
  // steady pressure is p = C / r, C = P / (2 pi (a - b)), and the depth per cycle (k/H) 4 theta C
  // on every element. 32^2 over +-1.1 a, 3000 cycles, updates every 0.2 um: the last cycle's mean
  // wear rate within 3 % of the closed form (-2.3 % measured: the elastic part of the slip) where the
  // unworn punch's is 8 % above it (its rims carry the load), the ring means of p r / C within 3 %
  // over b <= r <= 0.7 a (the outer rings' staircase rim scatters by element), the peak pressure at
  // the inner rim C / b within 1 % (+0.2 %), and the load kept at every step.
  const double a = 1e-3, b = 0.5e-3, P = 1000.0, theta = 0.05, ext = 1.1 * a;
  const int n = 32;
  const double dx = 2.0 * ext / n, C = P / (2.0 * M_PI * (a - b));
  int annulus = 0;  // the elements whose centres lie on the annulus
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -ext + (i + 0.5) * dx, y = -ext + (j + 0.5) * dx, r = std::hypot(x, y);
      annulus += r >= b && r < a;
    }
  json c = sphere(n, 1.1);
  c["materials"] = {{"body", {{"E", kE}, {"nu", 0.3}}}, {"base", {{"E", kE}, {"nu", 0.3}}}};
  c["profile"] = {{"type", "flat_punch"}, {"radius", a}, {"inner_radius", b}};
  c["grid"] = {{"nx", n}, {"ny", n}, {"x", {-ext, ext}}, {"y", {-ext, ext}}};
  c["normal"] = {{"force", P}};
  c["tangential"] = {{"regime", "torsion"}, {"history", {{{"angle", theta}}, {{"angle", -theta}}, {{"angle", theta}}}}};
  c["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"cycles", 3000},
               {"update", {{"max_depth", 2e-7}}}, {"cycle_from_step", 1}};
  c["output"] = {{"plots", true}};  // the figure wear_x: its data, the centre row of each body's depth
  const json s = solve(c);
  {
    std::istringstream data(slurp(dir_ / "out" / "wear_x.dat"));
    std::string line;
    int rows = 0;
    double deepest = 0.0;
    while (std::getline(data, line))
      if (line[0] != '#') {
        double x = 0, base = 0, body = 0;
        std::istringstream(line) >> x >> base >> body;
        EXPECT_EQ(base, body);  // both bodies wear alike
        deepest = std::max(deepest, base);
        ++rows;
      }
    EXPECT_EQ(rows, n);
    EXPECT_GT(deepest, 0.5 * s.at("wear").at("base").at("max_depth").get<double>());
    EXPECT_LE(deepest, s.at("wear").at("base").at("max_depth").get<double>() * (1.0 + 1e-8));  // 9 printed digits
  }
  const json& history = s.at("wear").at("history");
  ASSERT_GT(history.size(), 10u);
  const double rate = kK / kH * 4.0 * theta * C, area = annulus * dx * dx;
  const double first = history.front().at("cycle_volume").get<double>() / area / rate;
  const double last = history.back().at("cycle_volume").get<double>() / area / rate;
  EXPECT_GT(first, 1.05);
  EXPECT_NEAR(last, 1.0, 0.03);
  EXPECT_NEAR(history.back().at("max_pressure").get<double>() / (C / b), 1.0, 0.01);
  for (const json& u : history)
    for (const json& f : u.at("normal_force")) EXPECT_NEAR(f.get<double>(), P, 1e-9 * P);
  // Ring means of p r / C from fields.csv (the last cycle's last step).
  std::istringstream rows(slurp(dir_ / "out" / "fields.csv"));
  std::string line;
  std::getline(rows, line);
  std::vector<double> sum(40, 0.0);
  std::vector<int> count(40, 0);
  while (std::getline(rows, line)) {
    double x = 0, y = 0, p = 0;
    char comma = 0;
    std::istringstream(line) >> x >> comma >> y >> comma >> p;
    const double r = std::hypot(x, y);
    if (p <= 0.0 || r > 0.7 * a) continue;
    const int ring = static_cast<int>(std::lround(r / a * 20.0));
    sum[ring] += p * r / C;
    ++count[ring];
  }
  int rings = 0;
  for (int k = 0; k < 40; ++k)
    if (count[k] > 0) {
      ++rings;
      EXPECT_NEAR(sum[k] / count[k], 1.0, 0.03) << "r/a = " << k / 20.0;
    }
  EXPECT_GE(rings, 4);
  std::printf("[ info ] annular punch: steady wear rate %.4f x (k/H) 4 theta C (unworn %.4f), peak %.4f x C/b, %zu updates\n",
              last, first, history.back().at("max_pressure").get<double>() / (C / b), history.size());
}

TEST_F(CliWear, GrossSlipRunsInTheContactWidensAndThePeakPressureFalls) {
  // 100 cycles of shifts +-3 U(0), k = 1e-3, updates every 1e-7 m: the worn centre spreads the
  // load, so each update's contact is wider and its peak pressure lower than the one before.
  json c = sphere(32, 1.6);
  const double delta = 3.0 * sliding_displacement(0.0);
  c["tangential"] = {{"regime", "shift"},
                     {"history", {{{"shift", {delta, 0.0}}}, {{"shift", {-delta, 0.0}}}, {{"shift", {delta, 0.0}}}}}};
  c["wear"] = {{"law", "archard"}, {"k", 1e-3}, {"hardness", kH}, {"cycles", 100}, {"cycle_from_step", 1},
               {"update", {{"max_depth", 1e-7}}}};
  const json s = solve(c);
  const json& h = s.at("wear").at("history");
  ASSERT_GT(h.size(), 3u);
  for (std::size_t k = 1; k < h.size(); ++k) {
    EXPECT_LT(h[k].at("max_pressure").get<double>(), h[k - 1].at("max_pressure").get<double>()) << k;
    EXPECT_GE(h[k].at("contact_area").get<double>(), h[k - 1].at("contact_area").get<double>()) << k;
  }
  EXPECT_LT(h.back().at("max_pressure").get<double>(), 0.95 * kP0);
}

TEST_F(CliWear, BadWearBlocksAreInputErrorsNamingTheKey) {
  json base = sphere(16, 1.1);
  base["tangential"] = force_cycle(15.0);
  base["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}};
  const std::vector<std::pair<json, std::string>> bad = {
      {{{"wear", {{"law", "archard"}, {"k", kK}}}}, "wear.hardness"},
      {{{"wear", {{"law", "archard"}, {"k", -1.0}, {"hardness", kH}}}}, "wear.k"},
      {{{"wear", {{"law", "energy"}, {"coefficient", 1e-14}, {"k", 1.0}}}}, "wear.k"},
      {{{"wear", {{"law", "plastic"}}}}, "wear.law"},
      {{{"wear", {{"k", kK}, {"hardness", kH}}}}, "wear.law"},
      {{{"wear", {{"law", "energy"}}}}, "wear.coefficient"},
      {{{"wear", {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"cycles", 0}}}}, "wear.cycles"},
      {{{"wear", {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"bodies", {"rail"}}}}}, "wear.bodies"},
      {{{"wear", {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"update", {{"every", 3}}}}}}, "wear.update.every"},
      {{{"wear", {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"update", 3}}}}, "wear.update"},
      {{{"wear", {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"update", json::object()}}}}, "wear.update"},
      {{{"wear", {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"update", {{"max_depth", 0.0}}}}}},
       "wear.update.max_depth"},
      {{{"wear", {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"cycle_from_step", 3}}}}, "wear.cycle_from_step"},
      {{{"wear", {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"speed", 1}}}}, "wear.speed"},
      {{{"wear", 3}}, "wear"},
      // Where it does not apply: one step without a history, the normal problem (rolling:
      // test_cli_rolling_wear.cpp).
      {{{"tangential", {{"regime", "shift"}, {"force", {-15.0, 0.0}}, {"history", nullptr}}}}, "wear"},
      {{{"problem", "normal"}, {"tangential", nullptr}, {"friction", nullptr}}, "wear"},
      {{{"accuracy", {{"estimate", true}, {"target", 1e-3}}}}, "wear"},
  };
  for (const auto& [patch, key] : bad) {
    json doc = base;
    doc.merge_patch(patch);
    if (patch.contains("wear")) doc["wear"] = patch["wear"];  // the whole block, not merged
    SCOPED_TRACE(patch.dump());
    expect_input_error("validate " + write_case(doc), key);
  }
  // A dynamic case with a wear block.
  json dynamic = dc::test::coarse_ball_impact();
  dynamic["wear"] = base["wear"];
  expect_input_error("validate " + write_case(dynamic), "wear");
}

}  // namespace cli_wear_test
