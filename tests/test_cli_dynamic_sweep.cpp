// `dyncontact solve` of a dynamic case with a `sweep`: one run per value, spread over threads or
// mpirun ranks with the same bytes, each run the same as the case run alone with that value,
// summary.json with the runs and each run's energy_<k>.csv; checked on Hertz impacts at two drop speeds (peak force grows as
// v^(6/5), Johnson 11.4). Bad sweep values name their key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {
namespace {

using nlohmann::json;

/// The largest value of column `name` of a time series CSV text.
double column_max(const std::string& csv, const std::string& name) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::size_t column = 0;
  {
    std::istringstream header(line);
    std::string cell;
    for (std::size_t k = 0; std::getline(header, cell, ','); ++k)
      if (cell == name) column = k + 1;
  }
  EXPECT_GT(column, 0u) << name;
  double best = -HUGE_VAL;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    for (std::size_t k = 0; k < column && std::getline(row, cell, ','); ++k) {
    }
    best = std::max(best, std::atof(cell.c_str()));
  }
  return best;
}

class CliDynamicSweep : public CliTest {
 protected:
  /// The ball-impact example, coarse, with the drop speed swept (or set to `v` alone).
  std::string case_file(const std::string& name, double v = 0.0) const {
    json doc = example_json("ball-impact");
    doc["grid"]["nx"] = doc["grid"]["ny"] = 16;
    doc["time"]["dt"] = 1e-6;
    doc["output"] = {{"plots", false}};
    if (v > 0.0)
      doc["body"]["initial"]["velocity"] = {0.0, 0.0, -v};
    else
      doc["sweep"] = {{"body.initial.velocity", {{0.0, 0.0, -0.5}, {0.0, 0.0, -1.0}}}};
    return write_case(doc, name);
  }
};

TEST_F(CliDynamicSweep, RunsAreTheCaseAloneAndHertzPeaksScaleAsVToTheSixFifths) {
  const std::string sweep = case_file("sweep.json");
  const CliResult r = run_prefixed("DYNCONTACT_THREADS=2", "solve " + sweep + " --out sweep -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "sweep" / "summary.json"));
  EXPECT_EQ(s["status"], "completed");
  EXPECT_EQ(s["sweep"]["key"], "body.initial.velocity");
  ASSERT_EQ(s["runs"].size(), 2u);
  const double speeds[] = {0.5, 1.0};
  std::string series[2];
  for (int k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    const json& run = s["runs"][k];
    EXPECT_EQ(run["status"], "completed");
    EXPECT_EQ(run["label"], "body.initial.velocity = [0.0,0.0," + json(-speeds[k]).dump() + "]");
    series[k] = slurp(dir_ / "sweep" / run["timeseries"].get<std::string>());
    // The same bytes as the case run alone at that speed.
    const std::string alone = case_file("alone.json", speeds[k]);
    ASSERT_EQ(run_prefixed("DYNCONTACT_THREADS=1", "solve " + alone + " --out alone -q").code, 0);
    EXPECT_EQ(series[k], slurp(dir_ / "alone" / "timeseries.csv"));
    // Its energy audit, the run alone's (frictionless: nothing dissipated).
    const json alone_summary = json::parse(slurp(dir_ / "alone" / "summary.json"));
    EXPECT_EQ(run["energy"], alone_summary["energy"]);
    EXPECT_EQ(run["energy"]["dissipated"], 0.0);
    // Its energy.csv too: the same bytes as the run alone's, named in files.energy beside its series.
    const std::string energy = s["files"]["energy"][k].get<std::string>();
    EXPECT_EQ(energy, "energy_" + std::to_string(k) + ".csv");
    EXPECT_EQ(slurp(dir_ / "sweep" / energy), slurp(dir_ / "alone" / "energy.csv"));
  }
  // Hertz impact: F_max proportional to v^(6/5) (the same ball and materials); 16^2 elements
  // and 1 us steps resolve the peak to about 1 %.
  const double ratio = column_max(series[1], "Fz") / column_max(series[0], "Fz");
  EXPECT_NEAR(ratio, std::pow(2.0, 1.2), 0.03 * std::pow(2.0, 1.2));
}

TEST_F(CliDynamicSweep, ThreadsAndRanksWriteTheSameSeries) {
  const std::string sweep = case_file("sweep.json");
  ASSERT_EQ(run_prefixed("DYNCONTACT_THREADS=1", "solve " + sweep + " --out one -q").code, 0);
  ASSERT_EQ(run_prefixed("DYNCONTACT_THREADS=2", "solve " + sweep + " --out two -q").code, 0);
  for (const char* f : {"timeseries_0.csv", "timeseries_1.csv"})
    EXPECT_EQ(slurp(dir_ / "one" / f), slurp(dir_ / "two" / f)) << f;
  if (!have_mpirun()) GTEST_SKIP() << "no mpirun here";
  const CliResult mpi = run_mpi2("solve " + sweep + " --out ranks -q");
  ASSERT_EQ(mpi.code, 0) << mpi.err;
  for (const char* f : {"timeseries_0.csv", "timeseries_1.csv"})
    EXPECT_EQ(slurp(dir_ / "ranks" / f), slurp(dir_ / "one" / f)) << f;
}

TEST_F(CliDynamicSweep, BadSweepsNameTheKey) {
  json doc = example_json("ball-impact");
  doc["sweep"] = {{"body.mass", {0.03, -1.0}}};
  write_case(doc, "negative.json");
  expect_input_error("validate negative.json", "body.mass");
  expect_input_error("solve negative.json --out x", "body.mass");
  doc["sweep"] = {{"body.mass", json::array()}};
  write_case(doc, "empty.json");
  expect_input_error("solve empty.json --out x", "sweep.body.mass");
  doc["sweep"] = {{"body.mass", {0.03}}, {"time.dt", {1e-6}}};
  write_case(doc, "two.json");
  expect_input_error("solve two.json --out x", "sweep");
}

}  // namespace
}  // namespace dc::test
