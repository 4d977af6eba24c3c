// The NLopt fallback finished by the active-set polish (nlp/active_set_polish.hpp): on a random
// bound- and equality-constrained QP and on a disk-constrained one the polish takes a nearby
// point to the solution (KKT residual at round-off); and through the problems, NLopt alone
// certifies the normal and the tangential (Cattaneo) problems at the default tolerance and
// reports "polished". Small grids: each case takes well under a second.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "active_set_polish.hpp"
#include "dense_matrix_operator.hpp"
#include "normal_problem.hpp"
#include "tangential_support.hpp"

namespace dc {
namespace {

using test::DenseMatrixOperator;
using test::random_spd;

TEST(ActiveSetPolish, BoundsAndAnEqualityToRoundOff) {
  const int n = 40;
  DenseMatrixOperator Q(random_spd(n, 7));
  QuadraticProgram qp;
  qp.Q = &Q;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  qp.c.resize(n);
  for (auto& v : qp.c) v = u(rng);
  qp.lower.assign(n, 0.0);
  qp.upper.assign(n, kInf);
  qp.equalities.push_back({std::vector<double>(n, 1.0), 3.0});
  SolveOptions loose;
  loose.tol = 1e-3;  // a point near the solution, as NLopt leaves it
  loose.max_iter = 30;
  SolveOutcome near = solve_with_ipopt(qp, loose);
  ASSERT_EQ(near.x.size(), static_cast<std::size_t>(n));
  for (auto& v : near.x) v = std::max(v, 0.0);
  PolishResult r = polish_on_active_set(qp, near.x, near.equality_multipliers);
  EXPECT_TRUE(r.improved);
  EXPECT_LT(r.after, 1e-12) << "before " << r.before;
  EXPECT_LT(kkt_residual(qp, near.x, near.equality_multipliers), 1e-12);
  // At the solution there is nothing to improve: the point is kept.
  const std::vector<double> solved = near.x;
  r = polish_on_active_set(qp, near.x, near.equality_multipliers);
  EXPECT_FALSE(r.improved && r.before > 1e-12);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(near.x[i], solved[i], 1e-12);
}

TEST(NLoptPolish, NormalProblemCertifiesAndSaysPolished) {
  const MaterialPair m = test::steel_on_steel();
  const test::SphereSetup s = test::sphere_setup(16, 1.3, m, 0.01, 100.0);
  NormalProblem problem(s.grid, m, s.heights);
  SolverOptions solver;
  solver.backend = Backend::nlopt;
  const NormalSolution sol = problem.solve({Control::force, 100.0}, solver);
  EXPECT_EQ(sol.report.status, SolveStatus::converged) << sol.report.message;
  EXPECT_TRUE(sol.report.polished) << sol.report.message;
  EXPECT_LE(sol.report.certificate.worst(), solver.certificate_tol);
  EXPECT_NEAR(sol.force, 100.0, 1e-6 * 100.0);
}

TEST(NLoptPolish, CattaneoCertifiesWithNLoptAlone) {
  const MaterialPair m = test::steel_on_steel();
  const test::SphereSetup s = test::sphere_setup(12, 1.3, m, 0.01, 100.0);
  TangentialProblem problem = test::round_body_problem(s.grid, m, 0.01, 0.3);
  TangentialLoad load;
  load.normal = {Control::force, 100.0};
  load.modes[0] = test::resultant(-15.0);
  load.modes[1] = test::resultant(0.0);
  SolverOptions solver;
  solver.backend = Backend::nlopt;
  const TangentialSolution sol = problem.step(load, solver);
  EXPECT_EQ(sol.report.status, SolveStatus::converged) << sol.report.message;
  EXPECT_LE(sol.report.certificate.worst(), solver.certificate_tol);
  EXPECT_GT(sol.n_slip, 0);
  EXPECT_GT(sol.n_stick, 0);
}

}  // namespace
}  // namespace dc
