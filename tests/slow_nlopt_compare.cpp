// `compare --backends ipopt,nlopt,native` passes (every backend certified, exit 0) on the bundled
// normal examples at 32^2 and on a 30 x 10 mm steel ellipsoid under 300 N (extent 1.3) at 24^2
// and 40^2: the NLopt fallback, finished by the active-set polish, certifies where it used to
// hover at the tolerance. Slow: Ipopt takes several seconds per 3-D case.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

using json = nlohmann::json;

class SlowNLoptCompare : public dc::test::CliTest {
 protected:
  void expect_compare_passes(json doc, const std::string& name) const {
    doc["output"] = {{"plots", false}};
    std::ofstream(dir_ / (name + ".json")) << doc.dump(2);
    const auto r = run("compare " + name + ".json --backends ipopt,nlopt,native --out " + name + " -q");
    EXPECT_EQ(r.code, 0) << r.out << r.err;
  }
};

TEST_F(SlowNLoptCompare, BundledExamplesAt32) {
  for (const char* example : {"hertz-sphere", "hertz-ellipse", "hertz-cylinder-2d"}) {
    SCOPED_TRACE(example);
    json doc = dc::test::example_json(example);
    doc["grid"]["nx"] = 32;
    if (doc["dimension"] == 3) doc["grid"]["ny"] = 32;
    expect_compare_passes(doc, example);
  }
}

TEST_F(SlowNLoptCompare, EllipsoidAt24And40) {
  for (int n : {24, 40}) {
    SCOPED_TRACE(n);
    json doc = dc::test::example_json("hertz-ellipse");
    doc["profile"] = {{"type", "ellipsoid"}, {"radius_x", 0.03}, {"radius_y", 0.01}};
    doc["normal"] = {{"force", 300.0}};
    doc["grid"] = {{"nx", n}, {"ny", n}, {"extent", 1.3}};
    expect_compare_passes(doc, "ellipsoid" + std::to_string(n));
  }
}

}  // namespace
