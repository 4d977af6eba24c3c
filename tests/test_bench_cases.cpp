// The benchmark cases of examples/bench/ (scripts/bench.sh peer) are valid case files, kept out
// of the bundled examples (`example --list`): they are sized for timing, not for a first run.
#include <gtest/gtest.h>

#include <filesystem>

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
    const test::CliResult v = run("validate " + test::shell_quote(entry.path().string()));
    EXPECT_EQ(v.code, 0) << v.err;
  }
  EXPECT_GE(files, 7);
}

}  // namespace
}  // namespace dc
