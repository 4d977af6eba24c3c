// The command line on hostile and known-wrong inputs: every one a clear error (exit 2 naming
// the key) or a result with words, never a crash, never a silent wrong answer.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using Result = dc::test::CliResult;
using dc::test::slurp;
using dc::test::shell_quote;
using dc::test::example_json;

class CliInputHoles : public dc::test::CliTest {
 protected:
  std::string write(const std::string& text, const std::string& name = "case.json") const {
    std::ofstream(dir_ / name) << text;
    return name;
  }
  /// `args` exits 2 and stderr has "error: KEY" and `words`.
  void expect_error(const std::string& args, const std::string& key, const std::string& words = "") const {
    SCOPED_TRACE(args.substr(0, 200));
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("error: " + key), std::string::npos) << r.err.substr(0, 400);
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err.substr(0, 400);
  }
};

TEST_F(CliInputHoles, DeepNestingIsExit2NamingThePlace) {
  const std::string deep = std::string(1000000, '[') + std::string(1000000, ']');
  json doc = example_json("hertz-sphere");
  std::string text = doc.dump();
  text.insert(text.size() - 1, ", \"junk\": " + deep);
  const std::string file = write(text);
  expect_error("validate " + file, "junk[0][0]", "nested more than 64");
  expect_error("solve " + file, "junk[0][0]", "nested more than 64");
  expect_error("validate " + shell_quote(dc::test::example_path("hertz-sphere")) +
                   " --set " + shell_quote("grid.x=" + std::string(5000, '[') + std::string(5000, ']')),
               "grid.x[0]", "nested");
}

// Keys whose value is kept as given (description, sweep values) and --set values are bounded
// the same way, before any tree is built.
TEST_F(CliInputHoles, DeepOrHugeValuesAnywhereAreExit2) {
  const std::string deep = std::string(1000000, '[') + std::string(1000000, ']');
  std::string text = example_json("paper-cylinder").dump();
  text.replace(text.find("\"description\":"), 14, "\"description\": " + deep + ", \"x\":");
  expect_error("validate " + write(text), "description[0]", "nested more than 64");
  const std::string sweep = write(example_json("paper-cylinder").dump(), "sweep.json");
  const std::string deep_arg = std::string(20000, '[') + std::string(20000, ']');  // one argument < 128 KiB
  expect_error("solve " + sweep + " --set " + shell_quote("sweep.dimensionless.gamma_bar=" + deep_arg),
               "sweep.dimensionless.gamma_bar[0]", "nested");
  expect_error("validate " + sweep + " --set " + shell_quote("description=" + deep_arg), "description[0]", "nested");
  const std::string c = write(example_json("cattaneo-sphere").dump(), "c.json");
  expect_error("validate " + c + " --set normal.force=1e999", "normal.force", "1e999");
  expect_error("solve " + c + " --set " + shell_quote(R"(tangential.force=[-1e999, 0])"), "tangential.force[0]", "1e999");
}

TEST_F(CliInputHoles, OutOfRangeNumbersAndDuplicateKeysNameTheKey) {
  std::string text = example_json("hertz-sphere").dump(2);
  const std::string file = write(text.replace(text.find("\"force\": 100.0"), 14, "\"force\": 1e999"));
  expect_error("validate " + file, "normal.force", "1e999");
  expect_error("solve " + file, "normal.force", "1e999");
  std::string dup = example_json("hertz-sphere").dump(2);
  dup.replace(dup.find("\"nx\": 64"), 8, "\"nx\": 64, \"nx\": 16");
  expect_error("validate " + write(dup, "dup.json"), "grid.nx", "duplicate key");
}

TEST_F(CliInputHoles, CommandLineMistakesAreSaid) {
  Result r = run("frobnicate");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown subcommand 'frobnicate'"), std::string::npos) << r.err;
  const std::string file = write(example_json("hertz-sphere").dump());
  r = run("solve " + file + " --out ''");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(CliInputHoles, ValidateRejectsWhatSolveRejects) {
  json c = example_json("cattaneo-sphere");
  auto bad = [&](const std::string& set, const std::string& key) {
    expect_error("validate " + write(c.dump()) + " --set " + shell_quote(set), key);
  };
  bad("tangential.regime=skid", "tangential.regime");
  bad(R"(tangential={"regime": "rolling", "creepage": [0, 0], "velocity": 0})", "tangential.velocity");
  bad("tangential.history=[]", "tangential.history");
  bad("tangential.history=\"x\"", "tangential.history");
  bad(R"(tangential.history=[{"forse": [1, 0]}])", "tangential.history[0].forse");
  bad("tangential.force=[1]", "tangential.force");
  bad("tangential.force=[1, 2, 3]", "tangential.force");
  // Blocks the problem does not use.
  const std::string normal = write(example_json("hertz-sphere").dump(), "normal.json");
  expect_error("validate " + normal + " --set " + shell_quote(R"(friction={"law": "coulomb", "mu": 0.3})"), "friction",
               "not used by problem 'normal'");
  expect_error("solve " + normal + " --set " + shell_quote(R"(sweep={"normal.force": [1, 2]})"), "sweep", "not used");
}

TEST_F(CliInputHoles, KnownWrongResultsAreNotSuccesses) {
  const std::string file = write(example_json("hertz-sphere").dump());
  const std::string small_grid = shell_quote(R"(grid={"nx":32,"ny":32,"x":[-1e-4,1e-4],"y":[-1e-4,1e-4]})");
  // Truncated by the grid's edge: exit 2 naming grid, the share of the edge in the summary.
  expect_error("solve " + file + " -q --out edge --set " + small_grid, "grid", "edge of the grid");
  const json s = json::parse(slurp(dir_ / "edge" / "summary.json"));
  EXPECT_GT(s["contact_edge_fraction"].get<double>(), 0.9);  // the Hertz contact covers the whole square
  EXPECT_FALSE(s["limits"][0]["accepted"].get<bool>());
  expect_error("validate " + file + " --set " + small_grid, "grid", "beyond the grid");
  // Accepted by the case: exit 0 with a warning, the limit recorded as accepted.
  Result r = run("solve " + file + " -q --out accepted --set " + small_grid + " --set grid.allow_edge_contact=true");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: grid"), std::string::npos) << r.err;
  EXPECT_TRUE(json::parse(slurp(dir_ / "accepted" / "summary.json"))["limits"][0]["accepted"].get<bool>());
  // compare judges the same limits.
  expect_error("compare " + file + " -q --backends native --out cmp --set " + small_grid, "grid", "edge of the grid");
  EXPECT_FALSE(json::parse(slurp(dir_ / "cmp" / "compare.json"))[0]["summary"]["limits"][0]["accepted"].get<bool>());
  // A 1 x 1 grid cannot resolve a pressure distribution.
  expect_error("solve " + file + " --set grid.nx=1 --set grid.ny=1", "grid.nx", "one element");
  // E = 1e3 Pa: the contact is ~11 times the sphere's radius (a/R in the message).
  const std::string soft = " --set materials.body.E=1e3 --set materials.base.E=1e3";
  expect_error("solve " + file + " -q --out soft --set grid.nx=16 --set grid.ny=16" + soft, "materials", "a/R = 1");
  expect_error("validate " + file + soft, "materials", "a/R = 1");
  r = run("solve " + file + " -q --out soft-ok --set grid.nx=16 --set grid.ny=16 --set materials.allow_large_strain=true" +
          soft);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: materials"), std::string::npos) << r.err;
}

// time_s is the whole solve: every marching step of a steady rolling by time marching (Ipopt
// marches), not the last step's solve.
TEST_F(CliInputHoles, TimeCountsTheWholeSolve) {
  const std::string file = write(example_json("carter-2d").dump());
  const auto start = std::chrono::steady_clock::now();
  const Result r = run("solve " + file + " -q --out carter --backend ipopt --set grid.nx=20");
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "carter" / "summary.json"));
  ASSERT_GT(s["marching_steps"].get<int>(), 10);
  EXPECT_GT(s["solver"]["time_s"].get<double>(), 0.5 * wall) << "wall " << wall;
  EXPECT_LE(s["solver"]["time_s"].get<double>(), wall);
}

TEST_F(CliInputHoles, CompareSaysWhyPaperCylinderHasNoBackends) {
  const Result r = run("compare " + shell_quote(dc::test::example_path("paper-cylinder")) +
                       " --backends ipopt,native --out cmp");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no contact backend to compare"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("not implemented"), std::string::npos) << r.err;
}

TEST_F(CliInputHoles, OutputFolderCheckedBeforeSolvingAndOwned) {
  json doc = example_json("hertz-sphere");
  doc["grid"]["nx"] = 16;
  doc["grid"]["ny"] = 16;
  const std::string file = write(doc.dump());
  // Not writable (even for root: /proc takes no files): said before solving, naming the folder.
  Result r = run("solve " + file + " --out /proc");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("error: --out: cannot write into the output folder '/proc'"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("converged"), std::string::npos) << r.out;
  if (geteuid() != 0) {
    fs::create_directories(dir_ / "locked");
    fs::permissions(dir_ / "locked", fs::perms::owner_read | fs::perms::owner_exec);
    r = run("solve " + file + " --out locked");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("locked"), std::string::npos) << r.err;
    fs::permissions(dir_ / "locked", fs::perms::owner_all);
  }
  // Results of an earlier run go; other files stay.
  fs::create_directories(dir_ / "res");
  for (const char* name : {"fields_3.csv", "timeseries_12.csv", "pressure_x.svg", "summary.json", "notes.txt",
                           "fields_old.csv"})
    std::ofstream(dir_ / "res" / name) << "old\n";
  r = run("solve " + file + " -q --out res");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "res" / "fields_3.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "res" / "timeseries_12.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "res" / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir_ / "res" / "fields_old.csv"));
  EXPECT_NE(slurp(dir_ / "res" / "summary.json"), "old\n");
  if (fs::exists(dir_ / "res" / "pressure_x.svg")) {
    EXPECT_NE(slurp(dir_ / "res" / "pressure_x.svg"), "old\n");
  }
}

}  // namespace
