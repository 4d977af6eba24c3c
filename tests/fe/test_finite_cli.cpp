// problem "finite" from the command line: the bundled finite-hemisphere example solves, writes
// summary.json with the body's keys and body.vtu, and follows Hertz for the pair; bad fe_body
// input is an input error naming the key.
#include <cmath>
#include <fstream>
#include <functional>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "hertz.hpp"
#include "material.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

class FiniteCli : public dc::test::CliTest {
 protected:
  std::string case_file(const std::function<void(json&)>& edit) const {
    json doc = dc::test::example_json("finite-hemisphere");
    edit(doc);
    std::ofstream(dir_ / "case.json") << doc.dump(2);
    return "case.json";
  }
  void expect_rejected(const std::function<void(json&)>& edit, const std::string& key) const {
    const dc::test::CliResult r = run("solve " + case_file(edit));
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("error: " + key + ":"), std::string::npos) << "stderr: " << r.err;
  }
};

TEST_F(FiniteCli, HemisphereExampleSolvesWithBodyOutputs) {
  const dc::test::CliResult r = run("solve " + dc::test::shell_quote(dc::test::example_path("finite-hemisphere")) +
                                    " --out out");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(dc::test::slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(s["problem"], "finite");
  EXPECT_EQ(s["profile"], "fe_body");  // the body is its mesh, not a profile or a rigid stand-in
  EXPECT_EQ(s["materials"]["body"]["fe_body"], "hemisphere");
  EXPECT_GT(s["body_dofs"].get<int>(), 1000);
  EXPECT_GT(s["max_body_displacement"].get<double>(), 0.0);
  EXPECT_GE(s["factorisation_time_s"].get<double>(), 0.0);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "body.vtu"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "fields.csv"));
  // Plots as for the local problems (none, without failing, where gnuplot is missing).
  ASSERT_TRUE(s["files"].contains("plots"));
  for (const auto& p : s["files"]["plots"]) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / p.get<std::string>())) << p;
  }
  if (!s["files"]["plots"].empty()) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / "contact_map.svg"));
  }
  // Hertz for the pair (both steel): peak pressure within 5 % (the mesh error, see test_finite_contact).
  const dc::MaterialPair pair{dc::Elastic::from_E_nu(2.1e11, 0.3), dc::Elastic::from_E_nu(2.1e11, 0.3)};
  const json c = dc::test::example_json("finite-hemisphere");
  const auto h = dc::hertz::sphere(c["fe_body"]["radius"].get<double>(), c["normal"]["force"].get<double>(), pair.E_star());
  EXPECT_NEAR(s["max_pressure"].get<double>(), h.p0, 0.05 * h.p0);
}

TEST_F(FiniteCli, CoarseContactFaceIsAWarningNamingContactSize) {
  // Face elements as large as the contact (a = 0.60 mm): the pressure is not resolved. The run
  // finishes (exit 0) and says so on stderr and in summary.json's limits; the example, with the
  // default contact_size (an eighth of the grid's reach: a / 5), gives no warning.
  const dc::test::CliResult r =
      run("solve " + case_file([](json& d) { d["fe_body"]["contact_size"] = 6e-4; }) + " --out coarse");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: fe_body.contact_size:"), std::string::npos) << r.err;
  const json s = json::parse(dc::test::slurp(dir_ / "coarse" / "summary.json"));
  ASSERT_EQ(s["limits"].size(), 1u) << s["limits"].dump();
  EXPECT_EQ(s["limits"][0]["key"], "fe_body.contact_size");
  EXPECT_EQ(s["limits"][0]["level"], "warning");
  EXPECT_FALSE(s["limits"][0]["accepted"].get<bool>());  // no key of the case accepted it
  EXPECT_GT(s["contact_face_element_size"].get<double>(), 2e-4);
  EXPECT_FALSE(s["remeshed"].get<bool>());  // a given contact_size is the case's choice

  const dc::test::CliResult fine = run("solve " + case_file([](json&) {}) + " --out fine");
  ASSERT_EQ(fine.code, 0) << fine.err;
  EXPECT_EQ(fine.err.find("warning: fe_body.contact_size"), std::string::npos) << fine.err;
  const json f = json::parse(dc::test::slurp(dir_ / "fine" / "summary.json"));
  EXPECT_TRUE(f["limits"].empty()) << f["limits"].dump();
  EXPECT_LT(f["contact_face_element_size"].get<double>(), 2e-4);
}

TEST_F(FiniteCli, SoftBodyWithCoarseFaceIsAWarningNamingContactSize) {
  // The example's body 30 times as compliant as the half-space, with faces of 1.3 grid cells
  // given: the face does not resolve the grid's cells (face_cell_bound: 0.73 cells). A warning
  // naming fe_body.contact_size whatever the solver made of it.
  const dc::test::CliResult r = run("solve " + case_file([](json& d) {
                                      d["fe_body"]["material"]["E"] = 7e9;
                                      d["fe_body"]["contact_size"] = 2e-4;
                                      d["grid"]["x"] = {-1.8e-3, 1.8e-3};
                                      d["grid"]["y"] = {-1.8e-3, 1.8e-3};
                                      d["solver"]["backend"] = "ipopt";
                                    }) + " --out soft");
  EXPECT_NE(r.err.find("warning: fe_body.contact_size: the body is 30 times as compliant"), std::string::npos)
      << r.err;
}

TEST_F(FiniteCli, DefaultFaceIsRemeshedToAContactSmallAgainstTheGrid) {
  // The example on a grid three times its contact's radius (a = 0.60 mm, +-1.8 mm, 48 x 48): the
  // grid's default contact_size (reach / 8 = 0.37 a) does not resolve the contact, so the run
  // meshes the face again at a sixth of the half-width it found and solves once more. Then no
  // warning, the face within a third of the half-width, and Hertz for the pair: p0 within 3 %
  // (the mesh error at a / 6, docs/finite.md).
  const dc::test::CliResult r = run("solve " + case_file([](json& d) {
                                      d.at("fe_body").erase("contact_size");
                                      d["grid"] = {{"nx", 48}, {"ny", 48}, {"x", {-1.8e-3, 1.8e-3}}, {"y", {-1.8e-3, 1.8e-3}}};
                                    }) + " --out wide");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("remeshing:"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning:"), std::string::npos) << r.err;
  const json s = json::parse(dc::test::slurp(dir_ / "wide" / "summary.json"));
  EXPECT_TRUE(s["remeshed"].get<bool>());
  EXPECT_TRUE(s["limits"].empty()) << s["limits"].dump();
  const double half_width = s["contact_half_width_x"].get<double>();
  EXPECT_LT(s["contact_face_element_size"].get<double>(), half_width / 3.0);
  const dc::MaterialPair pair{dc::Elastic::from_E_nu(2.1e11, 0.3), dc::Elastic::from_E_nu(2.1e11, 0.3)};
  const json c = dc::test::example_json("finite-hemisphere");
  const auto h = dc::hertz::sphere(c["fe_body"]["radius"].get<double>(), c["normal"]["force"].get<double>(), pair.E_star());
  EXPECT_NEAR(s["max_pressure"].get<double>(), h.p0, 0.03 * h.p0);
}

TEST_F(FiniteCli, ContactTruncatedByTheGridIsAnErrorUnlessAccepted) {
  // The example's contact (a = 0.60 mm) on a grid of +-0.45 mm: the pressure is cut at the
  // grid's edge. As for the local problems: exit 2 naming grid, results written; accepted with
  // grid.allow_edge_contact (a warning).
  const auto narrow = [](json& d) {
    d["grid"]["x"] = {-4.5e-4, 4.5e-4};
    d["grid"]["y"] = {-4.5e-4, 4.5e-4};
  };
  const dc::test::CliResult r = run("solve " + case_file(narrow) + " --out cut");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("error: grid: the contact reaches the edge of the grid"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "cut" / "summary.json"));

  const dc::test::CliResult accepted = run("solve " + case_file([&](json& d) {
                                             narrow(d);
                                             d["grid"]["allow_edge_contact"] = true;
                                           }) + " --out accepted");
  EXPECT_EQ(accepted.code, 0) << accepted.err;
  EXPECT_NE(accepted.err.find("warning: grid: the contact reaches the edge"), std::string::npos) << accepted.err;
}

TEST_F(FiniteCli, ValidateDescribesTheFiniteElementBody) {
  const dc::test::CliResult r =
      run("validate " + dc::test::shell_quote(dc::test::example_path("finite-hemisphere")));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("body:     finite elements (fe_body)"), std::string::npos) << r.out;
  // The example leaves contact_size to the grid: an eighth of its reach (0.9 mm).
  EXPECT_NE(r.out.find("face:     contact_size at most 0.0001125 m (an eighth of the grid's reach)"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("rigid"), std::string::npos) << r.out;
}

TEST_F(FiniteCli, BadBodyInputNamesTheKey) {
  expect_rejected([](json& d) { d["fe_body"]["shape"] = "mesh"; d["fe_body"]["mesh"] = "missing.msh"; }, "fe_body.mesh");
  expect_rejected([](json& d) { d["fe_body"]["material"]["nu"] = 0.6; }, "fe_body.material.nu");
  expect_rejected([](json& d) { d["fe_body"].erase("density"); }, "fe_body.density");
  expect_rejected([](json& d) { d["fe_body"]["radius"] = -1.0; }, "fe_body.radius");
  expect_rejected([](json& d) { d["fe_body"]["colour"] = "red"; }, "fe_body.colour");
  expect_rejected([](json& d) { d.erase("fe_body"); }, "fe_body");
  expect_rejected([](json& d) { d["profile"] = {{"type", "sphere"}, {"radius", 0.01}}; }, "profile");
  expect_rejected([](json& d) { d["fe_body"]["program"] = "dense"; }, "fe_body.program");
  expect_rejected([](json& d) { d["fe_body"]["load_line"] = {0.0, 0.0}; d["fe_body"]["tilt"] = {0.0, 0.0}; },
                  "fe_body.load_line");
  expect_rejected([](json& d) { d["fe_body"]["load_line"] = {1e-4}; }, "fe_body.load_line");
  expect_rejected([](json& d) { d["fe_body"]["load_line"] = {1e-4, 0.0}; d["normal"] = {{"approach", 1e-6}}; },
                  "fe_body.load_line");
  // The sparse form is Ipopt's: another backend is an input error, not a silent change of program.
  expect_rejected([](json& d) { d["fe_body"]["program"] = "sparse"; d["solver"]["backend"] = "native"; },
                  "solver.backend");
  // The grid far from the body: no face over it.
  expect_rejected([](json& d) { d["grid"]["x"] = {0.5, 0.6}; }, "fe_body");
}
