// `dyncontact compare` on the bundled examples/finite-torsion.json (a 16k-dof hemisphere on a
// 24^2 grid, torsion by moment, partial slip): the condensed program by the native solver and
// by Ipopt (1152 tractions: the exact Hessian of the dense condensed compliance) and the sparse
// saddle form by Ipopt are all certified, and the two Ipopt runs' tractions and pressures are
// within the square root of the certificate's tolerance of the native solution (relative to
// their peaks). About two minutes.
#include <cmath>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

using json = nlohmann::json;

class FiniteTorsionCompare : public dc::test::CliTest {};

TEST_F(FiniteTorsionCompare, AllThreeFormsCertifiedAndAgreeOnTheBundledExample) {
  const json example = dc::test::example_json("finite-torsion");
  const double certificate_tol = example["solver"].value("certificate_tol", 1e-6);
  const dc::test::CliResult r =
      run("compare " + dc::test::shell_quote(dc::test::example_path("finite-torsion")) +
          " --backends native,ipopt,ipopt-sparse -q --out out");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const json list = json::parse(dc::test::slurp(dir_ / "out" / "compare.json"));
  ASSERT_EQ(list.size(), 3u);
  const char* backends[] = {"native", "ipopt", "ipopt-sparse"};
  for (std::size_t k = 0; k < 3; ++k) {
    const json& e = list[k];
    SCOPED_TRACE(backends[k]);
    EXPECT_EQ(e["backend"], backends[k]);
    EXPECT_EQ(e["status"], "converged") << e.dump();
    double worst = 0.0;
    for (const auto& [name, value] : e["certificate"].items()) worst = std::max(worst, value.get<double>());
    EXPECT_LE(worst, certificate_tol);
    EXPECT_GT(e["summary"]["n_slip"].get<int>(), 0) << "partial slip";
    if (k == 0) continue;
    const json& d = e["difference_from_first"];
    EXPECT_EQ(d["backend"], "native");
    EXPECT_LT(d["traction"].get<double>(), std::sqrt(certificate_tol));
    EXPECT_LT(d["pressure"].get<double>(), std::sqrt(certificate_tol));
  }
}
