// Forced failures through the program (DYNCONTACT_FAULT, read by the test-only program
// `dyncontact_with_faults`: tests/support/program_with_faults.cpp):
// `auto` falls back and says so in summary.json; an explicitly requested backend does not; a
// backend returning NaN is caught and nothing non-finite reaches a file; a non-converging outer
// loop ends with a clear message, exit 3 and its last iterate written; a broken table file is
// an input error naming the file and line.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using dc::test::slurp;
using Result = dc::test::CliResult;

class CliForcedFailures : public dc::test::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    use_program_with_faults();
  }
  void TearDown() override {
    unsetenv("DYNCONTACT_FAULT");
    CliTest::TearDown();
  }
  /// Example `name` on an n x n grid (no plots) with `edit`, written to the test folder.
  std::string case_file(const std::string& name, int n, const std::function<void(json&)>& edit = {}) const {
    json doc = dc::test::example_json(name);
    doc["grid"]["nx"] = n;
    if (doc["dimension"] == 3) doc["grid"]["ny"] = n;
    doc["output"] = {{"plots", false}};
    if (edit) edit(doc);
    return write_case(doc, name + ".json");
  }
  Result run_with_fault(const std::string& fault, const std::string& args) const {
    setenv("DYNCONTACT_FAULT", fault.c_str(), 1);
    Result r = run(args);
    unsetenv("DYNCONTACT_FAULT");
    return r;
  }
  /// No "nan"/"inf" in any CSV file of the folder; in summary.json (where a NaN would be
  /// written as null) the results and the certificate are numbers.
  void expect_no_non_finite(const fs::path& folder) const {
    ASSERT_TRUE(fs::exists(folder));
    for (const auto& entry : fs::directory_iterator(folder)) {
      if (!entry.is_regular_file() || entry.path().extension() != ".csv") continue;
      const std::string text = slurp(entry.path());
      for (const char* bad : {"nan", "NaN", "inf"})
        EXPECT_EQ(text.find(bad), std::string::npos) << entry.path() << " holds " << bad;
    }
    if (!fs::exists(folder / "summary.json")) return;
    const json s = json::parse(slurp(folder / "summary.json"));
    for (const char* key : {"normal_force", "approach", "max_pressure", "contact_area"})
      EXPECT_TRUE(s[key].is_number()) << key << ": " << s[key];
    for (const auto& [key, value] : s["solver"]["certificate"].items()) EXPECT_TRUE(value.is_number()) << key;
    if (s.contains("tangential_force")) {
      EXPECT_TRUE(s["tangential_force"][0].is_number() && s["tangential_force"][1].is_number());
      EXPECT_TRUE(s["twisting_moment"].is_number());
    }
  }
  json summary(const std::string& folder) const { return json::parse(slurp(dir_ / folder / "summary.json")); }
};

TEST_F(CliForcedFailures, AutoFallsBackAndSaysSo) {
  // 20^2 (400 unknowns): auto tries native first; its failure falls back to Ipopt.
  const Result r = run_with_fault("native:fail", "solve " + case_file("hertz-sphere", 20) + " --out o -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = summary("o");
  EXPECT_TRUE(s["solver"]["fallback_used"].get<bool>());
  EXPECT_NE(s["solver"]["backend"], "native");
  EXPECT_EQ(s["solver"]["status"], "converged");
  EXPECT_NE(s["solver"]["message"].get<std::string>().find("tried native: failed"), std::string::npos)
      << s["solver"]["message"];
  // The failed attempt is listed, and stderr says so (auto never hides a failing fast path).
  ASSERT_EQ(s["solver"]["failed_attempts"].size(), 1u) << s["solver"];
  EXPECT_EQ(s["solver"]["failed_attempts"][0]["backend"], "native");
  EXPECT_EQ(s["solver"]["failed_attempts"][0]["status"], "failed");
  EXPECT_NE(r.err.find("warning: solver: native: failed"), std::string::npos) << r.err;
}

TEST_F(CliForcedFailures, TheProgramItselfNeverReadsTheFaultVariable) {
  // DYNCONTACT_FAULT is the tests' own: `dyncontact` (not the test-only program) solves as if it
  // were unset, with its first backend and no fallback.
  const std::string doc = case_file("hertz-sphere", 20);
  program_ = DYNCONTACT_BINARY;
  const Result r = run_with_fault("native:fail,ipopt:fail,nlopt:fail", "solve " + doc + " --out o -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = summary("o");
  EXPECT_FALSE(s["solver"]["fallback_used"].get<bool>());
  EXPECT_EQ(s["solver"]["backend"], "native");
  EXPECT_EQ(s["solver"]["status"], "converged");
  EXPECT_EQ(r.err.find("injected"), std::string::npos) << r.err;
}

TEST_F(CliForcedFailures, NativeSolverThatRunsOutOfIterationsReportsItsHistory) {
  // Three iterations are not enough on 20^2 (nor for Ipopt): auto moves on until NLopt answers,
  // and the summary keeps the native solver's iterations (change, contact set) for the user to
  // see why.
  const Result r = run("solve " + case_file("hertz-sphere", 20) + " --set solver.max_iter=3 --out o -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = summary("o");
  EXPECT_TRUE(s["solver"]["fallback_used"].get<bool>());
  ASSERT_GE(s["solver"]["failed_attempts"].size(), 1u) << s["solver"];
  const json& native = s["solver"]["failed_attempts"][0];
  EXPECT_EQ(native["backend"], "native");
  EXPECT_EQ(native["status"], "not_converged");
  EXPECT_EQ(native["iterations"], 3);
  ASSERT_EQ(native["history"].size(), 3u) << native;
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(native["history"][k]["iteration"], k + 1);
    EXPECT_GT(native["history"][k]["change"].get<double>(), 0.0);
    EXPECT_GT(native["history"][k]["active"].get<int>(), 0);
  }
  EXPECT_NE(r.err.find("warning: solver: native: not_converged after 3 iterations (iteration limit reached; "
                       "relative change"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("took over"), std::string::npos) << r.err;
}

TEST_F(CliForcedFailures, AutoFallsBackOnAStalledTangentialSolve) {
  // 12^2 (288 unknowns): native first.
  const Result r = run_with_fault("native:stall", "solve " + case_file("cattaneo-sphere", 12) + " --out o -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = summary("o");
  EXPECT_TRUE(s["solver"]["fallback_used"].get<bool>());
  EXPECT_NE(s["solver"]["backend"], "native");
  EXPECT_NE(s["solver"]["message"].get<std::string>().find("native: not_converged"), std::string::npos)
      << s["solver"]["message"];
}

TEST_F(CliForcedFailures, NamedBackendDoesNotFallBack) {
  const Result r =
      run_with_fault("native:stall", "solve " + case_file("hertz-sphere", 16) + " --backend native --out o -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("did not converge"), std::string::npos) << r.err;
  const json s = summary("o");
  EXPECT_FALSE(s["solver"]["fallback_used"].get<bool>());
  EXPECT_EQ(s["solver"]["backend"], "native");
}

TEST_F(CliForcedFailures, NaNIsCaughtAndNeverWritten) {
  // auto: every backend's NaN is caught; the last one falls back to a clean solve.
  Result r = run_with_fault("native:nan,ipopt:nan", "solve " + case_file("hertz-sphere", 16) + " --out a -q");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(summary("a")["solver"]["backend"], "nlopt");
  expect_no_non_finite(dir_ / "a");
  // Named: a failure, said as such; nothing non-finite written.
  r = run_with_fault("native:nan", "solve " + case_file("hertz-sphere", 16) + " --backend native --out n -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("non-finite"), std::string::npos) << r.err;
  if (fs::exists(dir_ / "n")) expect_no_non_finite(dir_ / "n");
  // A tangential case whose normal problem cannot be solved: exit 3, not an internal error.
  r = run_with_fault("native:nan", "solve " + case_file("cattaneo-sphere", 8) + " --backend native --out t -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("normal problem failed"), std::string::npos) << r.err;
  if (fs::exists(dir_ / "t")) expect_no_non_finite(dir_ / "t");
}

TEST_F(CliForcedFailures, OuterLoopThatDoesNotConvergeEndsCleanly) {
  // Dissimilar materials: the kappa alternation (4.26)-(4.27) runs; forced never to settle.
  const std::string file = case_file("cattaneo-sphere", 12, [](json& d) {
    d["materials"]["base"] = {{"E", 7e10}, {"nu", 0.33}};
  });
  const Result r = run_with_fault("outer:stall", "solve " + file + " --out o -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("outer loop"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did not converge"), std::string::npos) << r.err;
  const json s = summary("o");
  EXPECT_EQ(s["solver"]["status"], "not_converged");
  EXPECT_FALSE(s["outer_converged"].get<bool>());
  EXPECT_TRUE(fs::exists(dir_ / "o" / "fields.csv"));
  expect_no_non_finite(dir_ / "o");
}

TEST_F(CliForcedFailures, BrokenTableFilesNameFileAndLine) {
  const auto table_case = [&](const std::string& table) {
    return case_file("hertz-sphere", 8, [&](json& d) {
      d["profile"] = {{"type", "table"}, {"file", table}};
      d["grid"] = {{"nx", 8}, {"ny", 8}, {"x", {-1e-4, 1e-4}}, {"y", {-1e-4, 1e-4}}};
    });
  };
  Result r = run("solve " + table_case("missing.csv") + " --out o -q");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("profile.file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("missing.csv"), std::string::npos) << r.err;
  std::ofstream(dir_ / "bad.csv") << "x,y,h\n-1e-3,-1e-3,0\n1e-3,-1e-3,zero\n-1e-3,1e-3,0\n1e-3,1e-3,0\n";
  r = run("solve " + table_case("bad.csv") + " --out o -q");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("profile.file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line 3"), std::string::npos) << r.err;
  // A table that does not cover the grid.
  std::ofstream(dir_ / "small.csv") << "x,y,h\n-1e-5,-1e-5,0\n1e-5,-1e-5,0\n-1e-5,1e-5,0\n1e-5,1e-5,0\n";
  r = run("solve " + table_case("small.csv") + " --out o -q");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("outside the table"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "o" / "summary.json"));
}

}  // namespace
