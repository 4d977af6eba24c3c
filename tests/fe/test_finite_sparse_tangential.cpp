// The sparse saddle form (a) of the tangential problem against the condensed program (b) on a
// tiny body (seconds): Ipopt's saddle point over (tau, v, a), with the friction disks
// |tau| <= f(p) for the sparse form's own pressure, gives the condensed program's tractions and
// rigid shift, certified with the condensed operators (friction law (2.4)-(2.5), gap function
// (4.24)); partial slip, so the disks are active. Larger bodies and torsion: slow_finite_saddle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "errors.hpp"
#include "fault_from_environment.hpp"
#include "mumps_ordering_hook.hpp"
#include "saddle_form.hpp"
#include "sparse_tangential_pair.hpp"

namespace dc {
namespace {

using fe::testing::expect_same_point;
using fe::testing::shift_by_force;
using fe::testing::solve_both;

constexpr std::array<int, 3> kSmall{2, 2, 1};  // about 4k dofs
constexpr double kHalfWidthTest = fe::testing::kHalfWidth;

TEST(FiniteSparseTangential, ShiftByForceAgreesWithTheCondensedProgram) {
  const long ordered_before = mumps_analyses_ordered_by_us();
  const fe::testing::Pair r = solve_both(shift_by_force(0.6), 8, kSmall, Backend::ipopt);
  expect_same_point(r);
  EXPECT_EQ(r.sparse.report.backend, "ipopt");
  // MUMPS took our ordering (nlp/process_tuning/mumps_ordering_hook.hpp) for the normal and the tangential
  // program's KKT matrix.
  if (mumps_ordering_hook_built()) {
    EXPECT_GE(mumps_analyses_ordered_by_us() - ordered_before, 2);
  }
  EXPECT_LT(r.sparse.amplitudes[0], 0.0) << "a force +F_x on the body meets a shift -s_x";
}

TEST(FiniteSparseTangential, OnlyIpoptTakesTheSparseForm) {
  const Grid g = Grid::make(3, 4, 4, -1.2e-3, 1.2e-3, -1.2e-3, 1.2e-3);
  FiniteContact a(fe::testing::hemisphere("sparse", kSmall), g, Elastic::from_E_nu(fe::testing::kE, fe::testing::kNu));
  for (const Backend backend : {Backend::nlopt, Backend::native}) {
    SolverOptions solver;
    solver.backend = backend;
    try {
      a.tangential_problem(FrictionLaw::coulomb(fe::testing::kMu)).step(shift_by_force(0.6), solver);
      FAIL() << to_string(backend) << " accepted the sparse form";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "solver.backend");
    }
  }
}


TEST(FiniteSparseTangential, NormalProblemFallsBackToNloptOnTheCondensedProgram) {
  // Ipopt made to fail on the sparse form: "auto" hands the same minimax, the body's rows
  // eliminated, to NLopt, which reaches the condensed program's certified point.
  const Grid g = Grid::make(3, 6, 6, -kHalfWidthTest, kHalfWidthTest, -kHalfWidthTest, kHalfWidthTest);
  const Elastic steel = Elastic::from_E_nu(fe::testing::kE, fe::testing::kNu);
  FiniteContact condensed(fe::testing::hemisphere("condensed", kSmall), g, steel);
  const FiniteNormalSolution reference = condensed.solve_normal({Control::force, fe::testing::kP}, SolverOptions{});
  ASSERT_EQ(reference.contact.report.status, SolveStatus::converged);
  FiniteContact sparse(fe::testing::hemisphere("sparse", kSmall), g, steel);
  test::install_faults_from_environment();
  setenv("DYNCONTACT_FAULT", "ipopt:fail", 1);
  const FiniteNormalSolution s = sparse.solve_normal({Control::force, fe::testing::kP}, SolverOptions{});
  unsetenv("DYNCONTACT_FAULT");
  ASSERT_EQ(s.contact.report.status, SolveStatus::converged) << s.contact.report.message;
  EXPECT_TRUE(s.contact.report.fallback_used);
  EXPECT_EQ(s.contact.report.backend, "nlopt (condensed program)");
  double peak = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < s.contact.pressure.size(); ++i) {
    peak = std::max(peak, reference.contact.pressure[i]);
    worst = std::max(worst, std::abs(s.contact.pressure[i] - reference.contact.pressure[i]));
  }
  EXPECT_LT(worst, std::sqrt(fe::testing::kCertificateTol) * peak);
  EXPECT_GT(s.max_body_displacement, 0.0);
}

TEST(FiniteSparseTangential, TangentialProblemFallsBackToTheCondensedProgram) {
  // Ipopt made to fail on the sparse form: "auto" hands the normal problem to NLopt and the
  // tangential program, the body's rows eliminated, to the native solver on the condensed
  // program; both reach the condensed program's certified point.
  test::install_faults_from_environment();
  setenv("DYNCONTACT_FAULT", "ipopt:fail", 1);
  const fe::testing::Pair r = solve_both(shift_by_force(0.6), 8, kSmall, Backend::automatic);
  unsetenv("DYNCONTACT_FAULT");
  expect_same_point(r);
  EXPECT_TRUE(r.sparse.report.fallback_used);
  EXPECT_EQ(r.sparse.report.backend, "native (condensed program)") << r.sparse.report.message;
  EXPECT_NE(r.sparse.report.message.find("ipopt: failed"), std::string::npos) << r.sparse.report.message;
  EXPECT_EQ(r.sparse.normal.report.backend, "nlopt (condensed program)");
}

}  // namespace
}  // namespace dc
