// The same case and build give bit-identical results: summary.json (timings aside) and every
// CSV file, run after run and with 1 or 2 threads (DYNCONTACT_THREADS). FFTW plans are
// estimated, never measured (a measured plan, and its round-off, depends on the moment's timings).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using dc::test::slurp;

/// summary.json without its timings (every "time_s", and the accuracy estimate's cost as a share
/// of the solve's time).
json without_timings(json j) {
  if (j.is_object()) {
    j.erase("time_s");
    j.erase("cost_fraction");
    for (auto& [key, value] : j.items()) value = without_timings(value);
  } else if (j.is_array()) {
    for (auto& value : j) value = without_timings(value);
  }
  return j;
}

struct Outputs {
  json summary;
  std::map<std::string, std::string> csv;  ///< file name -> bytes
};

class CliReproducibility : public dc::test::CliTest, public ::testing::WithParamInterface<const char*> {
 protected:
  void TearDown() override {
    unsetenv("DYNCONTACT_THREADS");
    CliTest::TearDown();
  }

  /// Solves examples/NAME (with `sets`) into `out` with `threads` threads.
  Outputs solve(const std::string& sets, const std::string& out, const char* threads) const {
    setenv("DYNCONTACT_THREADS", threads, 1);
    const auto r = run("solve " + dc::test::shell_quote(dc::test::example_path(GetParam())) + sets +
                       " -q --set output.plots=false --out " + out);
    EXPECT_EQ(r.code, 0) << r.err;
    Outputs o;
    o.summary = without_timings(json::parse(slurp(dir_ / out / "summary.json")));
    for (const auto& entry : fs::directory_iterator(dir_ / out))
      if (entry.path().extension() == ".csv") o.csv[entry.path().filename().string()] = slurp(entry.path());
    return o;
  }

  static void expect_identical(const Outputs& a, const Outputs& b) {
    EXPECT_EQ(a.summary.dump(), b.summary.dump()) << "summary.json differs";
    ASSERT_FALSE(a.csv.empty());
    ASSERT_EQ(a.csv.size(), b.csv.size());
    for (const auto& [name, bytes] : a.csv) {
      ASSERT_TRUE(b.csv.count(name)) << name;
      EXPECT_TRUE(bytes == b.csv.at(name)) << name << " differs";
    }
  }
};

TEST_P(CliReproducibility, BitIdenticalRunAfterRunAndWithOneOrTwoThreads) {
  const Outputs first = solve("", "a", "1"), again = solve("", "b", "1"), two = solve("", "c", "2");
  expect_identical(first, again);
  expect_identical(first, two);
}

// One case of each run kind: a normal solve, a tangential shift (Cattaneo-Mindlin),
// steady and transient rolling (marching steps), a sweep of dynamic runs.
INSTANTIATE_TEST_SUITE_P(Cases, CliReproducibility,
                         ::testing::Values("hertz-sphere", "cattaneo-sphere", "carter-2d", "rolling-sphere",
                                           "paper-cylinder"),
                         [](const ::testing::TestParamInfo<const char*>& p) {
                           std::string name;
                           for (const char* c = p.param; *c; ++c)
                             if (*c != '-') name += *c;
                           return name;
                         });

}  // namespace
