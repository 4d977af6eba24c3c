// Forced failures in the library (DYNCONTACT_FAULT: tests/support/fault_from_environment.hpp): `auto`
// falls back past a failing, stalling or NaN-returning backend and says so; a named backend is
// never replaced; a NaN never becomes a result; an outer loop that does not settle is reported
// not converged with its last iterate, all finite.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "fault_from_environment.hpp"
#include "fault_injection.hpp"
#include "normal_problem.hpp"
#include "tangential_support.hpp"

namespace dc {
namespace {

class ForcedFailures : public ::testing::Test {
 protected:
  void SetUp() override { test::install_faults_from_environment(); }
  void TearDown() override { unsetenv("DYNCONTACT_FAULT"); }
  static void inject(const char* faults) { setenv("DYNCONTACT_FAULT", faults, 1); }
};

struct SphereCase {
  MaterialPair m = test::steel_on_steel();
  test::SphereSetup setup = test::sphere_setup(12, 1.3, m, 0.01, 100.0);
};

bool all_finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

TEST_F(ForcedFailures, ParsesTargetsAndKinds) {
  inject("ipopt:fail,native:nan,outer:stall");
  EXPECT_EQ(injected_fault("ipopt"), Fault::fail);
  EXPECT_EQ(injected_fault("native"), Fault::nan);
  EXPECT_EQ(injected_fault("outer"), Fault::stall);
  EXPECT_EQ(injected_fault("nlopt"), Fault::none);
  inject("bogus:fail,nlopt:explode");  // ignored with a warning
  EXPECT_EQ(injected_fault("nlopt"), Fault::none);
  unsetenv("DYNCONTACT_FAULT");
  EXPECT_EQ(injected_fault("ipopt"), Fault::none);
}

TEST_F(ForcedFailures, NormalAutoFallsBackPastEachKind) {
  SphereCase c;
  SolverOptions s;  // auto, fallback on; 144 unknowns: Ipopt first
  for (const char* fault : {"ipopt:fail", "ipopt:stall", "ipopt:nan"}) {
    SCOPED_TRACE(fault);
    inject(fault);
    NormalProblem problem(c.setup.grid, c.m, c.setup.heights);
    const NormalSolution sol = problem.solve({Control::force, 100.0}, s);
    EXPECT_EQ(sol.report.status, SolveStatus::converged) << sol.report.message;
    EXPECT_TRUE(sol.report.fallback_used);
    EXPECT_EQ(sol.report.backend, "native");
    EXPECT_NE(sol.report.message.find("tried ipopt"), std::string::npos) << sol.report.message;
    EXPECT_TRUE(all_finite(sol.pressure));
  }
}

TEST_F(ForcedFailures, NamedBackendIsNeverReplacedAndNaNNeverKept) {
  SphereCase c;
  SolverOptions s;
  s.backend = Backend::native;  // fallback stays on: a named backend still does not fall back
  inject("native:nan");
  NormalProblem problem(c.setup.grid, c.m, c.setup.heights);
  const NormalSolution sol = problem.solve({Control::force, 100.0}, s);
  EXPECT_EQ(sol.report.status, SolveStatus::failed);
  EXPECT_EQ(sol.report.backend, "native");
  EXPECT_FALSE(sol.report.fallback_used);
  EXPECT_NE(sol.report.message.find("non-finite"), std::string::npos) << sol.report.message;
  EXPECT_TRUE(all_finite(sol.pressure));
}

TEST_F(ForcedFailures, TangentialAutoFallsBackOnAFailedCertificate) {
  SphereCase c;
  TangentialProblem problem = test::round_body_problem(c.setup.grid, c.m, 0.01, 0.3);
  TangentialLoad load;
  load.normal = {Control::force, 100.0};
  load.modes[0] = test::resultant(-15.0);
  load.modes[1] = test::resultant(0.0);
  inject("native:stall");  // 288 unknowns: native first; its stalled answer fails the certificate
  const TangentialSolution sol = problem.step(load, SolverOptions{});
  EXPECT_EQ(sol.report.status, SolveStatus::converged) << sol.report.message;
  EXPECT_TRUE(sol.report.fallback_used);
  EXPECT_NE(sol.report.backend, "native");
  EXPECT_NE(sol.report.message.find("native: not_converged"), std::string::npos) << sol.report.message;
}

TEST_F(ForcedFailures, OuterLoopThatDoesNotSettleIsReported) {
  SphereCase c;
  c.m.base = Elastic::from_E_nu(7e10, 0.33);  // kappa != 0: the alternation (4.26)-(4.27) runs
  TangentialProblem problem = test::round_body_problem(c.setup.grid, c.m, 0.01, 0.3);
  TangentialLoad load;
  load.normal = {Control::force, 100.0};
  load.modes[0] = test::resultant(-15.0);
  load.modes[1] = test::resultant(0.0);
  inject("outer:stall");
  const TangentialSolution sol = problem.step(load, SolverOptions{});
  EXPECT_FALSE(sol.outer.converged);
  EXPECT_EQ(sol.report.status, SolveStatus::not_converged);
  EXPECT_NE(sol.report.message.find("outer loop"), std::string::npos) << sol.report.message;
  EXPECT_TRUE(all_finite(sol.tx) && all_finite(sol.ty) && all_finite(sol.normal.pressure));
  EXPECT_NEAR(sol.resultants[0], -15.0, 1e-6 * 15.0);  // its last iterate, a solution of its own step
}

}  // namespace
}  // namespace dc
