// Wear over a dynamic run (CASES.md "wear", docs/wear_energy.md "Wear in dynamic runs"): the
// wheel of wheel-drive rolling under a growing driving moment until it slides. Archard's volume
// of both maps against k/(mu H) x the energy audit's dissipation (round-off), the track's wear
// per unit length under every step against that step's dissipation over its travel (the frame
// bookkeeping), growing with the slip; the worn circumference raising the approach of the
// following revolutions (the worn depth in the gap); the input errors of a dynamic wear block.
// The track map itself (DynamicWear fed steps directly): a curved path worn along its arc, its
// volume kept while the map's cells double beyond their budget.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_wear.hpp"

namespace cli_dynamic_wear_test {  // named: the unity build shares one translation unit

using json = nlohmann::json;
using dc::test::slurp;

constexpr double kK = 1e-4, kH = 2e9, kMu = 0.3;

/// The rows of a CSV file with a header, as numbers by column name.
std::vector<std::map<std::string, double>> csv_rows(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::istringstream h(line);
    std::string name;
    while (std::getline(h, name, ',')) names.push_back(name);
  }
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    std::istringstream r(line);
    std::string cell;
    std::map<std::string, double> row;
    for (std::size_t k = 0; k < names.size() && std::getline(r, cell, ','); ++k) row[names[k]] = std::stod(cell);
    rows.push_back(std::move(row));
  }
  return rows;
}

class CliDynamicWear : public dc::test::CliTest {
 protected:
  json solve(const json& c) const {
    const auto r = run("solve " + write_case(c) + " --out out -q");
    EXPECT_EQ(r.code, 0) << r.err;
    return json::parse(slurp(dir_ / "out" / "summary.json"));
  }
  /// bowling-ball launched sliding (transient model) at `velocity` with `omega` until `t_end`,
  /// the base wearing by Archard (k 1e-4, H 1e8, mu 0.2): its summary, the completed run's volume
  /// checked against k/(mu H) x the dissipation (round-off).
  json slide_ball(const json& velocity, const json& omega, double t_end) const {
    json c = dc::test::example_json("bowling-ball");
    c["body"]["initial"]["velocity"] = velocity;
    c["body"]["initial"]["omega"] = omega;
    c["time"]["t_end"] = t_end;
    c["contact_model"] = "transient";
    c["output"] = {{"plots", false}};
    c["wear"] = {{"law", "archard"}, {"k", 1e-4}, {"hardness", 1e8}};
    const json s = solve(c);
    EXPECT_EQ(s.at("status"), "completed");
    EXPECT_NEAR(s.at("wear").at("base").at("volume").get<double>() /
                    (1e-4 / (0.2 * 1e8) * s.at("energy").at("dissipated").get<double>()),
                1.0, 1e-9);
    return s;
  }
  static json wheel(const json& wear) {
    json c = dc::test::example_json("wheel-drive");
    c["output"] = {{"plots", false}};
    c["wear"] = wear;
    return c;
  }
};

TEST_F(CliDynamicWear, AWheelDrivenToSlidingWearsTheTrackWhereItSlipsByTheDissipatedEnergy) {
  // wheel-drive (12^2, R = 0.1 m, 1 kN, mu = 0.3, dt = 0.02 s): the moment grows at 20 N m/s,
  // the creepage with it, until the wheel slides after about 2.25 s. Coulomb: Archard's volume of
  // each map is k/(mu H) x the dissipated energy, to round-off.
  const json s = solve(wheel({{"law", "archard"}, {"k", kK}, {"hardness", kH}}));
  const double dissipated = s.at("energy").at("dissipated").get<double>();
  ASSERT_GT(dissipated, 0.0);
  const json& w = s.at("wear");
  for (const char* body : {"base", "body"})
    EXPECT_NEAR(w.at(body).at("volume").get<double>() / (kK / (kMu * kH) * dissipated), 1.0, 1e-9) << body;
  EXPECT_EQ(s.at("files").at("wear"), "wear.csv");
  EXPECT_EQ(s.at("files").at("wear_body"), "wear_body.csv");
  EXPECT_TRUE(w.at("gap_feedback").get<bool>());  // the default
  // The body turned ~9.7 times over ~6 m (omega R ~ v until it slides).
  const json& final = s.at("final");
  EXPECT_NEAR(w.at("travel").get<double>(), final.at("position")[0].get<double>(), 1e-12);
  EXPECT_GT(w.at("cycles").get<double>(), 9.0);

  // Every step's travel (2 to 10 cm, many contact lengths of 0.9 mm) is worn along the track by
  // the step's dissipation W_k spread over it: at the middle of the step's path the track's
  // volume per unit length (its column's depths times dy) is k/(mu H) W_k / travel_k. energy.csv
  // and timeseries.csv carry 10 digits (tolerance 1e-6).
  const auto energy = csv_rows(slurp(dir_ / "out" / "energy.csv"));
  const auto series = csv_rows(slurp(dir_ / "out" / "timeseries.csv"));
  const auto track = csv_rows(slurp(dir_ / "out" / "wear.csv"));
  ASSERT_EQ(energy.size(), series.size() + 1);  // energy.csv's first row is t = 0
  std::map<double, double> per_length;            // the track's column x -> sum of depth dy
  const double dy = 0.012 / 12;
  for (const auto& row : track) per_length[row.at("x")] += row.at("base") * dy;
  const double cell = w.at("base").at("cell").get<double>();
  double x_prev = 0.0, last_rolling = 0.0, first_rolling = 0.0;
  int checked = 0;
  for (std::size_t k = 0; k < series.size(); ++k) {
    const double x = series[k].at("x"), travel = x - x_prev;
    const double work = energy[k + 1].at("dissipated") - energy[k].at("dissipated");
    const double mid = 0.5 * (x + x_prev);
    x_prev = x;
    // (The first step, from the unloaded state, sticks: its work 4e-18 J is the solver's
    // round-off, against which Archard's p |s| of the stuck elements is not the work's share.)
    if (travel < 20.0 * cell || work < 1e-9 * dissipated) continue;
    auto it = per_length.lower_bound(mid - 0.5 * cell);
    ASSERT_NE(it, per_length.end());
    const double expected = kK / (kMu * kH) * work / travel;
    EXPECT_NEAR(it->second / expected, 1.0, 1e-6) << "step " << k + 1 << " at x = " << mid;
    ++checked;
    // While it rolls (t < 2 s) the creepage grows and so does the wear per length.
    if (series[k].at("t") < 2.0) {
      if (first_rolling == 0.0) first_rolling = it->second;
      EXPECT_GT(it->second, last_rolling) << "step " << k + 1;
      last_rolling = it->second;
    }
  }
  EXPECT_GT(checked, 100);
  // Sliding (the last steps) wears the track far more than early rolling.
  double max_per_length = 0.0;
  for (const auto& [x, v] : per_length) max_per_length = std::max(max_per_length, v);
  EXPECT_GT(max_per_length, 100.0 * first_rolling);

  // The energy law with alpha = k/(mu H), the body alone, wears the same volume.
  const json e = solve(wheel({{"law", "energy"}, {"coefficient", kK / (kMu * kH)}, {"bodies", {"body"}}}));
  EXPECT_NEAR(e.at("wear").at("body").at("volume").get<double>() / (kK / (kMu * kH) * dissipated), 1.0, 1e-9);
  EXPECT_FALSE(e.at("wear").contains("base"));
  EXPECT_FALSE(e.at("files").contains("wear"));
}

TEST_F(CliDynamicWear, AWheelsWornCircumferenceRaisesTheApproachByItsDepthOnceARevolution) {
  // cylinder-dynamic-2d (R = 0.5 m, 60 kN/m, 10 m/s) under a constant driving moment 6750 N m/m:
  // F = (2/3) M / R = 0.5 mu P, a steady creepage (-1.0058e-4) as it accelerates, so every step
  // wears the wheel's circumference by the same depth per length, d = k/(mu H) W_k / (R omega dt),
  // the track being fresh ahead. Force control in 2-D: a gap raised uniformly over the contact
  // raises the approach by the same amount. With the worn depth in the gap (the default) the
  // approach is the unworn run's during the first revolution, and then n d higher in revolution
  // n + 1 (the contact's 2b = 2.4 mm against 0.2 m of arc per step; revolutions counted as
  // sum omega_y dt, steps within 0.1 revolution of a boundary left out). timeseries.csv's 8
  // digits of the approach: 1e-3 of d (k = 0.1: d = 1.45e-10 m).
  json c = dc::test::example_json("cylinder-dynamic-2d");
  c["output"] = {{"plots", false}};
  c["loads"]["moment"]["y"] = {{"value", 6750.0}, {"rate", 0.0}};
  c["time"]["t_end"] = 1.0;
  const double k = 0.1, R = 0.5, dt = 0.02;
  c["wear"] = {{"law", "archard"}, {"k", k}, {"hardness", kH}, {"bodies", {"body"}}};
  const json worn = solve(c);
  ASSERT_EQ(worn.at("status"), "completed");
  EXPECT_TRUE(worn.at("wear").at("gap_feedback").get<bool>());
  const auto series = csv_rows(slurp(dir_ / "out" / "timeseries.csv"));
  const auto energy = csv_rows(slurp(dir_ / "out" / "energy.csv"));
  c["wear"]["gap_feedback"] = false;
  const json plain = solve(c);
  EXPECT_FALSE(plain.at("wear").at("gap_feedback").get<bool>());
  const auto unworn = csv_rows(slurp(dir_ / "out" / "timeseries.csv"));
  ASSERT_EQ(series.size(), unworn.size());
  auto step_depth = [&](std::size_t s) {
    const double work = energy[s + 1].at("dissipated") - energy[s].at("dissipated");
    return k / (kMu * kH) * work / (R * series[s].at("wy") * dt);
  };
  const double d = step_depth(5);  // steady from the third step
  double turns = 0.0;
  int checked[4] = {};
  for (std::size_t s = 0; s < series.size(); ++s) {
    turns += series[s].at("wy") * dt / (2.0 * M_PI);
    if (s > 2) {
      EXPECT_NEAR(step_depth(s) / d, 1.0, 1e-6) << "step " << s + 1;
    }
    const double fraction = turns - std::floor(turns);
    if (fraction < 0.1 || fraction > 0.9) continue;
    const int n = static_cast<int>(std::floor(turns));
    const double rise = series[s].at("approach") - unworn[s].at("approach");
    if (n == 0) {
      EXPECT_EQ(rise, 0.0) << "step " << s + 1;
    } else {
      EXPECT_NEAR(rise / (n * d), 1.0, 1e-3) << "step " << s + 1 << ", revolution " << n + 1;
    }
    if (n < 4) ++checked[n];
  }
  for (int n = 0; n < 3; ++n) EXPECT_GE(checked[n], 8) << "revolution " << n + 1;
  // The worn wheel's volume is still k/(mu H) x the dissipated energy.
  EXPECT_NEAR(worn.at("wear").at("body").at("volume").get<double>() /
                  (k / (kMu * kH) * worn.at("energy").at("dissipated").get<double>()),
              1.0, 1e-9);
}

TEST_F(CliDynamicWear, ATrackWornSidewaysOrAslantIsTheTrackWornAlongXTurned) {
  // bowling-ball (16^2, a = 1.4 mm) launched sliding at 0.5 m/s without spin, 50 steps of 2 ms
  // (transient model: it rolls after 73 ms): along +x, along +y (pure lateral motion) and aslant
  // (0.4, 0.3). The half-space's map is in world coordinates, so the three tracks are one track
  // turned: the same volume (k/(mu H) x each run's dissipation, round-off), the same deepest wear
  // (0.1 % sideways, where the rows and cells swap their binning; 1 % aslant, cells 0.23 mm across
  // a 2.8 mm track), the same length and width (a cell), and every worn cell aslant within a cell
  // of the contact's path. (With the rows kept in the grid's frame, the sideways track would pile
  // into the 16 rows under the ball, 8 times deeper.)
  auto slide = [&](double vx, double vy) {
    const json s = slide_ball({vx, vy, 0.0}, {0.0, 0.0, 0.0}, 0.1);
    return std::pair{s, csv_rows(slurp(dir_ / "out" / "wear.csv"))};
  };
  struct Extent {
    double along_lo = 1e9, along_hi = -1e9, across_lo = 1e9, across_hi = -1e9, farthest = 0.0;
  };
  auto extent = [](const std::vector<std::map<std::string, double>>& cells, double ux, double uy) {
    Extent e;
    for (const auto& cell : cells) {
      if (!(cell.at("base") > 0.0)) continue;
      const double along = cell.at("x") * ux + cell.at("y") * uy, across = cell.at("y") * ux - cell.at("x") * uy;
      e.along_lo = std::min(e.along_lo, along);
      e.along_hi = std::max(e.along_hi, along);
      e.across_lo = std::min(e.across_lo, across);
      e.across_hi = std::max(e.across_hi, across);
      e.farthest = std::max(e.farthest, std::abs(across));
    }
    return e;
  };
  const auto [along_x, x_cells] = slide(0.5, 0.0);
  const auto [along_y, y_cells] = slide(0.0, 0.5);
  const auto [aslant, slant_cells] = slide(0.4, 0.3);
  const double cell = along_x.at("wear").at("base").at("cell").get<double>();
  const double volume = along_x.at("wear").at("base").at("volume").get<double>();
  const double deepest = along_x.at("wear").at("base").at("max_depth").get<double>();
  const Extent ex = extent(x_cells, 1.0, 0.0), ey = extent(y_cells, 0.0, 1.0), es = extent(slant_cells, 0.8, 0.6);
  ASSERT_GT(ex.along_hi - ex.along_lo, 20.0 * (ex.across_hi - ex.across_lo) / 2.0) << "a track, not a scar";
  for (const auto* run : {&along_y, &aslant}) {
    const json& base = run->at("wear").at("base");
    EXPECT_NEAR(base.at("volume").get<double>() / volume, 1.0, 1e-3);
    EXPECT_NEAR(base.at("max_depth").get<double>() / deepest, 1.0, run == &along_y ? 1e-3 : 1e-2);
  }
  for (const Extent* e : {&ey, &es}) {
    EXPECT_NEAR(e->along_lo, ex.along_lo, 1.5 * cell);
    EXPECT_NEAR(e->along_hi, ex.along_hi, 1.5 * cell);
  }
  EXPECT_NEAR(ey.across_lo, ex.across_lo, 1.01 * cell);
  EXPECT_NEAR(ey.across_hi, ex.across_hi, 1.01 * cell);
  EXPECT_LT(es.farthest, ex.farthest + 1.5 * cell) << "aslant: the worn cells along the contact's path";
}

TEST_F(CliDynamicWear, AHookingBallWearsItsCurvedPath) {
  // bowling-ball launched at 0.5 m/s along x with a side roll (omega_x R = 0.3 m/s): the slip at
  // the contact, (0.5, 0.3) m/s, drives friction against it, and the ball hooks towards -y on a
  // parabola (3.5 mm sideways over its 36 mm slide; rolling from then on, straight). The track
  // map in world x and y: at every column of the slide's track the worn material's mean y is the
  // ball's y where its centre passed that x (timeseries.csv, interpolated) within a quarter cell
  // (measured: 0.1), 10 cells off y = 0 at the slide's end; the volume is k/(mu H) x the
  // dissipation (round-off).
  const double R = dc::test::example_json("bowling-ball")["body"]["radius"].get<double>();
  const json s = slide_ball({0.5, 0.0, 0.0}, {0.3 / R, 0.0, 0.0}, 0.12);
  ASSERT_EQ(s.at("status"), "completed");
  const double cell = s.at("wear").at("base").at("cell").get<double>();
  const auto path = csv_rows(slurp(dir_ / "out" / "timeseries.csv"));
  ASSERT_GT(path.size(), 10u);
  const double y_end = path.back().at("y");
  ASSERT_LT(y_end, -10.0 * cell) << "the ball hooks by many cells";
  auto y_at = [&](double x) {  // the ball's y where its centre passed x (x grows along the run)
    for (std::size_t k = 1; k < path.size(); ++k)
      if (path[k].at("x") >= x) {
        const auto &a = path[k - 1], &b = path[k];
        return a.at("y") + (b.at("y") - a.at("y")) * (x - a.at("x")) / (b.at("x") - a.at("x"));
      }
    return path.back().at("y");
  };
  std::map<double, std::pair<double, double>> columns;  // x -> (sum depth, sum depth y)
  for (const auto& w : csv_rows(slurp(dir_ / "out" / "wear.csv"))) {
    auto& [mass, moment] = columns[w.at("x")];
    mass += w.at("base");
    moment += w.at("base") * w.at("y");
  }
  const double x_first = path.front().at("x"), a = 1.4e-3;
  double heaviest = 0.0;
  for (const auto& [x, m] : columns) heaviest = std::max(heaviest, m.first);
  int checked = 0;
  double farthest = 0.0;
  for (const auto& [x, m] : columns) {
    if (!(m.first > 0.0) || x < x_first + 2.0 * a) continue;  // past the start's scar
    if (m.first >= 0.25 * heaviest) {  // the slide's track: the wear of many steps, evenly
      EXPECT_LT(std::abs(m.second / m.first - y_at(x)), 0.25 * cell) << "x = " << x;
      farthest = std::max(farthest, std::abs(y_at(x)));
      ++checked;
    }
    // Not asserted where the slide's wear fades (over the contact's length 2a a column's mean
    // leans to the heavier side by up to the path's slope x a) nor after it: rolling's micro-slip
    // wears the contact's slip zone, off the centre line.
  }
  EXPECT_GT(checked, 40);
  EXPECT_GT(farthest, 5.0 * cell) << "columns checked where the path is off y = 0";
}

TEST_F(CliDynamicWear, BadDynamicWearBlocksAreInputErrorsNamingTheKey) {
  const json law = {{"law", "archard"}, {"k", kK}, {"hardness", kH}};
  for (const char* key : {"cycles", "update", "cycle_from_step", "rolling_radius"}) {
    json w = law;
    w[key] = std::string(key) == "update" ? json{{"cycles", 2}} : json(1);
    SCOPED_TRACE(key);
    expect_input_error("validate " + write_case(wheel(w)), std::string("wear.") + key);
  }
  json frictionless = wheel(law);
  frictionless.erase("friction");
  expect_input_error("validate " + write_case(frictionless), "wear");
  json sweep = wheel(law);
  sweep["sweep"] = {{"body.mass", {50.0, 100.0}}};
  expect_input_error("validate " + write_case(sweep), "wear");
  json fe = dc::test::example_json("fe-hemisphere-drop");
  fe["wear"] = law;
  expect_input_error("validate " + write_case(fe), "wear");
  // The worn gap with an accuracy estimate (its coarser runs would wear too); a history's key.
  json estimate = wheel(law);
  estimate["accuracy"] = {{"estimate", true}};
  expect_input_error("validate " + write_case(estimate), "wear.gap_feedback");
  json history = dc::test::example_json("cattaneo-sphere");
  history["tangential"] = {{"regime", "shift"}, {"history", {{{"force", {-15.0, 0.0}}}, {{"force", {15.0, 0.0}}}}}};
  json w = law;
  w["gap_feedback"] = false;
  history["wear"] = w;
  expect_input_error("validate " + write_case(history), "wear.gap_feedback");
}

/// The track map of a contact patch (a disc of 5 elements' radius under uniform Archard wear)
/// carried along a quarter circle of radius 40 dx, fed to DynamicWear step by step as a run's
/// accepted steps would be: with the default budget, and with 1024 cells, where the map's cells
/// must double along and across (the coarsening branches). Either way the map holds the deposited
/// volume to round-off, and at every column up to the arc's 45 degrees the worn material's mean Y
/// is the arc's y(X) within a cell and the band's curvature r^2 (1 + y'^2) / 2 R_c (measured: at
/// most half a fine cell; rows that did not follow the body sideways would be 12 cells off).
TEST(DynamicWearMap, ACurvedTrackIsWornAlongItsArcAndKeepsItsVolumeWhenTheMapCoarsens) {
  nlohmann::json doc = dc::test::example_json("bowling-ball");
  doc["wear"] = {{"law", "archard"}, {"k", kK}, {"hardness", kH}, {"bodies", {"base"}}};
  const dc::Case c = dc::build_case(doc);
  const dc::Grid& g = c.grid;
  const double X0 = c.dynamic->position[0], Y0 = c.dynamic->position[1];
  dc::TangentialSolution t;
  const std::size_t n = g.size();
  t.normal.pressure.assign(n, 0.0);
  t.tx.assign(n, 0.0);
  t.ty.assign(n, 0.0);
  t.sx.assign(n, 0.0);
  t.sy.assign(n, 0.0);
  const double r = 5.0 * g.dx, p = 1e8, slip = 1e-6;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (std::hypot(g.xc(i), g.yc(j)) < r) {
        const std::size_t e = g.index(i, j);
        t.normal.pressure[e] = p;
        t.tx[e] = -kMu * p;  // against the slip: dissipates
        t.sx[e] = slip;
      }
  const double step_volume = [&] {
    double v = 0.0;
    for (std::size_t e = 0; e < n; ++e) v += kK * t.normal.pressure[e] * std::abs(t.sx[e]) / kH * g.area();
    return v;
  }();
  const double Rc = 40.0 * g.dx;
  const int steps = 210;  // 0.3 dx each
  for (const long long budget : {dc::runs::DynamicWear::kMaxMapCells, 1024LL}) {
    dc::runs::DynamicWear wear(c, budget);
    for (int k = 1; k <= steps; ++k) {
      const double theta = 0.5 * M_PI * k / steps;
      dc::dynamics::DynamicSample s;
      s.state.position = Eigen::Vector3d(X0 + Rc * std::sin(theta), Y0 + Rc * (1.0 - std::cos(theta)), 0.1);
      s.contact_state.in_contact = true;
      s.contact_state.fields = &t;
      s.contact_state.pressure = &t.normal.pressure;
      s.contact_state.frictional_work = dc::frictional_work(t, g.area());
      wear.observe(g, s);
    }
    const dc::runs::WornStrip track = wear.base();
    SCOPED_TRACE("budget " + std::to_string(budget));
    EXPECT_NEAR(track.volume(), steps * step_volume, 1e-12 * steps * step_volume);
    const dc::Grid& m = track.grid;
    if (budget == 1024) {
      EXPECT_LE(m.size(), 2u * 1024u);
      EXPECT_GE(m.dx, 2.0 * g.dx);  // doubled along
      EXPECT_GE(m.dy, 2.0 * g.dy);  // and across
    } else {
      EXPECT_DOUBLE_EQ(m.dx, g.dx);
      EXPECT_DOUBLE_EQ(m.dy, g.dy);
    }
    int columns = 0;
    for (int i = 0; i < m.nx; ++i) {
      const double X = m.xc(i) - X0;
      // From the start's patch to the arc's 45 degrees: beyond, a column cuts the band of the track
      // ever more obliquely and its mean leaves the centre line by the band's curvature.
      if (X < r || X > Rc / std::sqrt(2.0)) continue;
      double mass = 0.0, moment = 0.0;
      for (int j = 0; j < m.ny; ++j) {
        mass += track.depth[m.index(i, j)];
        moment += track.depth[m.index(i, j)] * (m.yc(j) - Y0);
      }
      if (!(mass > 0.0)) continue;
      ++columns;
      const double arc = Rc - std::sqrt(Rc * Rc - X * X);
      const double slope = X / std::sqrt(Rc * Rc - X * X);  // the patch's width across the column grows
      EXPECT_NEAR(moment / mass, arc, m.dy + r * r / (2.0 * Rc) * (1.0 + slope * slope)) << "X = " << X;
    }
    EXPECT_GT(columns, budget == 1024 ? 8 : 20);
  }
}

}  // namespace cli_dynamic_wear_test


