// Frictional power and dissipation (CASES.md "energy", issue 30): the bookkeeping of steady
// rolling, -(F_x xi + F_y eta + M_z phi) V = frictional + scheme power to round-off, the upwind
// scheme's share vanishing at first order with the element size, so that the dissipation tends
// to the creep forces' power, Carter's |F| xi V (Johnson 8.4); the power density column of
// fields.csv; a quasi-static history's dissipation per step and in total; a dynamic run's
// energy audit in energy.csv and summary.json (docs/wear_energy.md "Dynamic runs").
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "hertz.hpp"

namespace {

using json = nlohmann::json;
using dc::test::slurp;

class CliEnergy : public dc::test::CliTest {
 protected:
  json solve(const json& c) const {
    const auto r = run("solve " + write_case(c) + " --out out -q");
    EXPECT_EQ(r.code, 0) << r.err;
    return json::parse(slurp(dir_ / "out" / "summary.json"));
  }
};

json carter_case() {
  json c = json::parse(slurp(std::filesystem::path(DYNCONTACT_SOURCE_DIR) / "examples" / "carter-2d.json"));
  c["accuracy"] = {{"estimate", false}};
  c["output"] = {{"plots", false}, {"power", true}};
  return c;
}

TEST_F(CliEnergy, SteadyRollingsCreepPowerIsItsDissipationAndTheSchemesShare) {
  // Carter (carter-2d: steel, R = 20 mm, 100 kN/m, F = 0.5 mu P, mu = 0.3) on 100, 200, 400 strips.
  const double E = 2.1e11, nu = 0.3, R = 0.02, P = 1e5, mu = 0.3, F = 0.5 * mu * P, V = 1.0;
  const auto h = dc::hertz::cylinder2d(R, P, E / (2.0 * (1.0 - nu * nu)));
  const double carter = F * (mu * h.a / R) * (1.0 - std::sqrt(1.0 - F / (mu * P))) * V;  // |F| xi V
  double frictional[3] = {}, scheme[3] = {}, creep[3] = {};
  for (int k = 0; k < 3; ++k) {
    json c = carter_case();
    c["grid"]["nx"] = 100 << k;
    const json s = solve(c);
    const json& e = s.at("energy");
    // The bookkeeping: the creep forces' power is the frictional plus the scheme's, to round-off.
    EXPECT_LT(std::abs(e.at("balance").get<double>()), 1e-12) << e.dump();
    frictional[k] = e.at("frictional_power").get<double>();
    scheme[k] = e.at("scheme_power").get<double>();
    creep[k] = e.at("creep_power").get<double>();
    // The creep forces' power is Carter's within the grid's error of the creepage (1 %).
    EXPECT_NEAR(creep[k] / carter, 1.0, 0.015);
    EXPECT_GT(frictional[k], 0.0);
    EXPECT_NEAR(frictional[k], e.at("dissipated").get<double>() * V / (2.4 * h.a / (100 << k)), 1e-9 * frictional[k]);
    // fields.csv's power density integrates to the frictional power.
    std::istringstream rows(slurp(dir_ / "out" / "fields.csv"));
    std::string line;
    std::getline(rows, line);
    EXPECT_EQ(line, "x,y,p,tx,ty,sx,sy,state,power");
    double total = 0.0;
    while (std::getline(rows, line)) total += std::stod(line.substr(line.rfind(',') + 1));
    EXPECT_NEAR(total * 2.4 * h.a / (100 << k), frictional[k], 1e-8 * frictional[k]);
  }
  // The scheme's share of the creep power halves with the element size (first order: 4.1 %, 2.0 %,
  // 1.0 %), so that the dissipation's share extrapolated to h = 0 is 1 within 10^-3.
  double share[3];
  for (int k = 0; k < 3; ++k) share[k] = scheme[k] / creep[k];
  EXPECT_NEAR(share[0] / share[1], 2.0, 0.1);
  EXPECT_NEAR(share[1] / share[2], 2.0, 0.1);
  EXPECT_GT(share[0], 0.02);  // the coarse grid alone is not the continuum
  EXPECT_NEAR(2.0 * frictional[2] / creep[2] - frictional[1] / creep[1], 1.0, 1e-3);
}

TEST_F(CliEnergy, AShiftHistoryDissipatesOnlyWhereItSlipsAndAddsItUp) {
  json c = json::parse(slurp(std::filesystem::path(DYNCONTACT_SOURCE_DIR) / "examples" / "cattaneo-sphere.json"));
  c["accuracy"] = {{"estimate", false}};
  c["output"] = {{"plots", false}, {"power", true}};
  // Q = 0.5 mu P, back to 0, and to -0.5 mu P: every step slips somewhere.
  c["tangential"] = {{"regime", "shift"},
                     {"history", {{{"force", {-15.0, 0.0}}}, {{"force", {0.0, 0.0}}}, {{"force", {15.0, 0.0}}}}}};
  const json s = solve(c);
  double total = 0.0;
  for (const json& step : s.at("steps")) {
    const double w = step.at("energy").at("dissipated").get<double>();
    EXPECT_GT(w, 0.0);
    total += w;
    EXPECT_NEAR(step.at("energy").at("dissipated_total").get<double>(), total, 1e-12 * total);
  }
  EXPECT_NEAR(s.at("energy").at("dissipated_total").get<double>(), total, 1e-12 * total);
  // fields_0.csv: the step's work per area, zero in the stick circle.
  std::istringstream rows(slurp(dir_ / "out" / "fields_0.csv"));
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line, "x,y,p,tx,ty,sx,sy,state,dissipation");
  std::vector<std::pair<int, double>> work;  // state, J/m^2
  double largest = 0.0;
  while (std::getline(rows, line)) {
    work.emplace_back(std::stoi(line.substr(line.rfind(',', line.rfind(',') - 1) + 1)),
                      std::stod(line.substr(line.rfind(',') + 1)));
    largest = std::max(largest, work.back().second);
  }
  // Stick: no slip but the solver's tolerance; slip: -tau . ds = f |ds| >= 0 (Coulomb).
  for (const auto& [state, w] : work) {
    if (state == 1) {
      EXPECT_LT(std::abs(w), 1e-8 * largest);
    }
    EXPECT_GT(w, -1e-8 * largest);
  }
  EXPECT_GT(largest, 0.0);
  // Without output.power: the contract's columns only.
  c["output"]["power"] = false;
  solve(c);
  std::istringstream plain(slurp(dir_ / "out" / "fields.csv"));
  std::getline(plain, line);
  EXPECT_EQ(line, "x,y,p,tx,ty,sx,sy,state");
}

TEST_F(CliEnergy, ARollOverADistanceDissipatesTheCreepForcesWorkOverIt) {
  // cattaneo-carter-2d (100 strips, F = -0.5 mu P): after 2a of rolling its last roll (1a, 42
  // marching steps) is near Carter's steady state, where the creep force's work over the
  // distance, |F| xi D, is dissipated less the upwind scheme's share (4.1 % on 100 strips, the
  // Carter test above): the sum over every marching step, 42 times one step's.
  json c = json::parse(slurp(std::filesystem::path(DYNCONTACT_SOURCE_DIR) / "examples" / "cattaneo-carter-2d.json"));
  c["accuracy"] = {{"estimate", false}};
  c["output"] = {{"plots", false}};
  const json s = solve(c);
  const json& last = s.at("steps").back();
  ASSERT_EQ(last.at("marching_steps").get<int>(), 42);
  const double creep_work = std::abs(last.at("tangential_force")[0].get<double>() * last.at("creepage")[0].get<double>()) *
                            last.at("distance").get<double>();
  const double w = last.at("energy").at("dissipated").get<double>();
  EXPECT_GT(w, 0.93 * creep_work);
  EXPECT_LT(w, creep_work);
}

/// energy.csv's columns, parsed (a header line, then numbers).
std::vector<std::vector<double>> energy_rows(const std::filesystem::path& file) {
  std::istringstream in(slurp(file));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,kinetic,elastic,work,dissipated,numerical_damping");
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    EXPECT_EQ(row.size(), 6u) << line;
    rows.push_back(row);
  }
  return rows;
}

TEST_F(CliEnergy, ADynamicRunWritesItsAuditStepByStepAndSumsItUp) {
  // The bowling ball (16^2, quasi-static normal model, mu = 0.2) sliding at 3 m/s for 50 steps:
  // friction dissipates in every step ((2.4)-(2.5): W_k >= 0), and energy.csv's rows are the
  // audit: work = kinetic - kinetic(0) + elastic + dissipated + numerical damping (to the
  // file's 10 digits); its last row is summary.json's audit, and its first the kinetic energy
  // m v0^2 / 2 at t = 0.
  json c = dc::test::example_json("bowling-ball");
  c["time"]["t_end"] = 0.1;
  c["output"] = {{"plots", false}};
  const json s = solve(c);
  EXPECT_EQ(s.at("files").at("energy"), "energy.csv");
  const json& e = s.at("energy");
  const json& a = e.at("audit");
  const auto rows = energy_rows(dir_ / "out" / "energy.csv");
  ASSERT_EQ(rows.size(), s.at("steps").get<std::size_t>() + 1);
  const double ke0 = 0.5 * 7.0 * 3.0 * 3.0;
  EXPECT_DOUBLE_EQ(rows.front()[0], 0.0);
  EXPECT_NEAR(rows.front()[1], ke0, 1e-9 * ke0);
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const auto& r = rows[k];
    EXPECT_GE(r[4], rows[k - 1][4]) << "dissipation is never negative (step " << k << ")";
    EXPECT_NEAR(r[3], r[1] - ke0 + r[2] + r[4] + r[5], 1e-8 * ke0) << "step " << k;
  }
  const auto& last = rows.back();
  EXPECT_NEAR(last[4], e.at("dissipated").get<double>(), 1e-9 * last[4]);
  EXPECT_NEAR(last[4], a.at("dissipated").get<double>(), 1e-9 * last[4]);
  EXPECT_NEAR(last[1] - ke0, a.at("kinetic_change").get<double>(), 1e-8 * ke0);
  EXPECT_NEAR(last[5], a.at("numerical_damping").get<double>(), 1e-8 * ke0);
  EXPECT_GT(e.at("frictional_power").get<double>(), 0.0);
  EXPECT_GE(e.at("frictional_power").get<double>(), e.at("frictional_power_last").get<double>());
  EXPECT_LT(std::abs(a.at("relative_residual").get<double>()), 0.01);
}

}  // namespace
