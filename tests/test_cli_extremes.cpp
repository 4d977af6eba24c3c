// Extreme but valid inputs through the command line (docs/limits.md lists them): each gives
// the closed-form answer (Hertz, within the grid's discretisation error) or a clear error naming
// the key - never exit 0 with a result the program knows to be wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using dc::test::slurp;
using Result = dc::test::CliResult;

struct Extreme {
  const char* name;
  const char* example;
  std::string sets;      ///< --set arguments (already quoted)
  int exit_code;         ///< expected
  const char* error;     ///< exit 2: "error: <key>: ...<words>" prefix expected on stderr
  const char* words;
  bool hertz = false;    ///< exit 0: peak pressure within 1 %, force within 1e-9, approach within 0.5 % of Hertz
};

// ctest names show the parameter as GoogleTest prints it: the name, not raw bytes.
void PrintTo(const Extreme& x, std::ostream* os) { *os << x.name; }

const std::string k32 = " --set grid.nx=32 --set grid.ny=32";
const std::string kSoft = " --set materials.body.E=1e3 --set materials.base.E=1e3";

const std::vector<Extreme> kExtremes = {
    {"StiffE1e13", "hertz-sphere", k32 + " --set materials.body.E=1e13 --set materials.base.E=1e13", 0, "", "", true},
    {"SoftE1e3TinyLoad", "hertz-sphere", k32 + kSoft + " --set normal.force=1e-12", 0, "", "", true},
    {"SoftE1e3", "hertz-sphere", k32 + kSoft, 2, "materials", "a/R = ", false},
    {"SoftE1e3Accepted", "hertz-sphere", k32 + kSoft + " --set materials.allow_large_strain=true", 0, "", "", true},
    {"AuxeticNuMinus09", "hertz-sphere", k32 + " --set materials.body.nu=-0.9 --set materials.base.nu=-0.9", 0, "", "",
     true},
    {"NearlyIncompressibleNu0499", "hertz-sphere",
     k32 + " --set materials.body.nu=0.499 --set materials.base.nu=0.499", 0, "", "", true},
    {"AbsurdModulusE1em300", "hertz-sphere", k32 + " --set materials.body.E=1e-300", 2, "materials.body.E",
     "outside the range", false},
    {"AbsurdModulusE1e300", "hertz-sphere", k32 + " --set materials.base.E=1e300", 2, "materials.base.E",
     "outside the range", false},
    {"IncompressibleNu05", "hertz-sphere", k32 + " --set materials.body.nu=0.5", 2, "materials.body.nu", "", false},
    {"Grid1x1", "hertz-sphere", " --set grid.nx=1 --set grid.ny=1", 2, "grid.nx", "one element", false},
    {"Strips4096", "hertz-cylinder-2d", " --set grid.nx=4096", 0, "", "", true},
    {"ContactBeyondGridEdge", "hertz-sphere", " --set grid.extent=0.5" + k32, 2, "grid", "edge of the grid", false},
    {"ZeroLoad", "hertz-sphere", k32 + " --set normal.force=0", 2, "normal.force", "positive", false},
    {"TinyLoad1em9N", "hertz-sphere", k32 + " --set normal.force=1e-9", 0, "", "", true},
    {"HugeLoad1e9N", "hertz-sphere", k32 + " --set normal.force=1e9", 2, "materials", "a/R = ", false},
    {"BeyondGrossSliding", "cattaneo-sphere", " --set 'tangential.force=[-1e5,0]'", 2, "tangential.force[0]",
     "gross sliding", false},
};

class CliExtremes : public dc::test::CliTest, public ::testing::WithParamInterface<Extreme> {};

TEST_P(CliExtremes, CorrectOrSaidClearly) {
  const Extreme& x = GetParam();
  const Result r = run("solve " + dc::test::shell_quote(dc::test::example_path(x.example)) + x.sets + " -q --out res --set output.plots=false");
  ASSERT_EQ(r.code, x.exit_code) << r.err;
  if (x.exit_code == 2) {
    EXPECT_NE(r.err.find(std::string("error: ") + x.error + ":"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(x.words), std::string::npos) << r.err;
    return;
  }
  const json s = json::parse(slurp(dir_ / "res" / "summary.json"));
  EXPECT_EQ(s["solver"]["status"], "converged");
  if (!x.hertz) return;
  const json& h = s["hertz"];
  EXPECT_NEAR(s["max_pressure"].get<double>() / h["max_pressure"].get<double>(), 1.0, 1e-2);
  EXPECT_NEAR(s["normal_force"].get<double>() / h["normal_force"].get<double>(), 1.0, 1e-9);
  if (h.contains("approach") && h["approach"].is_number()) {
    EXPECT_NEAR(s["approach"].get<double>() / h["approach"].get<double>(), 1.0, 5e-3);
  }
  for (const auto& l : s["limits"]) EXPECT_EQ(l["level"], "warning") << l.dump();
}

INSTANTIATE_TEST_SUITE_P(Inputs, CliExtremes, ::testing::ValuesIn(kExtremes),
                         [](const ::testing::TestParamInfo<Extreme>& p) { return std::string(p.param.name); });

}  // namespace

namespace {

class CliEstimate : public dc::test::CliTest {};

// validate estimates memory and time from the grid size and the operator kind: a dense matrix
// on a small grid, the FFT on a large one, memory growing with the grid.
TEST_F(CliEstimate, ValidatePrintsMemoryAndTimeWithItsBasis) {
  const std::string file = dc::test::shell_quote(dc::test::example_path("hertz-sphere"));
  auto megabytes = [&](int n, const char* kind) {
    const Result r = run("validate " + file + " --set grid.nx=" + std::to_string(n) + " --set grid.ny=" + std::to_string(n));
    EXPECT_EQ(r.code, 0) << r.err;
    const auto at = r.out.find("estimate: ");
    EXPECT_NE(at, std::string::npos) << r.out;
    EXPECT_NE(r.out.find(std::string(kind) + " operator, about", at), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("flop", at), std::string::npos) << r.out;  // the basis is said
    return std::stod(r.out.substr(r.out.find("about ", at) + 6));
  };
  const double small = megabytes(24, "dense"), large = megabytes(2048, "fft");
  // 2048^2 elements: the padded spectrum (4N complex values, 16 bytes) alone is 268 MB.
  EXPECT_GT(large, 268.0);
  EXPECT_LT(large, 5000.0);
  EXPECT_GT(large, 100.0 * small);
}

}  // namespace
