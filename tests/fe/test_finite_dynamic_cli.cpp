// problem "dynamic" with an fe_body from the command line: the bundled fe-hemisphere-drop
// example (its first steps) writes summary.json with the body's keys, a body_NNNN.vtu per
// snapshot and body.pvd listing them with their times; rolling input is an input error (exit 2)
// naming the key.
#include <fstream>
#include <functional>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

class FiniteDynamicCli : public dc::test::CliTest {
 protected:
  std::string case_file(const std::function<void(json&)>& edit) const {
    json doc = dc::test::example_json("fe-hemisphere-drop");
    edit(doc);
    std::ofstream(dir_ / "case.json") << doc.dump(2);
    return "case.json";
  }
};

TEST_F(FiniteDynamicCli, DropWritesBodyKeysAndASnapshotSeries) {
  // Ten steps into the impact (the body touches from the start), a snapshot every five.
  const std::string file = case_file([](json& d) {
    d["time"]["t_end"] = 10 * d["time"]["dt"].get<double>();
    d["output"]["plots"] = false;
  });
  const dc::test::CliResult r = run("solve " + file + " --out out");
  ASSERT_EQ(r.code, 0) << r.err;
  const json s = json::parse(dc::test::slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(s["status"], "completed");
  EXPECT_GT(s["body_dofs"].get<int>(), 1000);
  EXPECT_GT(s["max_body_displacement"].get<double>(), 0.0);
  EXPECT_GE(s["factorisation_time_s"].get<double>(), 0.0);
  EXPECT_EQ(s["models"]["contact_model_used"], "shift_torsion");
  EXPECT_GT(s["body"]["mass"].get<double>(), 0.0);
  ASSERT_EQ(s["files"]["snapshots"].size(), 2u);
  EXPECT_EQ(s["files"]["snapshots"][0]["body"], "body_0000.vtu");
  EXPECT_EQ(s["files"]["snapshots"][1]["body"], "body_0001.vtu");
  EXPECT_EQ(s["files"]["body_series"], "body.pvd");
  for (const char* f : {"body_0000.vtu", "body_0001.vtu"}) {
    const std::string vtu = dc::test::slurp(dir_ / "out" / f);
    for (const char* field : {"\"displacement\"", "\"stress\"", "\"von_mises\""})
      EXPECT_NE(vtu.find(field), std::string::npos) << f << " lacks " << field;
  }
  const std::string pvd = dc::test::slurp(dir_ / "out" / "body.pvd");
  EXPECT_NE(pvd.find("file=\"body_0000.vtu\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("file=\"body_0001.vtu\""), std::string::npos) << pvd;
}

TEST_F(FiniteDynamicCli, RollingIsAnInputErrorNamingTheKey) {
  const dc::test::CliResult r = run("solve " + case_file([](json& d) { d["body"]["initial"]["omega"] = {0, 20, 0}; }));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("error: body.initial.omega:"), std::string::npos) << r.err;
}
