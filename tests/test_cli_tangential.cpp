// `dyncontact solve` / `compare` on tangential cases, run as a program: the summary.json keys
// of the contract (CASES.md), fields.csv with stick and slip, Carter's creepage for steady
// rolling, a loading history with one entry per step, and bad tangential inputs (exit 2,
// the message naming the key). Small grids and the Ipopt backend keep the file fast.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <set>
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

using dc::test::example_json;

/// Rows of fields.csv: the header, then the state column of every row.
struct FieldsFile {
  std::string header;
  std::vector<int> states;
};

FieldsFile read_fields(const fs::path& p) {
  FieldsFile f;
  std::ifstream in(p);
  std::getline(in, f.header);
  for (std::string line; std::getline(in, line);) {
    const auto comma = line.rfind(',');
    if (comma != std::string::npos) f.states.push_back(std::stoi(line.substr(comma + 1)));
  }
  return f;
}

class CliTangential : public dc::test::CliTest {
 protected:
  /// Writes example `name` with `edit` applied (Ipopt, no plots) and returns the file name.
  std::string case_file(const std::string& name, const std::function<void(json&)>& edit = {}) const {
    json doc = example_json(name);
    doc["solver"]["backend"] = "ipopt";
    doc["output"] = {{"plots", false}};
    if (edit) edit(doc);
    return write_case(doc, name + ".json");
  }

  /// Example `base` (on an 8-element grid) with `edit` must be rejected with exit 2 and a message
  /// naming `key`.
  void expect_rejected(const std::function<void(json&)>& edit, const std::string& key, const std::string& phrase = "",
                       const std::string& base = "cattaneo-sphere") const {
    const std::string file = case_file(base, [&](json& d) {
      d["grid"]["nx"] = 8;
      if (d["dimension"] == 3) d["grid"]["ny"] = 8;
      edit(d);
    });
    expect_input_error("solve " + file + " --out rejected -q", key);
    if (!phrase.empty()) {
      const std::string err = slurp(dir_ / "stderr.txt");
      EXPECT_NE(err.find(phrase), std::string::npos) << "stderr: " << err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "rejected" / "summary.json"));
  }
};

const char* const kTangentialExamples[] = {"cattaneo-sphere", "torsion-sphere", "carter-2d", "rolling-sphere",
                                           "spence-sphere",   "cattaneo-carter-2d"};

TEST_F(CliTangential, ExamplesMatchTheFilesAndValidate) {
  const Result list = run("example --list");
  EXPECT_EQ(list.code, 0);
  for (const char* name : kTangentialExamples) {
    SCOPED_TRACE(name);
    EXPECT_NE(list.out.find(name), std::string::npos);
    const Result e = run(std::string("example ") + name);
    EXPECT_EQ(e.code, 0);
    EXPECT_EQ(e.out, slurp(fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / (std::string(name) + ".json")));
    const json doc = json::parse(e.out);
    EXPECT_EQ(doc["name"], name);
    EXPECT_EQ(doc["problem"], "tangential");
    std::ofstream(dir_ / "example.json") << e.out;
    const Result v = run("validate example.json");
    EXPECT_EQ(v.code, 0) << v.err;
  }
}

TEST_F(CliTangential, CattaneoSphereWritesTheContract) {
  // 16 x 16 instead of the example's 32 x 32: the same physics in a second.
  const std::string file = case_file("cattaneo-sphere", [](json& d) {
    d["grid"]["nx"] = 16;
    d["grid"]["ny"] = 16;
  });
  const Result r = run("solve " + file + " --out result");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("tangential force"), std::string::npos) << r.out;
  const fs::path out = dir_ / "result";
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  const json s = json::parse(slurp(out / "summary.json"));
  for (const char* key : {"schema", "name", "problem", "dimension", "solver", "normal_force", "approach",
                          "contact_area", "max_pressure", "n_contact", "tangential_force", "twisting_moment",
                          "creepage", "spin", "rigid_shift", "rotation", "n_stick", "n_slip", "stick_area",
                          "outer_iterations", "outer_last_change", "marching_steps"})
    EXPECT_TRUE(s.contains(key)) << key;
  for (const char* key : {"backend", "status", "iterations", "time_s", "objective", "fallback_used", "certificate"})
    EXPECT_TRUE(s["solver"].contains(key)) << key;
  for (const char* key : {"complementarity", "friction_law", "gap_function"})
    EXPECT_TRUE(s["solver"]["certificate"].contains(key)) << key;
  EXPECT_EQ(s["name"], "cattaneo-sphere");
  EXPECT_EQ(s["problem"], "tangential");
  EXPECT_EQ(s["solver"]["status"], "converged");
  EXPECT_EQ(s["solver"]["backend"], "ipopt");
  // The prescribed force, on the body.
  ASSERT_TRUE(s["tangential_force"].is_array());
  ASSERT_EQ(s["tangential_force"].size(), 2u);
  EXPECT_NEAR(s["tangential_force"][0].get<double>(), -15.0, 1e-6);
  EXPECT_NEAR(s["tangential_force"][1].get<double>(), 0.0, 1e-6);
  EXPECT_NEAR(s["normal_force"].get<double>(), 100.0, 1e-3);
  // Shift regime: a rigid shift (towards +x, opposite to the force on the body), no creepage.
  ASSERT_TRUE(s["rigid_shift"].is_array());
  EXPECT_GT(s["rigid_shift"][0].get<double>(), 0.0);
  EXPECT_TRUE(s["creepage"].is_null());
  const int n_stick = s["n_stick"].get<int>(), n_slip = s["n_slip"].get<int>();
  EXPECT_GT(n_stick, 0);
  EXPECT_GT(n_slip, 0);
  EXPECT_EQ(n_stick + n_slip, s["n_contact"].get<int>());
  const double area = s["grid"]["dx"].get<double>() * s["grid"]["dy"].get<double>();
  EXPECT_NEAR(s["stick_area"].get<double>(), n_stick * area, 1e-9 * area);

  const FieldsFile f = read_fields(out / "fields.csv");
  EXPECT_EQ(f.header, "x,y,p,tx,ty,sx,sy,state");
  EXPECT_EQ(f.states.size(), 16u * 16u);
  const std::multiset<int> states(f.states.begin(), f.states.end());
  EXPECT_EQ(static_cast<int>(states.count(1)), n_stick);
  EXPECT_EQ(static_cast<int>(states.count(2)), n_slip);
  EXPECT_GT(states.count(0), 0u);
}

/// The carter-2d example solved with `backend`: Carter's creepage, reported as a creepage.
void check_carter_summary(const json& s) {
  EXPECT_EQ(s["solver"]["status"], "converged");
  EXPECT_EQ(s["dimension"], 2);
  EXPECT_TRUE(s["rigid_shift"].is_null());
  const double E = 2.1e11, nu = 0.3, R = 0.02, P = 1.0e5, mu = 0.3, F = -15000.0;
  const double E_star = E / (2.0 * (1.0 - nu * nu));
  const double a = std::sqrt(4.0 * P * R / (std::numbers::pi * E_star));
  const double carter = mu * a / R * (1.0 - std::sqrt(1.0 - std::abs(F) / (mu * P)));
  EXPECT_NEAR(s["tangential_force"][0].get<double>(), F, 1e-6 * std::abs(F));
  ASSERT_TRUE(s["creepage"].is_array());
  const double xi = s["creepage"][0].get<double>();
  EXPECT_GT(xi, 0.0);  // a braking force on the body: the body creeps forwards (F = -sgn(xi)|F|)
  EXPECT_NEAR(std::abs(xi), carter, 0.03 * carter) << "Carter |xi| = " << carter;
  EXPECT_EQ(s["n_stick"].get<int>() + s["n_slip"].get<int>(), s["n_contact"].get<int>());
  EXPECT_GT(s["n_stick"].get<int>(), 0);
  EXPECT_GT(s["n_slip"].get<int>(), 0);
}

TEST_F(CliTangential, CarterRollingCreepageByMarching) {
  const Result r = run("solve " + case_file("carter-2d") + " --out carter -q");  // ipopt: marching
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "carter" / "summary.json"));
  EXPECT_GT(s["marching_steps"].get<int>(), 0);
  check_carter_summary(s);
}

TEST_F(CliTangential, CarterRollingCreepageByNewton) {
  const std::string file = case_file("carter-2d", [](json& d) { d["solver"]["backend"] = "auto"; });
  const Result r = run("solve " + file + " --out carter-newton");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("steady state by Newton"), std::string::npos) << r.out;
  const json s = json::parse(slurp(dir_ / "carter-newton" / "summary.json"));
  EXPECT_EQ(s["marching_steps"].get<int>(), 0);
  EXPECT_GT(s["newton_iterations"].get<int>(), 0);
  check_carter_summary(s);
}

TEST_F(CliTangential, LoadingHistoryWritesEveryStep) {
  // The example's own backend (auto: native first): the history's files are checked here,
  // Ipopt's kappa alternation in the slow validations.
  const std::string file = case_file("spence-sphere", [](json& d) {
    d["grid"]["nx"] = 16;
    d["grid"]["ny"] = 16;
    d["solver"]["backend"] = "auto";
  });
  const Result r = run("solve " + file + " --out history");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const fs::path out = dir_ / "history";
  const json s = json::parse(slurp(out / "summary.json"));
  ASSERT_TRUE(s.contains("steps"));
  ASSERT_EQ(s["steps"].size(), 3u);
  const double loads[] = {50.0, 100.0, 150.0};
  for (std::size_t k = 0; k < 3; ++k) {
    SCOPED_TRACE(k);
    const json& st = s["steps"][k];
    for (const char* key : {"normal_force", "tangential_force", "twisting_moment", "rigid_shift", "n_stick", "n_slip",
                            "stick_area", "n_contact", "solver"})
      EXPECT_TRUE(st.contains(key)) << key;
    EXPECT_NEAR(st["normal_force"].get<double>(), loads[k], 1e-6 * loads[k]);
    EXPECT_EQ(st["solver"]["status"], "converged");
    EXPECT_NEAR(st["tangential_force"][0].get<double>(), 0.0, 1e-6);
    const std::string name = "fields_" + std::to_string(k) + ".csv";
    EXPECT_EQ(st["fields"], name);
    EXPECT_TRUE(fs::exists(out / name)) << name;
    EXPECT_EQ(st["n_stick"].get<int>() + st["n_slip"].get<int>(), st["n_contact"].get<int>());
  }
  // The contact grows with the load; the top level is the last step.
  EXPECT_LT(s["steps"][0]["n_contact"].get<int>(), s["steps"][2]["n_contact"].get<int>());
  EXPECT_EQ(s["n_contact"], s["steps"][2]["n_contact"]);
  EXPECT_EQ(s["normal_force"], s["steps"][2]["normal_force"]);
  EXPECT_EQ(slurp(out / "fields.csv"), slurp(out / "fields_2.csv"));
  // Dissimilar materials (kappa != 0): the indentation alone makes part of the contact slip.
  EXPECT_GT(s["n_slip"].get<int>(), 0);
  EXPECT_GT(s["n_stick"].get<int>(), 0);
}

/// Hertz half-width a of the carter-2d / cattaneo-carter-2d cylinder (R = 20 mm, 100 kN/m, steel).
double carter_example_half_width() {
  const double E = 2.1e11, nu = 0.3, R = 0.02, P = 1.0e5;
  const double E_star = E / (2.0 * (1.0 - nu * nu));
  return std::sqrt(4.0 * P * R / (std::numbers::pi * E_star));
}

TEST_F(CliTangential, RollingHistoryWritesEveryStep) {
  // The bundled Cattaneo-to-Carter history (no travel, then 0.5a, 0.5a, 1a, 1a at F = -mu P/2),
  // on the native backend (Ipopt takes seconds for its 126 marching steps).
  const std::string file = case_file("cattaneo-carter-2d", [](json& d) { d["solver"]["backend"] = "native"; });
  const Result r = run("solve " + file + " --out rolling");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("history (5 steps)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rolled"), std::string::npos) << r.out;
  const fs::path out = dir_ / "rolling";
  const json s = json::parse(slurp(out / "summary.json"));
  ASSERT_TRUE(s.contains("steps"));
  ASSERT_EQ(s["steps"].size(), 5u);
  EXPECT_EQ(s["all_steps_converged"], true);
  const double a = carter_example_half_width(), dx = s["grid"]["dx"].get<double>();
  const json history = example_json("cattaneo-carter-2d")["tangential"]["history"];
  double total = 0.0;
  for (std::size_t k = 0; k < 5; ++k) {
    SCOPED_TRACE(k);
    const json& st = s["steps"][k];
    EXPECT_EQ(st["solver"]["status"], "converged");
    EXPECT_NEAR(st["tangential_force"][0].get<double>(), -15000.0, 1e-6 * 15000.0);
    EXPECT_NEAR(st["normal_force"].get<double>(), 1e5, 1e-6 * 1e5);
    // The distance rolled is the nearest whole number of elements.
    const double asked = history[k]["distance"].get<double>();
    EXPECT_NEAR(st["distance"].get<double>(), asked, 0.5 * dx);
    total += st["distance"].get<double>();
    EXPECT_NEAR(st["total_distance"].get<double>(), total, 1e-12);
    EXPECT_EQ(st["marching_steps"].get<int>(), static_cast<int>(std::lround(asked / dx)));
    EXPECT_EQ(st["fields"], "fields_" + std::to_string(k) + ".csv");
    EXPECT_TRUE(fs::exists(out / ("fields_" + std::to_string(k) + ".csv")));
    EXPECT_EQ(st["n_stick"].get<int>() + st["n_slip"].get<int>(), st["n_contact"].get<int>());
    if (k == 0) {
      // No travel: Cattaneo's shift (towards +x under a braking force), no creepage.
      EXPECT_TRUE(st["creepage"].is_null());
      EXPECT_GT(st["rigid_shift"][0].get<double>(), 0.0);
    } else {
      EXPECT_TRUE(st["rigid_shift"].is_null());
      EXPECT_GT(st["creepage"][0].get<double>(), 0.0);
    }
  }
  EXPECT_NEAR(total, 3 * a, 2 * dx);
  // After 3a Carter's creepage, within the 3 % CarterRollingCreepage allows on this grid.
  const double carter = 0.3 * a / 0.02 * (1.0 - std::sqrt(0.5));
  EXPECT_NEAR(s["creepage"][0].get<double>(), carter, 0.03 * carter);
  EXPECT_LT(s["steps"][1]["creepage"][0].get<double>(), s["steps"][4]["creepage"][0].get<double>());
  EXPECT_EQ(slurp(out / "fields.csv"), slurp(out / "fields_4.csv"));
}

TEST_F(CliTangential, RollingHistoryStepsTheNormalLoad) {
  // A step's "normal" holds from that step on; each step reports its own load and Hertz reference.
  const std::string file = case_file("cattaneo-carter-2d", [](json& d) {
    d["solver"]["backend"] = "native";
    d["grid"]["nx"] = 40;
    d["tangential"]["history"] = json::parse(R"([{"force": [-15000.0], "distance": 0.0},
        {"normal": {"force": 8.0e4}, "distance": 5e-5}, {"distance": 5e-5}])");
  });
  const Result r = run("solve " + file + " --out stepped -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(slurp(dir_ / "stepped" / "summary.json"));
  ASSERT_EQ(s["steps"].size(), 3u);
  const double loads[] = {1e5, 8e4, 8e4};
  for (std::size_t k = 0; k < 3; ++k) {
    SCOPED_TRACE(k);
    const json& st = s["steps"][k];
    EXPECT_NEAR(st["normal_force"].get<double>(), loads[k], 1e-6 * loads[k]);
    EXPECT_NEAR(st["hertz"]["normal_force"].get<double>(), loads[k], 1e-9 * loads[k]);
    EXPECT_NEAR(st["tangential_force"][0].get<double>(), -15000.0, 1e-6 * 15000.0);
    EXPECT_EQ(st["solver"]["status"], "converged");
  }
  EXPECT_LT(s["steps"][1]["hertz"]["contact_area"].get<double>(), s["steps"][0]["hertz"]["contact_area"].get<double>());
  EXPECT_NEAR(s["normal_force"].get<double>(), 8e4, 1e-6 * 8e4);
}

TEST_F(CliTangential, BadRollingHistoryInputsNameTheKey) {
  const std::string base = "cattaneo-carter-2d";
  expect_rejected([](json& d) { d["tangential"]["history"][1].erase("distance"); }, "tangential.history[1].distance",
                  "required", base);
  expect_rejected([](json& d) { d["tangential"]["history"][2]["distance"] = -1e-5; },
                  "tangential.history[2].distance", ">= 0", base);
  expect_rejected([](json& d) { d["tangential"]["history"][2]["distance"] = "far"; },
                  "tangential.history[2].distance", "must be a number", base);
  expect_rejected([](json& d) { d["tangential"]["history"][1]["shift"] = 1e-6; }, "tangential.history[1].shift",
                  "unknown key", base);
  expect_rejected([](json& d) { d["tangential"]["history"][3]["creepage"] = "x"; },
                  "tangential.history[3].creepage", "", base);
  expect_rejected([](json& d) { d["tangential"]["max_steps"] = 100; }, "tangential.max_steps", "steady rolling only",
                  base);
  expect_rejected([](json& d) { d["tangential"]["history"] = json::array(); }, "tangential.history", "non-empty",
                  base);
}

TEST_F(CliTangential, BadTangentialInputsNameTheKey) {
  expect_rejected([](json& d) { d["tangential"]["forse"] = {1.0, 0.0}; }, "tangential.forse", "unknown key");
  expect_rejected([](json& d) { d.erase("friction"); }, "friction");
  expect_rejected([](json& d) { d["friction"]["mu"] = -0.3; }, "friction.mu");
  expect_rejected([](json& d) { d["tangential"]["force"] = {-40.0, 0.0}; }, "tangential.force[0]", "gross sliding");
  // Each component below mu P = 30 N, together above it.
  expect_rejected([](json& d) { d["tangential"]["force"] = {-25.0, -20.0}; }, "tangential.force", "gross sliding");
  expect_rejected(
      [](json& d) {
        d["tangential"].erase("creepage");
        d["tangential"]["force"] = {-25.0, -20.0};
      },
      "tangential.force", "gross sliding", "rolling-sphere");
  expect_rejected([](json& d) { d["tangential"]["regime"] = "skid"; }, "tangential.regime");
}

TEST_F(CliTangential, CompareReportsTractionDifferences) {
  const std::string file = case_file("cattaneo-sphere", [](json& d) {
    d["grid"]["nx"] = 12;
    d["grid"]["ny"] = 12;
  });
  const Result r = run("compare " + file + " --backends ipopt,ipopt --out cmp -q");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("d_traction"), std::string::npos) << r.out;
  const json list = json::parse(slurp(dir_ / "cmp" / "compare.json"));
  ASSERT_EQ(list.size(), 2u);
  for (const auto& e : list) {
    EXPECT_EQ(e["status"], "converged");
    EXPECT_TRUE(e["certificate"].contains("friction_law"));
    EXPECT_NEAR(e["summary"]["tangential_force"][0].get<double>(), -15.0, 1e-6);
  }
  EXPECT_LT(list[1]["difference_from_first"]["traction"].get<double>(), 1e-6);
  EXPECT_LT(list[1]["difference_from_first"]["tangential_force"].get<double>(), 1e-6);
}

}  // namespace
