// The benchmark cases of examples/bench/ (scripts/bench.sh peer) are valid case files, kept out
// of the bundled examples (`example --list`): they are sized for timing, not for a first run. A
// case whose table is not committed (too large) is made by scripts/make_gap_bank.py first.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc {
namespace {

namespace fs = std::filesystem;

class BenchCases : public test::CliTest {};

TEST_F(BenchCases, EveryBenchCaseValidatesAndIsNotBundled) {
  const test::CliResult list = run("example --list");
  ASSERT_EQ(list.code, 0);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / "bench")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(name);
    EXPECT_EQ(list.out.find(name + " "), std::string::npos) << "a bench case is listed as an example";
    std::string path = entry.path().string();
    const nlohmann::json doc = nlohmann::json::parse(test::slurp(entry.path()));
    if (doc.contains("profile") && doc["profile"].contains("file") &&
        !fs::exists(entry.path().parent_path() / doc["profile"]["file"].get<std::string>())) {
      // A table too large to commit (.gitignore): scripts/make_gap_bank.py writes it with its case,
      // here into the test folder; the case it writes must be the committed one.
      ASSERT_FALSE(std::string(DYNCONTACT_PYTHON).empty())
          << name << ": its table is not committed and CMake found no python3 with NumPy to make it";
      const std::string cmd = test::shell_quote(DYNCONTACT_PYTHON) + " " +
                              test::shell_quote(std::string(DYNCONTACT_SOURCE_DIR) + "/scripts/make_gap_bank.py") +
                              " --only " + name + " --out " + test::shell_quote((dir_ / "generated").string()) +
                              " >/dev/null";
      ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
      path = (dir_ / "generated" / (name + ".json")).string();
      EXPECT_EQ(nlohmann::json::parse(test::slurp(path)), doc) << "scripts/make_gap_bank.py writes another " << name;
    }
    const test::CliResult v = run("validate " + test::shell_quote(path));
    EXPECT_EQ(v.code, 0) << v.err;
  }
  EXPECT_GE(files, 7);
}

}  // namespace
}  // namespace dc
