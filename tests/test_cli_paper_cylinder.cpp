// `dyncontact solve` / `validate` on the paper's Section 5 cylinder (problem "paper_cylinder"):
// the bundled sweep, the contract's summary and timeseries columns, gross sliding where the
// derived quasi-static limit puts it, the numerical traction (tangential solver) against the
// closed form, and bad inputs naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>
#include <vector>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

class CliPaperCylinder : public CliTest {
 protected:
  /// The bundled example with `edit` applied, no plots; returns the file name.
  std::string case_file(const std::function<void(json&)>& edit = {}) const {
    json doc = json::parse(slurp(fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / "paper-cylinder.json"));
    doc["output"] = {{"plots", false}};
    if (edit) edit(doc);
    return write_case(doc);
  }
  void expect_rejected(const std::function<void(json&)>& edit, const std::string& key) const {
    const std::string file = case_file(edit);
    expect_input_error("validate " + file, key);
    expect_input_error("solve " + file + " --out rejected -q", key);
  }
};

TEST_F(CliPaperCylinder, SweepOfTheMomentRateReachesGrossSlidingWhereTheQuasiStaticLimitSays) {
  const CliResult r = run("solve " + case_file() + " --out pc -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "pc" / "summary.json"));
  EXPECT_EQ(s["problem"], "paper_cylinder");
  ASSERT_EQ(s["runs"].size(), 3u);
  for (const char* key : {"steps", "final", "timeseries"}) EXPECT_TRUE(s.contains(key)) << key;
  // eta = 2, M0_bar = 0.2: F_bar = (2/3)(0.2 + gamma t) reaches 1 at t* = 1.3/gamma; eps = 1e-3
  // and dt = 0.002 put the onset within 0.02 of it.
  const double gammas[] = {0.25, 0.5, 1.0};
  for (std::size_t k = 0; k < 3; ++k) {
    const json& run_k = s["runs"][k];
    EXPECT_EQ(run_k["status"], "completed");
    const double t_star = 1.3 / gammas[k];
    if (t_star < 3.0) {
      ASSERT_TRUE(run_k["sliding_onset_t_bar"].is_number());
      EXPECT_NEAR(run_k["sliding_onset_t_bar"].get<double>(), t_star, 0.02);
      EXPECT_EQ(run_k["final"]["F_bar"].get<double>(), 1.0);
    } else {
      EXPECT_TRUE(run_k["sliding_onset_t_bar"].is_null());
      EXPECT_NEAR(run_k["final"]["F_bar"].get<double>(), run_k["quasi_static_final"]["F_bar"].get<double>(), 1e-3);
      EXPECT_NEAR(run_k["final"]["v_bar"].get<double>(), run_k["quasi_static_final"]["v_bar"].get<double>(), 1e-3);
    }
  }
  std::ifstream ts(dir_ / "pc" / s["runs"][0]["timeseries"].get<std::string>());
  std::string header;
  std::getline(ts, header);
  EXPECT_EQ(header, "t,x,y,z,vx,vy,vz,wx,wy,wz,Fx,Fy,Fz,Mx,My,Mz,creepage,stick_fraction,t_bar,F_bar,l_bar,v_bar");
  int rows = 0;
  for (std::string line; std::getline(ts, line);) ++rows;
  EXPECT_EQ(rows, s["runs"][0]["steps"].get<int>() + 1);
}

TEST_F(CliPaperCylinder, RigidSlipVelocityGoesOnALogAxisOnlyWhenARunSlides) {
  // Gross sliding makes v_bar about 1/epsilon: a linear axis would flatten the creep phase.
  auto v_bar_block = [&](const std::string& out) {
    const std::string gp = slurp(dir_ / out / "plots.gp");
    const auto at = gp.rfind("rigid-slip velocity");
    return at == std::string::npos ? std::string() : gp.substr(gp.rfind("reset", at), gp.find("plot ", at) - gp.rfind("reset", at));
  };
  ASSERT_EQ(run("solve " + case_file([](json& d) { d["output"] = {{"plots", true}}; }) + " --out sliding -q").code, 0);
  EXPECT_NE(v_bar_block("sliding").find("set logscale y"), std::string::npos) << v_bar_block("sliding");
  const std::string creeping = case_file([](json& d) {
    d["output"] = {{"plots", true}};
    d["sweep"] = {{"dimensionless.gamma_bar", {0.1, 0.2}}};
  });
  ASSERT_EQ(run("solve " + creeping + " --out creeping -q").code, 0);
  const std::string block = v_bar_block("creeping");
  ASSERT_FALSE(block.empty());
  EXPECT_EQ(block.find("set logscale y"), std::string::npos) << block;
}

TEST_F(CliPaperCylinder, SweepOverThreadsAndRanksWritesTheSameBytes) {
  // The sweep's runs spread over threads or `mpirun -n 2` ranks (dynamic assignment, gathered in
  // sweep order): the same summary.json and time series as one thread.
  const std::string file = case_file([](json& doc) { doc["dimensionless"]["t_bar_end"] = 1.5; });
  auto files = [&](const std::string& out) {
    std::string all = slurp(dir_ / out / "summary.json");
    for (int k = 0; k < 3; ++k) all += slurp(dir_ / out / ("timeseries_" + std::to_string(k) + ".csv"));
    return all;
  };
  const CliResult serial = run_prefixed("DYNCONTACT_THREADS=1", "solve " + file + " --out serial");
  ASSERT_EQ(serial.code, 0) << serial.err;
  ASSERT_EQ(run_prefixed("DYNCONTACT_THREADS=3", "solve " + file + " --out threads -q").code, 0);
  EXPECT_EQ(files("threads"), files("serial"));
  EXPECT_NE(files("serial").find("timeseries_2.csv"), std::string::npos);
  if (!have_mpirun()) GTEST_SKIP() << "no mpirun here";
  const CliResult mpi = run_mpi2("solve " + file + " --out ranks");
  ASSERT_EQ(mpi.code, 0) << mpi.err;
  EXPECT_EQ(files("ranks"), files("serial"));
  // The runs reported once, by rank 0, in sweep order.
  const std::string lines = mpi.out.substr(0, mpi.out.find("wrote"));
  EXPECT_EQ(lines, serial.out.substr(0, serial.out.find("wrote")));
}

TEST_F(CliPaperCylinder, NumericalTractionMatchesCarterPoritsky) {
  // The creep law tabulated from the tangential solver's steady rolling (200 strips) against
  // the closed form: the final F_bar and v_bar of an unsaturated run within 1e-3.
  auto edit = [](json& d) {
    d.erase("sweep");
    d["dimensionless"]["gamma_bar"] = 0.25;
  };
  const std::string closed = case_file(edit);
  ASSERT_EQ(run("solve " + closed + " --out closed -q").code, 0);
  const std::string numerical = case_file([&](json& d) {
    edit(d);
    d["traction_model"] = "numerical";
  });
  const CliResult r = run("solve " + numerical + " --out numerical -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json a = json::parse(slurp(dir_ / "closed" / "summary.json"));
  const json b = json::parse(slurp(dir_ / "numerical" / "summary.json"));
  EXPECT_EQ(b["traction_model"], "numerical");
  EXPECT_NEAR(b["final"]["F_bar"].get<double>(), a["final"]["F_bar"].get<double>(), 1e-3);
  EXPECT_NEAR(b["final"]["v_bar"].get<double>(), a["final"]["v_bar"].get<double>(), 1e-3);
}

/// Rows of a timeseries.csv (numbers; empty cells as NaN).
std::vector<std::vector<double>> read_rows(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(cell.empty() ? NAN : std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST_F(CliPaperCylinder, DimensionalInputsAreThePapersScalesAndBalanceMomentum) {
  const fs::path example = fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / "paper-cylinder-si.json";
  const json d = json::parse(slurp(example));
  const CliResult r = run("solve " + shell_quote(example.string()) + " --out si -q --set output.plots=false");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "si" / "summary.json"));
  EXPECT_EQ(s["inputs"], "dimensional");
  // The paper's scales from the inputs (Hertz half-width of a steel pair in plane strain).
  const double M = d["body"]["mass"], R = d["body"]["radius"], I = d["body"]["inertia"][1];
  const double P = -d["loads"]["force"]["z"]["value"].get<double>(), mu = d["friction"]["mu"];
  const double M0 = d["loads"]["moment"]["y"]["value"], gamma = d["loads"]["moment"]["y"]["rate"];
  const double V0 = d["body"]["initial"]["velocity"][0], E = 2.1e11, nu = 0.3;
  const double a = std::sqrt(4.0 * P * R * 2.0 * (1.0 - nu * nu) / (std::numbers::pi * E));
  const json& dl = s["run"]["dimensionless"];
  EXPECT_NEAR(dl["epsilon"].get<double>(), a / R, 1e-12 * a / R);
  EXPECT_NEAR(dl["eta"].get<double>(), M * R * R / I, 1e-12);
  EXPECT_NEAR(dl["gamma_bar"].get<double>(), gamma * M * V0 / (mu * P * mu * P * R), 1e-12);
  EXPECT_NEAR(dl["M0_bar"].get<double>(), M0 / (mu * P * R), 1e-12);
  // The same run from those dimensionless inputs gives the same dimensionless history.
  const std::string twin = case_file([&](json& c) {
    c.erase("sweep");
    c["dimensionless"] = {{"gamma_bar", dl["gamma_bar"]}, {"M0_bar", dl["M0_bar"]}, {"eta", dl["eta"]},
                          {"epsilon", dl["epsilon"]}, {"mu", dl["mu"]}, {"v_bar0", 0.0}, {"t_bar_end", dl["t_bar_end"]}};
    c["time"] = {{"dt", s["run"]["dt_bar"]}, {"scheme", "bdf1"}};
  });
  ASSERT_EQ(run("solve " + twin + " --out twin -q").code, 0);
  const json t = json::parse(slurp(dir_ / "twin" / "summary.json"));
  for (const char* k : {"F_bar", "l_bar", "v_bar"})
    EXPECT_NEAR(s["final"][k].get<double>(), t["final"][k].get<double>(), 1e-9 * (1.0 + t["final"][k].get<double>())) << k;
  // BDF1 steps (5.7)-(5.8) with the end-of-step wrench: M dV = dt F_x and I dOmega = dt (M_y +
  // M_ex) summed over the steps hold to the Newton tolerance.
  const auto rows = read_rows(dir_ / "si" / "timeseries.csv");
  ASSERT_GT(rows.size(), 100u);
  double impulse = 0.0, angular = 0.0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const double dt = rows[k][0] - rows[k - 1][0];
    impulse += dt * rows[k][10];
    angular += dt * (rows[k][14] + M0 + gamma * rows[k][0]);
  }
  EXPECT_NEAR(M * (rows.back()[4] - rows.front()[4]), impulse, 1e-8 * std::abs(impulse));
  EXPECT_NEAR(I * (rows.back()[8] - rows.front()[8]), angular, 1e-8 * std::abs(angular));
  EXPECT_NEAR(s["final"]["time"].get<double>(), d["time"]["t_end"].get<double>(), d["time"]["dt"].get<double>());
}

TEST_F(CliPaperCylinder, BadInputsNameTheKey) {
  expect_rejected([](json& d) { d["dimensionless"]["gama_bar"] = 0.5; }, "dimensionless.gama_bar");
  expect_rejected([](json& d) { d["dimensionless"]["eta"] = -1.0; }, "dimensionless.eta");
  expect_rejected([](json& d) { d["dimensionless"]["epsilon"] = 0.0; }, "dimensionless.epsilon");
  expect_rejected([](json& d) { d.erase("dimensionless"); }, "dimensionless");
  expect_rejected([](json& d) { d["time"]["scheme"] = "rk4"; }, "time.scheme");
  expect_rejected([](json& d) { d["time"]["dt"] = -0.1; }, "time.dt");
  expect_rejected([](json& d) { d["sweep"] = {{"loads.moment", {1, 2}}}; }, "sweep.loads.moment");
  expect_rejected([](json& d) { d["sweep"] = {{"dimensionless.eta", {1, -2}}}; }, "dimensionless.eta");
  auto si = [](const std::function<void(json&)>& edit) {
    return [edit](json& d) {
      d = json::parse(slurp(fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / "paper-cylinder-si.json"));
      d["output"] = {{"plots", false}};
      edit(d);
    };
  };
  expect_rejected(si([](json& d) { d["body"]["mass"] = -1.0; }), "body.mass");
  expect_rejected(si([](json& d) { d["body"]["initial"]["velocity"] = {0, 0, 0}; }), "body.initial.velocity[0]");
  expect_rejected(si([](json& d) { d["loads"]["force"]["z"]["value"] = 100.0; }), "loads.force.z.value");
  expect_rejected(si([](json& d) { d["loads"]["force"]["z"]["rate"] = 1.0; }), "loads.force.z.rate");
  expect_rejected(si([](json& d) { d["time"].erase("t_end"); }), "time.t_end");
  expect_rejected(si([](json& d) { d.erase("friction"); }), "friction");
}

}  // namespace
}  // namespace dc::test
