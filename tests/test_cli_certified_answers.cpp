// Right answers are certified, through the program: the reproductions of tangential solves
// that used to exit 3 with a correct result (full stick at huge mu, tiny forces, huge loads),
// frictionless contact (mu = 0), and `compare` with the NLopt fallback on a 2-D example.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using dc::test::slurp;
using Result = dc::test::CliResult;
using dc::test::shell_quote;

class CliCertifiedAnswers : public dc::test::CliTest {
 protected:
  json summary(const std::string& folder) const { return json::parse(slurp(dir_ / folder / "summary.json")); }
  Result solve(const std::string& example, const std::string& sets, const std::string& out) const {
    return run("solve " + shell_quote(dc::test::example_path(example)) + " " + sets +
               " --set 'output={\"plots\":false}' --out " + out + " -q");
  }
};

/// Lubkin's full-stick torsional stiffness of a circular contact: M = 16 G* a^3 theta / 3, with
/// 1/G* = 1/G + 1/G (both bodies twist) and Hertz's a = (3 P R / 4 E*)^(1/3), steel on steel
/// (E = 2.1e11 Pa, nu = 0.3).
double lubkin_stick_moment(double P, double R, double theta) {
  const double E = 2.1e11, nu = 0.3, G_star = E / (2.0 * (1.0 + nu)) / 2.0, E_star = E / (2.0 * (1.0 - nu * nu));
  const double a = std::cbrt(3.0 * P * R / (4.0 * E_star));
  return 16.0 * G_star * a * a * a * theta / 3.0;
}

TEST_F(CliCertifiedAnswers, TorsionInFullStickAtHugeMu) {
  // Was: native stopped after 0 iterations with M = 0 (absolute stopping test), exit 3.
  const Result r = solve("torsion-sphere", "--set 'tangential={\"regime\":\"torsion\",\"angle\":1e-9}' --set friction.mu=1e3", "o");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = summary("o");
  EXPECT_EQ(s["solver"]["status"], "converged");
  EXPECT_EQ(s["n_slip"], 0);
  const double M = lubkin_stick_moment(100.0, 0.01, 1e-9);
  EXPECT_NEAR(std::abs(s["twisting_moment"].get<double>()), M, 0.03 * M);
}

TEST_F(CliCertifiedAnswers, LubkinStickAtMu50On40x40) {
  // Steel on steel, R = 15 mm, P = 400 N, 40 x 40 over 1.1 a, twisted by 1e-6 rad at mu = 50.
  const Result r = solve("torsion-sphere",
                         "--set profile.radius=0.015 --set normal.force=400 --set friction.mu=50 "
                         "--set 'grid={\"nx\":40,\"ny\":40,\"extent\":1.1}' "
                         "--set 'tangential={\"regime\":\"torsion\",\"angle\":1e-6}'",
                         "o");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = summary("o");
  const double M = lubkin_stick_moment(400.0, 0.015, 1e-6);
  EXPECT_NEAR(std::abs(s["twisting_moment"].get<double>()), M, 0.02 * M);
}

TEST_F(CliCertifiedAnswers, SmallForceAndHugeLoadCertify) {
  Result r = solve("cattaneo-sphere", "--set 'tangential.force=[-0.3,0]'", "small");
  EXPECT_EQ(r.code, 0) << r.err;
  // 1e9 N on the 10 mm sphere: far outside linear elasticity (accepted here), a full-stick answer.
  r = solve("cattaneo-sphere", "--set normal.force=1e9 --set materials.allow_large_strain=true", "huge");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(summary("huge")["solver"]["status"], "converged");
}

TEST_F(CliCertifiedAnswers, FrictionlessContactIsValid) {
  Result r = solve("cattaneo-sphere", "--set friction.mu=0 --set 'tangential.force=[0,0]'", "o");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = summary("o");
  EXPECT_EQ(s["solver"]["backend"], "none");
  EXPECT_EQ(s["solver"]["status"], "converged");
  EXPECT_TRUE(s["rigid_shift_undetermined"].get<bool>());
  EXPECT_NE(s["solver"]["message"].get<std::string>().find("undetermined"), std::string::npos);
  EXPECT_EQ(s["tangential_force"][0].get<double>(), 0.0);
  EXPECT_GT(s["normal_force"].get<double>(), 99.0);  // the contact carries its load
  // A tangential force without friction is gross sliding: an input error naming the component.
  r = solve("cattaneo-sphere", "--set friction.mu=0", "f");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("error: tangential.force[0]:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("gross sliding"), std::string::npos) << r.err;
}

TEST_F(CliCertifiedAnswers, CompareWithNLoptOn2D) {
  // The 3-D examples and the ellipsoid take ~10 s each (Ipopt): slow_nlopt_compare.cpp.
  json doc = dc::test::example_json("hertz-cylinder-2d");
  doc["grid"]["nx"] = 32;
  doc["output"] = {{"plots", false}};
  write_case(doc, "c.json");
  const Result r = run("compare c.json --backends ipopt,nlopt,native --out c -q");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
}

TEST_F(CliCertifiedAnswers, AnOverflowedSolutionIsNeverCertified) {
  // Steady rolling at a creepage of 1e308 overflows the slip: the certificate meets NaN. It used
  // to drop out of the certificate's max() and the run exited 0 as "converged".
  const Result r = solve("rolling-sphere", "--set 'tangential.creepage=[1e308,0]' --set grid.nx=16 --set grid.ny=16", "o");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_EQ(summary("o")["solver"]["status"], "not_converged");
}

}  // namespace
