// The dyncontact command line, run as a program: exit codes, error messages naming the key,
// example/validate output, and solve writing summary.json with the contract keys.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

using dc::test::slurp;
using Result = dc::test::CliResult;
using dc::test::shell_quote;

class Cli : public dc::test::CliTest {
 protected:
  /// Writes the hertz-sphere example with `edit` applied and returns its file name.
  std::string case_file(const std::function<void(json&)>& edit, const std::string& name = "case.json") const {
    json doc = json::parse(slurp(fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / "hertz-sphere.json"));
    doc["grid"]["nx"] = 16;
    doc["grid"]["ny"] = 16;
    edit(doc);
    return write_case(doc, name);
  }

  /// The case with `edit` must be rejected with exit code 2 and a message naming `key`.
  void expect_rejected(const std::function<void(json&)>& edit, const std::string& key,
                       const std::string& command = "solve") const {
    expect_input_error(command + " " + case_file(edit), key);
    EXPECT_FALSE(fs::exists(dir_ / "out" / "hertz-sphere" / "summary.json"));
  }
};

TEST_F(Cli, HelpAndVersion) {
  Result r = run("--help");
  EXPECT_EQ(r.code, 0);
  for (const char* sub : {"solve", "compare", "validate", "example"}) EXPECT_NE(r.out.find(sub), std::string::npos);
  for (const char* sub : {"solve", "compare", "validate", "example"}) {
    r = run(std::string(sub) + " --help");
    EXPECT_EQ(r.code, 0) << sub;
    EXPECT_GT(r.out.size(), 300u) << sub;  // a paragraph, not just the usage line
  }
  r = run("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("dyncontact"), std::string::npos);
  r = run("");
  EXPECT_EQ(r.code, 2);  // a subcommand is required
  r = run("frobnicate");
  EXPECT_EQ(r.code, 2);
}

TEST_F(Cli, ExamplesMatchTheFilesAndValidate) {
  Result r = run("example --list");
  EXPECT_EQ(r.code, 0);
  for (const char* name : {"hertz-sphere", "hertz-cylinder-2d", "flat-punch", "hertz-ellipse"}) {
    SCOPED_TRACE(name);
    EXPECT_NE(r.out.find(name), std::string::npos);
    const Result e = run(std::string("example ") + name);
    EXPECT_EQ(e.code, 0);
    EXPECT_EQ(e.out, slurp(fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / (std::string(name) + ".json")));
    const std::string file = std::string(name) + ".json";
    std::ofstream(dir_ / file) << e.out;
    const Result v = run("validate " + file);
    EXPECT_EQ(v.code, 0) << v.err;
    EXPECT_NE(v.out.find("valid"), std::string::npos);
    EXPECT_NE(v.out.find("grid:"), std::string::npos);
  }
  r = run("example no-such-example");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: example:"), std::string::npos) << r.err;
}

TEST_F(Cli, EveryExampleFileIsBundledAndValid) {
  const Result list = run("example --list");
  ASSERT_EQ(list.code, 0);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(DYNCONTACT_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(name);
    EXPECT_NE(list.out.find(name + " "), std::string::npos) << "not in `example --list`";
    const Result e = run("example " + name);
    ASSERT_EQ(e.code, 0) << e.err;
    EXPECT_EQ(e.out, slurp(entry.path()));
    const Result v = run("validate " + shell_quote(entry.path().string()));
    EXPECT_EQ(v.code, 0) << v.err;
  }
  EXPECT_GE(files, 12);
}

TEST_F(Cli, ValidateDescribesTheCase) {
  const Result r = run("validate " + case_file([](json&) {}));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("16 x 16 = 256 elements"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Hertz"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("a = 0.0001866"), std::string::npos) << r.out;
}

TEST_F(Cli, BadInputsExitWithCode2AndNameTheKey) {
  expect_rejected([](json& d) { d["materials"]["body"]["E"] = -2.1e11; }, "materials.body.E");
  expect_rejected([](json& d) { d["materials"]["base"]["nu"] = 0.5; }, "materials.base.nu");
  expect_rejected([](json& d) { d["friction"] = {{"law", "coulomb"}, {"mu", -0.2}}; }, "friction.mu");
  expect_rejected([](json& d) { d["grid"]["nx"] = 0; }, "grid.nx");
  expect_rejected([](json& d) { d["materials"]["body"]["Ex"] = 1; }, "materials.body.Ex");
  expect_rejected([](json& d) { d["profile"]["type"] = "cone"; }, "profile.type");
  expect_rejected([](json& d) { d["problem"] = "whatever"; }, "problem");
  expect_rejected([](json& d) { d["grid"]["nx"] = 0; }, "grid.nx", "validate");
  const Result mu = run("solve " + case_file([](json& d) { d["friction"] = {{"law", "coulomb"}, {"mu", -0.2}}; }));
  EXPECT_NE(mu.err.find("mu must be non-negative"), std::string::npos) << mu.err;
}

TEST_F(Cli, ContactOutsideTheGridIsAClearError) {
  const auto edit = [](json& d) {
    d["grid"].erase("extent");
    d["grid"]["x"] = {5e-3, 6e-3};
    d["grid"]["y"] = {-5e-4, 5e-4};
  };
  for (const char* command : {"solve", "validate"}) {
    const Result r = run(std::string(command) + " " + case_file(edit));
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("error: grid: the contact point lies outside the grid"), std::string::npos) << r.err;
  }
}

TEST_F(Cli, MalformedJsonAndMissingFile) {
  std::ofstream(dir_ / "broken.json") << "{\n  \"name\": \"x\",\n  \"problem\": \"normal\"\n  \"dimension\": 3\n}\n";
  Result r = run("solve broken.json");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: broken.json: malformed JSON at line 4"), std::string::npos) << r.err;
  r = run("solve does-not-exist.json");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: does-not-exist.json: cannot open"), std::string::npos) << r.err;
  r = run("validate does-not-exist.json");
  EXPECT_EQ(r.code, 2);
}

TEST_F(Cli, OverridesOnTheCommandLine) {
  const std::string file = case_file([](json&) {});
  Result r = run("validate " + file + " --set grid.nx=8 --set materials.body.E=-1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: materials.body.E:"), std::string::npos) << r.err;
  r = run("validate --set grid.nx=8 " + file);  // --set takes exactly one value
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("8 x 16"), std::string::npos) << r.out;
  r = run("validate " + file + " --set grid.nx");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: --set:"), std::string::npos) << r.err;
  r = run("solve " + file + " --backend simplex");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: solver.backend:"), std::string::npos) << r.err;
}

TEST_F(Cli, StaticCaseTurnedDynamicNamesWhatItLacks) {
  // A dynamic case needs a body and takes no normal block (the body's motion loads the contact).
  Result r = run("solve " + case_file([](json& d) {
                   d["problem"] = "dynamic";
                   d["time"] = {{"dt", 1e-4}, {"t_end", 1e-3}};
                 }));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: body: missing required key"), std::string::npos) << r.err;
  r = run("solve " + case_file([](json& d) {
        d["problem"] = "dynamic";
        d["time"] = {{"dt", 1e-4}, {"t_end", 1e-3}};
        d["body"] = {{"mass", 0.03}, {"inertia", 1e-6}};
      }));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: normal: not used by problem 'dynamic'"), std::string::npos) << r.err;
}

TEST_F(Cli, SolveHertzSphereWritesTheContractFiles) {
  const std::string file = case_file([](json& d) { d["grid"]["nx"] = 24; d["grid"]["ny"] = 24; });
  const Result r = run("solve " + file + " --out result");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const fs::path out = dir_ / "result";
  ASSERT_TRUE(fs::exists(out / "summary.json")) << r.err;
  const json s = json::parse(slurp(out / "summary.json"));
  for (const char* key : {"schema", "name", "problem", "dimension", "solver", "normal_force", "approach",
                          "contact_area", "max_pressure", "n_contact"})
    EXPECT_TRUE(s.contains(key)) << key;
  for (const char* key : {"backend", "status", "iterations", "time_s", "objective", "fallback_used", "certificate"})
    EXPECT_TRUE(s["solver"].contains(key)) << key;
  EXPECT_TRUE(s["solver"]["certificate"].contains("complementarity"));
  EXPECT_EQ(s["name"], "hertz-sphere");
  EXPECT_EQ(s["problem"], "normal");
  EXPECT_EQ(s["dimension"], 3);
  EXPECT_EQ(s["solver"]["status"], "converged");
  EXPECT_NEAR(s["normal_force"].get<double>(), 100.0, 1e-3);
  EXPECT_GT(s["n_contact"].get<int>(), 0);
  // against Hertz on a coarse 24 x 24 grid
  const double a = 1.866255578e-4, p0 = 1.370879e9;
  EXPECT_NEAR(s["max_pressure"].get<double>(), p0, 0.05 * p0);
  EXPECT_NEAR(s["contact_area"].get<double>(), 3.14159265 * a * a, 0.1 * 3.14159265 * a * a);
  EXPECT_TRUE(s.contains("hertz"));

  // fields.csv: header and one row per element
  std::ifstream fields(out / "fields.csv");
  std::string header;
  std::getline(fields, header);
  EXPECT_EQ(header, "x,y,p,tx,ty,sx,sy,state");
  int rows = 0;
  for (std::string line; std::getline(fields, line);) ++rows;
  EXPECT_EQ(rows, 24 * 24);
  EXPECT_TRUE(fs::exists(out / "plots.gp"));
}

TEST_F(Cli, MapOfAFineGridIsSampledAndFieldsKeepEveryElement) {
  // 300 x 300 elements: the map images are drawn from every 2nd element (150 x 150, a regular
  // grid for gnuplot's image), fields.csv keeps all 90 000.
  const std::string file = case_file([](json& d) { d["grid"]["nx"] = 300; d["grid"]["ny"] = 300; });
  const Result r = run("solve " + file + " --out result -q");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  std::ifstream map(dir_ / "result" / "map.dat");
  std::vector<double> xs;
  int points = 0;
  double y_first = 0.0;
  for (std::string line; std::getline(map, line);) {
    if (line.empty() || line[0] == '#') continue;
    double x = 0.0, y = 0.0;
    std::istringstream(line) >> x >> y;
    if (points == 0) y_first = y;
    if (y == y_first) xs.push_back(x);
    ++points;
  }
  EXPECT_EQ(points, 150 * 150);
  ASSERT_EQ(xs.size(), 150u);
  // Regular to the 9 digits map.dat prints (a skipped element would double a step).
  for (std::size_t i = 2; i < xs.size(); ++i) EXPECT_NEAR(xs[i] - xs[i - 1], xs[1] - xs[0], 1e-6 * std::abs(xs[1] - xs[0]));
  std::ifstream fields(dir_ / "result" / "fields.csv");
  int rows = -1;  // the header
  for (std::string line; std::getline(fields, line);) ++rows;
  EXPECT_EQ(rows, 300 * 300);
}

TEST_F(Cli, SolveTwoDimensionalCylinderReportsHalfWidth) {
  std::ofstream(dir_ / "cyl.json") << slurp(fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / "hertz-cylinder-2d.json");
  const Result r = run("solve cyl.json --set grid.nx=128 --set output.plots=false -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "out" / "hertz-cylinder-2d" / "summary.json"));
  ASSERT_TRUE(s.contains("contact_half_width"));
  const double a = 1.4855802e-4;
  EXPECT_NEAR(s["contact_half_width"].get<double>(), a, 0.05 * a);
  EXPECT_EQ(s["dimension"], 2);
}

TEST_F(Cli, UnconvergedSolveExitsWith3UnlessAccepted) {
  const std::string file = case_file([](json& d) {
    d["solver"] = {{"backend", "native"}, {"max_iter", 2}, {"fallback", false}};
  });
  Result r = run("solve " + file + " --out nc -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("error: solver:"), std::string::npos) << r.err;
  ASSERT_TRUE(fs::exists(dir_ / "nc" / "summary.json"));
  EXPECT_EQ(json::parse(slurp(dir_ / "nc" / "summary.json"))["solver"]["status"], "not_converged");
  r = run("solve " + file + " --out nc -q --set solver.accept_unconverged=true");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: solver:"), std::string::npos) << r.err;
}

TEST_F(Cli, CompareWritesOneEntryPerBackend) {
  const std::string file = case_file([](json&) {});
  Result r = run("compare " + file + " --backends ipopt,native --out cmp -q");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("d_pressure"), std::string::npos) << r.out;
  const json list = json::parse(slurp(dir_ / "cmp" / "compare.json"));
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["backend"], "ipopt");
  EXPECT_EQ(list[1]["backend"], "native");
  for (const auto& e : list)
    for (const char* key : {"backend", "status", "time_s", "iterations", "objective", "certificate", "summary"})
      EXPECT_TRUE(e.contains(key)) << key;
  EXPECT_EQ(list[1]["summary"]["solver"]["backend"], "native");
  EXPECT_LT(list[1]["difference_from_first"]["pressure"].get<double>(), 1e-3);
  r = run("compare " + file + " --backends ipopt,bogus");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: --backends:"), std::string::npos) << r.err;
}

}  // namespace
