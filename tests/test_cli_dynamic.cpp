// `dyncontact solve` / `validate` on problem "dynamic": the files and summary keys of the
// contract, bad keys named with exit 2, and a run that cannot converge stopping cleanly with
// exit 3 and the time series so far.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

class CliDynamic : public CliTest {
 protected:
  /// The ball-impact example, coarse and short, with `edit` applied; returns the file name.
  std::string case_file(const std::function<void(json&)>& edit = {}) const {
    json doc = coarse_ball_impact();
    if (edit) edit(doc);
    return write_case(doc);
  }
  void expect_rejected(const std::function<void(json&)>& edit, const std::string& key) const {
    const std::string file = case_file(edit);
    expect_input_error("validate " + file, key);
    expect_input_error("solve " + file + " --out rejected -q", key);
  }
};

TEST_F(CliDynamic, WritesSummaryAndTimeseries) {
  const CliResult r = run("solve " + case_file() + " --out out -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(s["problem"], "dynamic");
  EXPECT_EQ(s["status"], "completed");
  EXPECT_EQ(s["steps"], 40);
  EXPECT_EQ(s["timeseries"], "timeseries.csv");
  for (const char* k : {"time", "position", "velocity", "omega"}) EXPECT_TRUE(s["final"].contains(k)) << k;
  EXPECT_EQ(s["models"]["normal_model"], "dynamic");
  EXPECT_GT(s["final"]["velocity"][2].get<double>(), 0.0);  // rebounded
  EXPECT_LE(s["solver"]["certificate"]["worst"].get<double>(), 1e-6);
  std::istringstream csv(slurp(dir_ / "out" / "timeseries.csv"));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("t,x,y,z,vx,vy,vz,wx,wy,wz,Fx,Fy,Fz,Mx,My,Mz,creepage,stick_fraction", 0), 0u) << header;
  // Each step's work: the columns contact_solves and alternations add up to the run's counts.
  std::vector<std::string> columns;
  std::string heading;
  for (std::istringstream h(header); std::getline(h, heading, ',');) columns.push_back(heading);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  const std::size_t solves_column = column("contact_solves"), alternations_column = column("alternations");
  ASSERT_LT(solves_column, columns.size()) << header;
  ASSERT_LT(alternations_column, columns.size()) << header;
  ASSERT_EQ(s["rejected_steps"], 0) << "every solve belongs to an accepted step";
  int rows = 0;
  long solves = 0, alternations = 0;
  while (std::getline(csv, line)) {
    ++rows;
    std::vector<std::string> cells;
    std::string cell;
    for (std::istringstream c(line); std::getline(c, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), columns.size()) << line;
    solves += std::stol(cells[solves_column]);
    alternations += std::stol(cells[alternations_column]);
  }
  EXPECT_EQ(rows, 40);
  EXPECT_EQ(solves, s["solver"]["contact_solves"].get<long>());
  EXPECT_EQ(alternations, s["solver"]["outer_iterations"].get<long>());
  EXPECT_GT(solves, 0);
}

TEST_F(CliDynamic, SnapshotsEveryKSteps) {
  const CliResult r = run("solve " + case_file([](json& d) { d["output"]["snapshot_every"] = 10; }) + " --out out -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  ASSERT_EQ(s["files"]["snapshots"].size(), 4u);
  EXPECT_EQ(s["files"]["snapshots"][1]["file"], "fields_20.csv");
  const std::string f = slurp(dir_ / "out" / "fields_20.csv");
  EXPECT_EQ(f.rfind("x,y,p,tx,ty,sx,sy,state", 0), 0u) << f.substr(0, 80);
}

TEST_F(CliDynamic, BadInputIsNamed) {
  expect_rejected([](json& d) { d["body"]["mass"] = -1.0; }, "body.mass");
  expect_rejected([](json& d) { d["body"]["spin"] = 1.0; }, "body.spin");
  expect_rejected([](json& d) { d["time"]["scheme"] = "rk4"; }, "time.scheme");
  expect_rejected([](json& d) { d["contact_model"] = "fast"; }, "contact_model");
  expect_rejected([](json& d) { d["normal"] = {{"force", 10.0}}; }, "normal");
  expect_rejected([](json& d) { d["loads"] = {{"force", {{"w", {{"value", 1.0}}}}}}; }, "loads.force.w");
  expect_rejected([](json& d) { d.erase("time"); }, "time");
  expect_rejected([](json& d) { d["normal_model"] = "quasi_static"; }, "loads.force.z");
  expect_rejected([](json& d) { d["output"] = {{"snapshot_every", -1}}; }, "output.snapshot_every");
}

TEST_F(CliDynamic, UnconvergedStepStopsWithPartialResults) {
  // One iteration of the contact solver cannot certify a contact: the run stops at the first
  // step in contact with the time series so far and exit 3.
  const CliResult r = run("solve " + case_file([](json& d) {
                            d["body"]["initial"]["position"] = {0, 0, 0.01 + 5e-6};
                            d["solver"] = {{"max_iter", 1}, {"fallback", false}};
                          }) + " --out out -q");
  EXPECT_EQ(r.code, 3) << r.err;
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(s["status"], "stopped");
  EXPECT_NE(s["message"].get<std::string>().find("contact solve"), std::string::npos) << s["message"];
  EXPECT_GT(s["steps"].get<int>(), 0);  // the free flight before the contact
  EXPECT_TRUE(fs::exists(dir_ / "out" / "timeseries.csv"));
}

TEST_F(CliDynamic, UnconvergedPressedInStartStopsBeforeTheFirstStep) {
  // A ball started 5 um inside (a fifth of the impact's approach): the contact at t = 0 gives the
  // stored energy and the first step's force. One solver iteration cannot certify it, so the run
  // stops at t = 0 with exit 3 rather than audit its energy from an unconverged solve.
  const CliResult r = run("solve " + case_file([](json& d) {
                            d["body"]["initial"]["position"] = {0, 0, 0.01 - 5e-6};
                            d["solver"] = {{"max_iter", 1}, {"fallback", false}};
                          }) + " --out out -q");
  EXPECT_EQ(r.code, 3) << r.err;
  const json s = json::parse(slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(s["status"], "stopped");
  const std::string message = s["message"].get<std::string>();
  EXPECT_NE(message.find("t = 0 s"), std::string::npos) << message;
  EXPECT_NE(message.find("pressed into the half-space"), std::string::npos) << message;
  EXPECT_EQ(s["steps"].get<int>(), 0);
  EXPECT_GT(s["solver"]["certificate"]["worst"].get<double>(), 1e-6) << "the t = 0 solve's certificate";
}

}  // namespace
}  // namespace dc::test
