// The preconditioned conjugate gradients of the normal problem (nlp/preconditioned_normal.cpp):
// the same answers as the unpreconditioned Polonsky-Keer iteration, iteration counts that do
// not grow with the grid, and warm starts that finish at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hertz.hpp"
#include "native_solvers.hpp"
#include "normal_problem.hpp"
#include "profile.hpp"
#include "scaled_operator.hpp"
#include "solver_support.hpp"

namespace dc {
namespace {


struct SphereCase {
  Grid grid;
  std::vector<double> heights;
  hertz::SphereSolution hz;
};

SphereCase sphere(int n, double R = 0.01, double P = 100.0) {
  const MaterialPair m = test::steel_on_aluminium();
  const auto hz = hertz::sphere(R, P, m.E_star());
  const double L = 1.3 * hz.a;
  const Grid g = Grid::make(3, n, n, -L, L, -L, L);
  ProfileSpec prof;
  prof.type = ProfileType::sphere;
  prof.radius = R;
  return {g, profile_heights(prof, g), hz};
}

/// The scaled program of NormalProblem, for the solvers called directly.
struct Program {
  std::unique_ptr<LinearOperator> C;
  std::unique_ptr<ScaledOperator> Q;
  QuadraticProgram qp;
  double c0 = 1.0;
};

Program program(const SphereCase& s, bool force_control, double value) {
  Program p;
  p.C = HalfSpace(s.grid, test::steel_on_aluminium()).normal(OperatorKind::fft);
  p.c0 = p.C->diagonal(0);
  p.Q = std::make_unique<ScaledOperator>(*p.C, 1.0 / p.c0);
  const std::size_t n = s.grid.size();
  const double p_ref = s.hz.p0;
  p.qp.Q = p.Q.get();
  p.qp.c.resize(n);
  p.qp.lower.assign(n, 0.0);
  p.qp.upper.assign(n, kInf);
  const double delta = force_control ? 0.0 : value;
  for (std::size_t i = 0; i < n; ++i) p.qp.c[i] = (s.heights[i] - delta) / (p.c0 * p_ref);
  if (force_control) {
    LinearEquality eq;
    eq.a.assign(n, 1.0);
    eq.b = value / (s.grid.area() * p_ref);
    p.qp.equalities.push_back(eq);
  }
  return p;
}

void expect_same_solution(const SphereCase& s, bool force_control, double value) {
  Program p = program(s, force_control, value);
  SolveOptions o;
  o.tol = 1e-11;
  o.max_iter = 5000;
  const SolveOutcome plain = solve_normal_native(p.qp, o);
  const NormalPreconditioner M(*p.C, s.grid);
  const SolveOutcome pcg = solve_normal_native(p.qp, o, &M, p.c0);
  ASSERT_TRUE(plain.success) << plain.message;
  ASSERT_TRUE(pcg.success) << pcg.message;
  const double x_max = *std::max_element(plain.x.begin(), plain.x.end());
  double diff = 0.0;
  for (std::size_t i = 0; i < plain.x.size(); ++i) diff = std::max(diff, std::abs(plain.x[i] - pcg.x[i]));
  EXPECT_LT(diff, 1e-7 * x_max);
  EXPECT_LT(pcg.iterations, plain.iterations);
  if (force_control) {
    ASSERT_EQ(pcg.equality_multipliers.size(), 1u);
    EXPECT_NEAR(pcg.equality_multipliers[0], plain.equality_multipliers[0],
                1e-7 * std::abs(plain.equality_multipliers[0]));
  }
}

TEST(NormalPreconditioned, SameAnswerAsPolonskyKeerUnderForceAndApproachControl) {
  const SphereCase s = sphere(40);
  expect_same_solution(s, true, 100.0);
  expect_same_solution(s, false, s.hz.approach);
}

TEST(NormalPreconditioned, IterationsDoNotGrowWithTheGrid) {
  // The unpreconditioned iteration count grows roughly like the grid's edge (the condition
  // number of the 1/r kernel); the preconditioned one stays nearly level: from 32^2 to 128^2 it
  // needs at most half the plain iteration's additional iterations, and at most 10 more.
  std::vector<int> iterations, plain;
  for (int n : {32, 64, 128}) {
    const SphereCase s = sphere(n);
    NormalProblem problem(s.grid, test::steel_on_aluminium(), s.heights, OperatorKind::fft);
    const NormalSolution sol = problem.solve({Control::force, 100.0}, test::native_solver_spec(1000));
    ASSERT_EQ(sol.report.status, SolveStatus::converged) << sol.report.message;
    EXPECT_LT(std::abs(*std::max_element(sol.pressure.begin(), sol.pressure.end()) / s.hz.p0 - 1.0), 0.02) << n;
    iterations.push_back(sol.report.iterations);
    if (n == 64) continue;
    Program p = program(s, true, 100.0);
    SolveOptions o;
    o.max_iter = 1000;
    const SolveOutcome unpreconditioned = solve_normal_native(p.qp, o);
    ASSERT_TRUE(unpreconditioned.success) << unpreconditioned.message;
    plain.push_back(unpreconditioned.iterations);
  }
  std::printf("[ PCG ] iterations at 32^2, 64^2, 128^2: %d %d %d (unpreconditioned at 32^2, 128^2: %d %d)\n",
              iterations[0], iterations[1], iterations[2], plain[0], plain[1]);
  EXPECT_GT(plain[1], 1.5 * plain[0]);  // the growth the preconditioner removes is there
  EXPECT_LE(iterations[2] - iterations[0], 0.5 * (plain[1] - plain[0]));
  EXPECT_LE(iterations[2] - iterations[0], 10);
  EXPECT_LE(iterations[2], 30);
}

TEST(NormalPreconditioned, WarmStartFromTheSolutionFinishesAtOnce) {
  const SphereCase s = sphere(48);
  NormalProblem problem(s.grid, test::steel_on_aluminium(), s.heights, OperatorKind::fft);
  const SolverOptions solver = test::native_solver_spec(1000);
  const NormalSolution cold = problem.solve({Control::force, 100.0}, solver);
  ASSERT_EQ(cold.report.status, SolveStatus::converged);
  const NormalSolution warm = problem.solve({Control::force, 100.0}, solver);  // member warm state
  ASSERT_EQ(warm.report.status, SolveStatus::converged);
  EXPECT_LE(warm.report.iterations, 2);
  // A nearby load starts from the given pressure; a cleared start is cold again.
  problem.set_warm_start(cold.pressure);
  const NormalSolution near = problem.solve({Control::force, 105.0}, solver);
  problem.clear_warm_start();
  const NormalSolution near_cold = problem.solve({Control::force, 105.0}, solver);
  ASSERT_EQ(near.report.status, SolveStatus::converged);
  ASSERT_EQ(near_cold.report.status, SolveStatus::converged);
  EXPECT_LT(near.report.iterations, near_cold.report.iterations);
  for (std::size_t i = 0; i < near.pressure.size(); ++i)
    EXPECT_NEAR(near.pressure[i], near_cold.pressure[i], 1e-6 * s.hz.p0);
  EXPECT_THROW(problem.set_warm_start({1.0, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace dc
