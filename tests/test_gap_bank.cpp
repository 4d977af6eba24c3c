// The gap bank (scripts/make_gap_bank.py) at its small scale: each test generates the cases it
// needs into its own folder (nothing generated is committed) and solves them with the program.
// Checked against Sneddon's cone, the punch's own face, an independent solver (Ipopt against the
// native solver), force against approach control on the same gap, and the generator's
// determinism. Skipped when CMake found no python3 with NumPy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// The pressure column of fields.csv on its ny x nx grid (x fastest).
struct PressureMap {
  int nx = 0, ny = 0;
  std::vector<double> p;
  double at(int i, int j) const { return p[static_cast<std::size_t>(j) * nx + i]; }
};

PressureMap read_pressure(const fs::path& fields, int nx, int ny) {
  PressureMap m{nx, ny, {}};
  std::ifstream in(fields);
  std::string line;
  std::getline(in, line);  // header x,y,p,...
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string x, y, p;
    std::getline(s, x, ',');
    std::getline(s, y, ',');
    std::getline(s, p, ',');
    m.p.push_back(std::stod(p));
  }
  return m;
}

/// The loads of the 4-connected patches of p > 0, largest first.
std::vector<double> patch_loads(const PressureMap& m) {
  std::vector<int> label(m.p.size(), 0);
  std::vector<double> loads;
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) {
      if (m.at(i, j) <= 0.0 || label[static_cast<std::size_t>(j) * m.nx + i]) continue;
      const int id = static_cast<int>(loads.size()) + 1;
      double load = 0.0;
      std::vector<std::pair<int, int>> stack{{i, j}};
      label[static_cast<std::size_t>(j) * m.nx + i] = id;
      while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        load += m.at(a, b);
        const int next[4][2] = {{a + 1, b}, {a - 1, b}, {a, b + 1}, {a, b - 1}};
        for (const auto& n : next) {
          if (n[0] < 0 || n[0] >= m.nx || n[1] < 0 || n[1] >= m.ny) continue;
          const std::size_t k = static_cast<std::size_t>(n[1]) * m.nx + n[0];
          if (m.p[k] > 0.0 && !label[k]) {
            label[k] = id;
            stack.push_back({n[0], n[1]});
          }
        }
      }
      loads.push_back(load);
    }
  std::sort(loads.rbegin(), loads.rend());
  return loads;
}

class GapBank : public test::CliTest {
 protected:
  void SetUp() override {
    test::CliTest::SetUp();
    if (std::string(DYNCONTACT_PYTHON).empty()) GTEST_SKIP() << "no python3 with NumPy was found by CMake";
  }

  /// Runs the generator (small scale) for `names` into `folder` under the test folder.
  void generate(const std::string& names, const std::string& folder = "bank") const {
    const std::string cmd = test::shell_quote(DYNCONTACT_PYTHON) + " " +
                            test::shell_quote(std::string(DYNCONTACT_SOURCE_DIR) + "/scripts/make_gap_bank.py") +
                            " --scale small --only " + names + " --out " + test::shell_quote((dir_ / folder).string()) +
                            " >/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  }

  json case_json(const std::string& name) const { return json::parse(test::slurp(dir_ / "bank" / (name + ".json"))); }

  /// Solves bank/NAME.json (plus `sets`, each "--set k=v") into `out`; exit 0 expected.
  json solve(const std::string& name, const std::string& out, const std::string& sets = "") const {
    const test::CliResult r =
        run("solve bank/" + name + ".json --out " + out + " -q --set output.plots=false " + sets);
    EXPECT_EQ(r.code, 0) << r.err;
    json s = json::parse(test::slurp(dir_ / out / "summary.json"));
    if (sets.find("solver.backend") == std::string::npos) {  // auto: the native solver, no fallback
      EXPECT_EQ(s["solver"]["backend"], "native") << name << ": " << s["solver"];
      EXPECT_FALSE(s["solver"]["fallback_used"].get<bool>()) << name << ": " << s["solver"];
    }
    return s;
  }
};

// Sneddon's cone (Johnson 1985, section 5.2(b)): F = (pi/2) a^2 E* tan(beta), approach
// delta = (pi/2) a tan(beta). 33 x 33 elements over +-1.32 a: the approach within 0.5 % (it
// comes out 0.02 % low), the contact area (its elements) within 3 % of pi a^2 (1.2 % high: the
// boundary ring of elements is 2 dx / a = 16 % of it).
TEST_F(GapBank, ConeMatchesSneddon) {
  generate("cone");
  const json c = case_json("cone");
  const json s = solve("cone", "out");
  const double G = c["materials"]["body"]["G"], nu = c["materials"]["body"]["nu"];
  const double e_star = G / (1.0 - nu);  // both bodies alike
  const double tan_beta = std::tan(2.0 * M_PI / 180.0), F = c["normal"]["force"];
  const double a = std::sqrt(2.0 * F / (M_PI * e_star * tan_beta));
  const double delta = 0.5 * M_PI * a * tan_beta;
  EXPECT_NEAR(s["approach"].get<double>() / delta, 1.0, 5e-3);
  EXPECT_NEAR(s["contact_area"].get<double>() / (M_PI * a * a), 1.0, 0.03);
  EXPECT_EQ(s["limits"].size(), 0u);
}

// The sharp rectangular punch: whatever the load, the contact is the face (the table's zeros)
// and nothing else, and the largest pressure sits at the face's corners (the strongest
// singularity), the four of them equal to 1e-9 by symmetry.
TEST_F(GapBank, SharpPunchTouchesWithItsFaceAndPeaksAtItsCorners) {
  generate("flat-punch-sharp");
  std::ifstream table(dir_ / "bank" / "flat-punch-sharp.csv");
  std::string line;
  std::getline(table, line);
  int face = 0;
  while (std::getline(table, line)) face += line.substr(line.rfind(',') + 1) == "0";
  const json s = solve("flat-punch-sharp", "out");
  ASSERT_GT(face, 0);
  EXPECT_EQ(s["n_contact"].get<int>(), face);
  const int nx = s["grid"]["nx"], ny = s["grid"]["ny"];
  const PressureMap m = read_pressure(dir_ / "out" / "fields.csv", nx, ny);
  // the face's corner elements: the first and last rows and columns with p > 0
  int i0 = nx, i1 = -1, j0 = ny, j1 = -1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (m.at(i, j) > 0.0) i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  const double pmax = *std::max_element(m.p.begin(), m.p.end());
  for (const auto& [i, j] : {std::pair{i0, j0}, std::pair{i1, j0}, std::pair{i0, j1}, std::pair{i1, j1}})
    EXPECT_NEAR(m.at(i, j) / pmax, 1.0, 1e-9) << "corner (" << i << ", " << j << ")";
}

// Tread and flange root: two separate patches, both carrying load (designed: about 70 / 30 %;
// each at least 20 % here), and Ipopt (an independent solver) finds the same approach to 1e-6
// and the same patch loads to 1e-4 of the force.
TEST_F(GapBank, TwoPatchesBothLoadedAndIpoptAgrees) {
  generate("two-patches");
  const json native = solve("two-patches", "native", "--set solver.backend=native");
  const json ipopt = solve("two-patches", "ipopt", "--set solver.backend=ipopt");
  const int nx = native["grid"]["nx"], ny = native["grid"]["ny"];
  const double F = native["normal_force"];
  const std::vector<double> a = patch_loads(read_pressure(dir_ / "native" / "fields.csv", nx, ny));
  const std::vector<double> b = patch_loads(read_pressure(dir_ / "ipopt" / "fields.csv", nx, ny));
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  const double area = native["grid"]["dx"].get<double>() * native["grid"]["dy"].get<double>();
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_GE(a[k] * area / F, 0.2) << "patch " << k;
    EXPECT_NEAR(a[k] * area / F, b[k] * area / F, 1e-4) << "patch " << k;
  }
  EXPECT_NEAR(ipopt["approach"].get<double>() / native["approach"].get<double>(), 1.0, 1e-6);
}

// The measured wheel/rail gap (noise, quantisation, bilinear table): force control at 10 kN and
// approach control at the approach it gave are the same problem: the force comes back to 1e-6.
TEST_F(GapBank, MeasuredWheelRailForceAndApproachControlAgree) {
  generate("measured-wheel-rail,measured-wheel-rail-force");
  const json f = solve("measured-wheel-rail-force", "force");
  const double approach = f["approach"];
  std::ostringstream set;
  set.precision(17);
  set << "--set normal.approach=" << approach;
  const json d = solve("measured-wheel-rail", "approach", set.str());
  EXPECT_NEAR(d["normal_force"].get<double>() / 10e3, 1.0, 1e-6);
  EXPECT_EQ(d["n_contact"], f["n_contact"]);
}

// The tangential solvers on the measured gap (force control, 10 kN, mu = 0.3): a shift to half
// of mu P, steady rolling at a creepage of 5e-4 (about half saturation: |Fx| / mu P measured
// 0.54) and the shift again with kappa != 0 (a base of G = 70 GPa, nu = 0.33). Each is answered
// by the native solvers, certified (exit 0) and without a fallback; the shift's force is the
// given one.
TEST_F(GapBank, TangentialSolversOnTheMeasuredGap) {
  generate("measured-wheel-rail-force");
  const std::string tangential = " --set problem=tangential --set friction.law=coulomb --set friction.mu=0.3";
  const json shift = solve("measured-wheel-rail-force", "shift",
                           tangential + " --set tangential.regime=shift --set tangential.force=[1500,0]");
  EXPECT_NEAR(shift["tangential_force"][0].get<double>(), 1500.0, 1e-6 * 1500.0);
  const json rolling = solve("measured-wheel-rail-force", "rolling",
                             tangential + " --set tangential.regime=rolling --set tangential.creepage=[5e-4,0]" +
                                 " --set tangential.velocity=30");
  const double saturation = std::abs(rolling["tangential_force"][0].get<double>()) / 3000.0;
  EXPECT_GT(saturation, 0.3);
  EXPECT_LT(saturation, 0.8);
  const json kappa = solve("measured-wheel-rail-force", "kappa",
                           tangential + " --set tangential.regime=shift --set tangential.force=[1500,0]" +
                               " --set materials.base.G=7e10 --set materials.base.nu=0.33");
  EXPECT_NEAR(kappa["tangential_force"][0].get<double>(), 1500.0, 1e-6 * 1500.0);
}

// The conformal band: flat to +-0.4 um over |y| <= 4 mm, so the contact spans the whole band
// (and reaches beyond it, where the gap rises slowly), inside the grid.
TEST_F(GapBank, ConformalBandIsInContactAcrossTheBand) {
  generate("conformal-band");
  const json s = solve("conformal-band", "out");
  EXPECT_LE(s["contact_extent"]["y"][0].get<double>(), -4e-3);
  EXPECT_GE(s["contact_extent"]["y"][1].get<double>(), 4e-3);
  EXPECT_EQ(s["limits"].size(), 0u);
}

// The rough sphere (128 x 128, self-affine H = 0.8, rms slope 0.1): the contact breaks into
// many patches (17 today; at least 10) inside the grid, and its area is at most half the smooth
// sphere's Hertz area pi a^2 at the same load (24 % of it today; the smooth sphere on this grid:
// 100.7 %).
TEST_F(GapBank, RoughSphereFormsManyPatchesInsideTheGrid) {
  generate("rough-sphere");
  const json s = solve("rough-sphere", "out");
  const int nx = s["grid"]["nx"], ny = s["grid"]["ny"];
  EXPECT_GE(patch_loads(read_pressure(dir_ / "out" / "fields.csv", nx, ny)).size(), 10u);
  const double L = s["grid"]["x"][1].get<double>() - s["grid"]["x"][0].get<double>();
  const double a_hertz = 0.25 * L;  // the case's load is the Hertz force of this radius
  EXPECT_LT(s["contact_area"].get<double>(), 0.5 * M_PI * a_hertz * a_hertz);
  EXPECT_EQ(s["limits"].size(), 0u);
}

// The generator is deterministic: two runs write the same bytes (seeded RandomState streams).
TEST_F(GapBank, GeneratorIsDeterministic) {
  generate("measured-wheel-rail,rough-sphere", "one");
  generate("measured-wheel-rail,rough-sphere", "two");
  for (const char* f : {"measured-wheel-rail.json", "measured-wheel-rail.csv", "rough-sphere.json", "rough-sphere.csv"}) {
    const std::string a = test::slurp(dir_ / "one" / f);
    EXPECT_FALSE(a.empty()) << f;
    EXPECT_EQ(a, test::slurp(dir_ / "two" / f)) << f;
  }
}

}  // namespace
}  // namespace dc
