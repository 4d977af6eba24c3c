// `dyncontact table`, run as a program: the creep-force table of a rolling sphere against
// Kalker's linear theory near the origin ([K] in core/contact_closed_forms.hpp) and against
// saturation at mu P far from it; the files of the contract (CASES.md); the same bytes from one
// thread, two threads and `mpirun -n 2`; a failing point reported with the others kept; bad
// ranges as input errors naming the option.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "contact_closed_forms.hpp"
#include "hertz.hpp"
#include "material.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using dc::test::slurp;

/// A number as the command line should read it back exactly.
std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

/// One row of table.csv by column name.
struct Row {
  std::vector<std::string> cells;
  double num(std::size_t column) const { return std::stod(cells.at(column)); }
};

struct Table {
  std::vector<std::string> header;
  std::vector<Row> rows;
  std::size_t col(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  double at(std::size_t row, const std::string& name) const { return rows.at(row).num(col(name)); }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

Table read_table(const fs::path& p) {
  Table t;
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  t.header = split(line);
  while (std::getline(in, line)) t.rows.push_back({split(line)});
  return t;
}

// The rolling-sphere example (steel on steel, R = 10 mm, P = 100 N, mu = 0.3) on a 48^2 grid over
// +-1.1 a, where the steady rolling tests measure Kalker's coefficients within 3 % (C23: 5 %).
constexpr double kR = 0.01, kP = 100.0, kMu = 0.3, kE = 2.1e11, kNu = 0.3;

class CliTable : public dc::test::CliTest {
 protected:
  std::string case_file(int n = 48) const {
    json doc = dc::test::example_json("rolling-sphere");
    doc["grid"] = {{"nx", n}, {"ny", n}, {"extent", 1.1}};
    doc["output"] = {{"plots", false}};
    return write_case(doc);
  }
};

TEST_F(CliTable, KalkerLinearTheoryNearTheOriginAndTheFilesOfTheContract) {
  const dc::MaterialPair steel{dc::Elastic::from_E_nu(kE, kNu), dc::Elastic::from_E_nu(kE, kNu)};
  const double a = dc::hertz::sphere(kR, kP, steel.E_star()).a, G = steel.body.G;
  const auto k = dc::closed_form::kalker_circular(kNu);
  // |F|/(mu P) ~ 4e-3: linear theory holds to ~0.1 %; the spin 2 xi / a gives a comparable force.
  const double xi = 1e-5, phi = 2.0 * xi / a;
  const std::string file = case_file();
  const auto r =
      run("table " + file + " --creepage 0," + num(xi) + " --lateral 0," + num(xi) + " --spin 0," + num(phi) + " --out tab -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const Table t = read_table(dir_ / "tab" / "table.csv");
  EXPECT_EQ(t.header, (std::vector<std::string>{"creepage_x", "creepage_y", "spin", "Fx", "Fy", "Mz", "Fx_mu_P",
                                                "Fy_mu_P", "n_stick", "certificate", "status"}));
  ASSERT_EQ(t.rows.size(), 8u);
  // Order: creepage_x fastest, then creepage_y, then spin.
  EXPECT_NEAR(t.at(1, "creepage_x"), xi, 1e-11 * xi);  // table.csv: 12 digits
  EXPECT_NEAR(t.at(2, "creepage_y"), xi, 1e-11 * xi);
  EXPECT_NEAR(t.at(4, "spin"), phi, 1e-11 * phi);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    EXPECT_EQ(t.rows[i].cells.back(), "converged");
    EXPECT_LT(t.at(i, "certificate"), 1e-6);
  }
  const double fx = t.at(1, "Fx"), fy = t.at(2, "Fy"), fy_spin = t.at(4, "Fy");
  const double kfx = -G * a * a * k.c11 * xi, kfy = -G * a * a * k.c22 * xi, kfs = -G * a * a * a * k.c23 * phi;
  std::printf("[ table ] Fx %.5g (Kalker %.5g)  Fy %.5g (%.5g)  Fy(spin) %.5g (%.5g)\n", fx, kfx, fy, kfy, fy_spin,
              kfs);
  EXPECT_NEAR(fx / kfx, 1.0, 0.05);
  EXPECT_NEAR(fy / kfy, 1.0, 0.05);
  EXPECT_NEAR(fy_spin / kfs, 1.0, 0.05);
  EXPECT_NEAR(t.at(1, "Fx_mu_P"), fx / (kMu * kP), 1e-3 * std::abs(fx / (kMu * kP)));
  // Linear: the point with both creepages is the sum of the two (within the linear range).
  EXPECT_NEAR(t.at(3, "Fx"), fx, 0.01 * std::abs(fx));
  EXPECT_NEAR(t.at(3, "Fy"), fy, 0.01 * std::abs(fy));
  // No creepage, no force.
  EXPECT_LT(std::abs(t.at(0, "Fx")) + std::abs(t.at(0, "Fy")), 1e-6 * std::abs(fx));

  const json meta = json::parse(slurp(dir_ / "tab" / "table.json"));
  EXPECT_EQ(meta["ranges"]["creepage_x"], json({0.0, xi}));
  EXPECT_EQ(meta["points"], 8);
  EXPECT_TRUE(meta["failed"].empty());
  EXPECT_EQ(meta["case"]["name"], "rolling-sphere");
}

TEST_F(CliTable, SaturatesAtMuPAndGrowsMonotonically) {
  // Far from the origin (xi >> mu a / R) the whole contact slips: |Fx| -> mu P.
  const std::string file = case_file(24);
  const auto r = run("table " + file + " --creepage 0:0.05:6 --out tab -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const Table t = read_table(dir_ / "tab" / "table.csv");
  ASSERT_EQ(t.rows.size(), 6u);
  for (std::size_t i = 1; i < t.rows.size(); ++i) {
    EXPECT_LT(t.at(i, "Fx"), t.at(i - 1, "Fx"));  // more creepage, more force (opposite to it)
    EXPECT_GE(t.at(i, "Fx_mu_P"), -1.0 - 1e-9);   // never beyond the friction capacity
  }
  EXPECT_NEAR(t.at(5, "Fx_mu_P"), -1.0, 1e-3);
  EXPECT_NEAR(t.at(5, "Fx"), -kMu * kP, 1e-3 * kMu * kP);
  EXPECT_EQ(t.at(5, "n_stick"), 0);
}

TEST_F(CliTable, ThreadsAndRanksWriteTheSameBytes) {
  const std::string file = case_file(16);
  const std::string args = "table " + file + " --creepage -0.004:0.004:3 --lateral 0,0.002 --spin 0,20 -q --out ";
  auto files = [&](const std::string& out) {
    return slurp(dir_ / out / "table.csv") + slurp(dir_ / out / "table.json");
  };
  ASSERT_EQ(run_prefixed("DYNCONTACT_THREADS=1", args + "serial").code, 0);
  ASSERT_EQ(run_prefixed("DYNCONTACT_THREADS=2", args + "threads").code, 0);
  const std::string serial = files("serial");
  ASSERT_FALSE(serial.empty());
  EXPECT_EQ(files("threads"), serial);
  if (!have_mpirun()) GTEST_SKIP() << "no mpirun here";
  const auto mpi = run_mpi2(args + "ranks");
  ASSERT_EQ(mpi.code, 0) << mpi.err;
  EXPECT_EQ(files("ranks"), serial);
}

TEST_F(CliTable, AFailingPointIsReportedAndTheOthersKept) {
  // A creepage of 1e308 overflows the slip (its certificate meets NaN), one of 1e200 is beyond
  // what the steady solver resolves: neither certifies, both reported, the ordinary points kept.
  const std::string file = case_file(16);
  const auto r = run("table " + file + " --creepage 0,1e-3,1e308,1e200 -q --out tab");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("point 2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("point 3"), std::string::npos) << r.err;
  const Table t = read_table(dir_ / "tab" / "table.csv");
  ASSERT_EQ(t.rows.size(), 4u);
  EXPECT_EQ(t.rows[0].cells.back(), "converged");
  EXPECT_EQ(t.rows[1].cells.back(), "converged");
  EXPECT_LT(t.at(1, "Fx"), 0.0);
  EXPECT_NE(t.rows[2].cells.back(), "converged");
  EXPECT_NE(t.rows[3].cells.back(), "converged");
  const json meta = json::parse(slurp(dir_ / "tab" / "table.json"));
  ASSERT_EQ(meta["failed"].size(), 2u);
  EXPECT_EQ(meta["failed"][0]["row"], 2);
  EXPECT_EQ(meta["failed"][1]["row"], 3);
  EXPECT_FALSE(meta["failed"][0]["message"].get<std::string>().empty());
  // Over MPI ranks: the same failures reported, the same files written.
  if (!have_mpirun()) GTEST_SKIP() << "no mpirun here";
  const auto mpi = run_mpi2("table " + file + " --creepage 0,1e-3,1e308,1e200 -q --out tab-ranks");
  EXPECT_EQ(mpi.code, 3) << mpi.err;
  EXPECT_NE(mpi.err.find("point 2"), std::string::npos) << mpi.err;
  EXPECT_EQ(slurp(dir_ / "tab-ranks" / "table.csv"), slurp(dir_ / "tab" / "table.csv"));
  EXPECT_EQ(slurp(dir_ / "tab-ranks" / "table.json"), slurp(dir_ / "tab" / "table.json"));
}

TEST_F(CliTable, BadRangesAreInputErrorsNamingTheOption) {
  const std::string file = case_file(16);
  struct Bad {
    std::string args, option;
  };
  for (const Bad& b : {Bad{"--creepage 0:1:0", "--creepage"}, Bad{"--creepage 0:1", "--creepage"},
                       Bad{"--lateral abc", "--lateral"}, Bad{"--spin 1,,2", "--spin"},
                       Bad{"--creepage 0:1:1", "--creepage"}, Bad{"--spin 0:1:2.5", "--spin"},
                       Bad{"--creepage nan", "--creepage"}}) {
    const auto r = run("table " + file + " " + b.args + " -q --out tab");
    EXPECT_EQ(r.code, 2) << b.args << "\n" << r.err;
    EXPECT_NE(r.err.find(b.option), std::string::npos) << b.args << "\n" << r.err;
  }
  // Blocks a table would leave out: refused, naming the block, nothing written.
  for (const auto& [key, patch] : std::vector<std::pair<std::string, json>>{
           {"subsurface", {{"subsurface", {{"depths", "0:1e-3:4"}}}}},
           {"materials.base.yield", {{"materials", {{"base", {{"yield", {{"von_mises", 8e8}}}}}}}}},
           {"accuracy.target", {{"accuracy", {{"target", 1e-3}}}}},
           {"materials.base.thermal",
            {{"materials", {{"base", {{"thermal", {{"conductivity", 50.0}, {"diffusivity", 1.4e-5}}}}},
                            {"body", {{"thermal", {{"conductivity", 50.0}, {"diffusivity", 1.4e-5}}}}}}}}}}) {
    json doc = dc::test::example_json("rolling-sphere");
    doc["grid"] = {{"nx", 16}, {"ny", 16}, {"extent", 1.1}};
    doc.merge_patch(patch);
    std::ofstream(dir_ / "beyond.json") << doc.dump();
    const auto r = run("table beyond.json --creepage 0,1e-3 -q --out beyond");
    EXPECT_EQ(r.code, 2) << key << "\n" << r.err;
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "beyond")) << key;
  }
  // Not a rolling case: the key says why.
  std::ofstream(dir_ / "hertz.json") << dc::test::example_json("hertz-sphere").dump();
  const auto r = run("table hertz.json --creepage 0,1e-3 -q --out tab");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("problem"), std::string::npos) << r.err;
}

}  // namespace
