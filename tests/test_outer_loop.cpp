// The normal-tangential alternation (4.26)-(4.27) with kappa != 0 in a loading history:
// warm-started from the previous step and Anderson-accelerated, it reaches the same states as
// steps started cold, stops on the coupling certificate, and needs fewer alternations.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "anderson_mixing.hpp"
#include "contact_closed_forms.hpp"
#include "normal_problem.hpp"
#include "proportional_predictor.hpp"
#include "tangential_support.hpp"

namespace dc {
namespace {

using test::amplitude;
using test::expect_certified;
using test::expect_same_state;

/// Spence-like indentation: a rigid sphere (R = 10 mm) pressed into an elastic body
/// (E = 70 GPa, Poisson's ratio nu: kappa != 0) up to P_max = 100 N, Coulomb friction mu, 24^2.
struct Indentation {
  static constexpr double P_max = 100.0;
  MaterialPair m;
  double mu;
  test::SphereSetup su;
  Indentation(double nu, double mu_)
      : m{Elastic::make_rigid(), Elastic::from_E_nu(7e10, nu)}, mu(mu_), su(test::sphere_setup(24, 1.2, m, 0.01, P_max)) {}
  TangentialProblem problem() const { return TangentialProblem(su.grid, m, su.heights, FrictionLaw::coulomb(mu)); }
};

TEST(OuterLoop, WarmStartedHistoryEqualsColdStartedSteps) {
  // Spence-like indentation of aluminium by a rigid sphere (beta = -0.09 kappa != 0), 5 steps.
  const Indentation in(0.45, 0.06);
  ASSERT_NE(in.m.kappa(), 0.0);
  const double P_max = Indentation::P_max;
  TangentialProblem warm = in.problem();
  TangentialProblem cold = in.problem();
  TangentialLoad load;
  load.modes = {amplitude(0.0), amplitude(0.0), amplitude(0.0)};
  const SolverOptions solver = test::native_tangential_solver();
  int warm_alternations = 0, cold_alternations = 0;
  for (int k = 1; k <= 5; ++k) {
    load.normal = {Control::force, P_max * k / 5.0};
    const TangentialSolution a = warm.step(load, solver);
    cold.forget_starting_points();
    const TangentialSolution b = cold.step(load, solver);
    expect_certified(a);
    expect_certified(b);
    EXPECT_TRUE(a.outer.converged);
    EXPECT_LE(a.outer.coupling_residual, 0.01 * solver.certificate_tol) << "step " << k;
    warm_alternations += a.outer.iterations;
    cold_alternations += b.outer.iterations;
    expect_same_state(a, b, "step " + std::to_string(k));
  }
  std::printf("[ outer loop ] alternations over 5 steps: warm %d, cold %d\n", warm_alternations, cold_alternations);
  EXPECT_LE(warm_alternations, cold_alternations);
}

TEST(OuterLoop, ProportionalHistoryStartsFromTheExtrapolatedState) {
  // Spence-like indentation (kappa != 0) in 10 equal load steps: from step 3 on the load continues
  // in proportion, and the alternation starts from the state extrapolated from the last two
  // steps. It reaches the same states as starting from the last step's state and as cold starts,
  // from a smaller first coupling residual, in fewer alternations.
  const Indentation in(0.0, 0.3);
  ASSERT_NE(in.m.kappa(), 0.0);
  const double P_max = Indentation::P_max;
  TangentialProblem predicted = in.problem();
  TangentialProblem previous = in.problem();
  TangentialProblem cold = in.problem();
  previous.set_extrapolation(false);
  TangentialLoad load;
  load.modes = {test::resultant(0.0), test::resultant(0.0), amplitude(0.0)};
  const SolverOptions solver = test::native_tangential_solver();
  const int steps = 10;
  int predicted_alternations = 0, previous_alternations = 0;
  for (int k = 1; k <= steps; ++k) {
    load.normal = {Control::force, P_max * k / static_cast<double>(steps)};
    const TangentialSolution a = predicted.step(load, solver);
    const TangentialSolution b = previous.step(load, solver);
    cold.forget_starting_points();
    const TangentialSolution c = cold.step(load, solver);
    for (const TangentialSolution* s : {&a, &b, &c}) {
      expect_certified(*s);
      EXPECT_TRUE(s->outer.converged);
      EXPECT_LE(s->outer.coupling_residual, 0.01 * solver.certificate_tol) << "step " << k;
    }
    expect_same_state(a, c, "extrapolated, step " + std::to_string(k));
    expect_same_state(b, c, "from the last state, step " + std::to_string(k));
    if (k >= 3) {
      EXPECT_LT(a.outer.first_residual, 0.5 * b.outer.first_residual) << "step " << k;
      predicted_alternations += a.outer.iterations;
      previous_alternations += b.outer.iterations;
    }
  }
  std::printf("[ outer loop ] alternations over steps 3-%d: extrapolated %d, from the last state %d\n", steps,
              predicted_alternations, previous_alternations);
  EXPECT_LT(predicted_alternations, previous_alternations);
}

TEST(OuterLoop, PressureIsCertifiedWithTheFinalTraction) {
  // The loop stops once the coupling residual is a hundredth of certificate_tol; the pressure's
  // certificate is then that of the gap (4.26) with the final traction, not of the one the
  // pressure was solved with: recomputed here from the solution alone.
  const Indentation in(0.0, 0.3);
  TangentialProblem problem = in.problem();
  TangentialLoad load;
  load.modes = {test::resultant(0.0), test::resultant(0.0), amplitude(0.0)};
  const SolverOptions solver = test::native_tangential_solver();
  for (int k = 1; k <= 2; ++k) {
    load.normal = {Control::force, Indentation::P_max * k / 2.0};
    const TangentialSolution s = problem.step(load, solver);
    expect_certified(s);
    ASSERT_GT(s.outer.iterations, 1);
    std::vector<double> tau(s.tx), shift;
    tau.insert(tau.end(), s.ty.begin(), s.ty.end());
    problem.normal_from_tangential()->apply(tau, shift);
    std::vector<double> h = in.su.heights;
    for (std::size_t i = 0; i < h.size(); ++i) h[i] += shift[i];
    const NormalProblem normal(in.su.grid, in.m, h);
    const Certificate c = normal.certify(s.normal.pressure, s.normal.approach, load.normal);
    const double allowance = 1e-12 + 1e-3 * s.outer.coupling_residual;
    EXPECT_NEAR(s.report.certificate.complementarity, c.complementarity, allowance) << "step " << k;
    EXPECT_NEAR(s.report.certificate.gap_violation, c.gap_violation, allowance) << "step " << k;
    EXPECT_LE(c.worst(), solver.certificate_tol) << "step " << k;
  }
}

TEST(OuterLoop, ProportionalLoadsAreRecognised) {
  using Load = ProportionalPredictor::Load;
  const Load a{{10.0, 0.0, 1e-6}, {1, 0, 0}}, b{{20.0, 0.0, 2e-6}, {1, 0, 0}};
  EXPECT_DOUBLE_EQ(ProportionalPredictor::ratio(a, b, {{30.0, 0.0, 3e-6}, {1, 0, 0}}), 1.0);
  EXPECT_DOUBLE_EQ(ProportionalPredictor::ratio(a, b, {{25.0, 0.0, 2.5e-6}, {1, 0, 0}}), 0.5);
  EXPECT_EQ(ProportionalPredictor::ratio(a, b, {{30.0, 0.0, 2e-6}, {1, 0, 0}}), 0.0);   // not in proportion
  EXPECT_EQ(ProportionalPredictor::ratio(a, b, {{10.0, 0.0, 1e-6}, {1, 0, 0}}), 0.0);   // reversed
  EXPECT_EQ(ProportionalPredictor::ratio(a, b, {{60.0, 0.0, 6e-6}, {1, 0, 0}}), 0.0);   // r = 4: too far
  EXPECT_EQ(ProportionalPredictor::ratio(a, b, {{30.0, 0.0, 3e-6}, {0, 0, 0}}), 0.0);   // other controls
  EXPECT_EQ(ProportionalPredictor::ratio(b, b, {{30.0, 0.0, 3e-6}, {1, 0, 0}}), 0.0);   // held: no direction
  // Extrapolation: tau linear, the pressure kept >= 0.
  ProportionalPredictor predictor;
  std::vector<double> tau, p;
  EXPECT_FALSE(predictor.predict(b, tau, p));
  predictor.record(a, {1.0, -1.0}, {3.0, 1.0});
  predictor.record(b, {2.0, -3.0}, {4.0, 0.5});
  ASSERT_TRUE(predictor.predict({{30.0, 0.0, 3e-6}, {1, 0, 0}}, tau, p));
  EXPECT_EQ(tau, (std::vector<double>{3.0, -5.0}));
  EXPECT_EQ(p, (std::vector<double>{5.0, 0.0}));
  predictor.clear();
  EXPECT_FALSE(predictor.predict({{30.0, 0.0, 3e-6}, {1, 0, 0}}, tau, p));
}

TEST(OuterLoop, IpoptAndNativeReachTheSameState) {
  // One Spence-like indentation step (kappa != 0) by each backend alone: both certified, the
  // same pressure, traction and stick set.
  const MaterialPair m{Elastic::make_rigid(), Elastic::from_E_nu(7e10, 0.33)};
  ASSERT_NE(m.kappa(), 0.0);
  const auto su = test::sphere_setup(12, 1.3, m, 0.01, 150.0);
  TangentialLoad load;
  load.modes = {amplitude(0.0), amplitude(0.0), amplitude(0.0)};
  load.normal = {Control::force, 150.0};
  SolverOptions ipopt = test::native_tangential_solver();
  ipopt.backend = Backend::ipopt;
  TangentialProblem by_native(su.grid, m, su.heights, FrictionLaw::coulomb(0.2));
  TangentialProblem by_ipopt(su.grid, m, su.heights, FrictionLaw::coulomb(0.2));
  const TangentialSolution a = by_native.step(load, test::native_tangential_solver());
  const TangentialSolution b = by_ipopt.step(load, ipopt);
  expect_certified(a);
  expect_certified(b);
  EXPECT_EQ(b.report.backend, "ipopt");
  expect_same_state(b, a, "ipopt against native");
  EXPECT_GT(a.n_stick, 0);
}

TEST(OuterLoop, AndersonSolvesALinearFixedPointInFewSteps) {
  // x = G x + b with a contraction of rate 0.9: plain iteration needs ~200 steps for 1e-9;
  // Anderson with memory 5 on this 4-dimensional problem is exact after about 5.
  const double G[4][4] = {{0.9, 0.1, 0.0, 0.0}, {0.0, 0.5, 0.3, 0.0}, {0.0, 0.0, -0.7, 0.2}, {0.1, 0.0, 0.0, 0.3}};
  const std::vector<double> b = {1.0, -2.0, 0.5, 3.0};
  auto apply = [&](const std::vector<double>& x) {
    std::vector<double> y(b);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) y[i] += G[i][j] * x[j];
    return y;
  };
  AndersonMixing mixer(5);
  std::vector<double> x(4, 0.0);
  int steps = 0;
  double residual = 1.0;
  for (; steps < 50 && residual > 1e-9; ++steps) {
    const std::vector<double> g = apply(x);
    residual = 0.0;
    for (int i = 0; i < 4; ++i) residual = std::max(residual, std::abs(g[i] - x[i]));
    x = mixer.next(x, g);
  }
  EXPECT_LE(steps, 10);
  EXPECT_LE(residual, 1e-9);
}

TEST(OuterLoop, ATrialNearTheLastOneStartsWithAnExactPass) {
  // A dynamic step's Newton trials solve the same step at data a correction apart, each from the
  // last trial's traction (restore_history). Such a start is already within a loose pass's
  // tolerance: with set_near_start the first pass is exact, one pass fewer than the loose start
  // takes, and the answer is the same to the solver's tolerance.
  const Indentation in(0.0, 0.3);
  TangentialProblem problem = in.problem();
  const NormalSpec load{Control::force, 0.5 * Indentation::P_max};
  const SolverOptions solver = test::native_tangential_solver();
  const double shift = 1e-7;  // partial slip: a fraction of the full-sliding shift
  const TangentialMemory before = problem.memory();
  expect_certified(problem.convected_step(load, {shift, 0.3 * shift, 0.0}, {0.0, 0.0}, solver));
  const std::array<double, 3> corrected = {shift * (1.0 + 1e-6), 0.3 * shift, 0.0};
  problem.restore_history(before);
  const TangentialSolution loose = problem.convected_step(load, corrected, {0.0, 0.0}, solver);
  problem.restore_history(before);
  problem.set_near_start(true);
  const TangentialSolution exact = problem.convected_step(load, corrected, {0.0, 0.0}, solver);
  expect_certified(loose);
  expect_certified(exact);
  EXPECT_LT(exact.outer.iterations, loose.outer.iterations);
  EXPECT_LE(exact.outer.iterations, 2);
  double worst = 0.0, scale = 0.0;
  for (std::size_t e = 0; e < exact.tx.size(); ++e) {
    worst = std::max({worst, std::abs(exact.tx[e] - loose.tx[e]), std::abs(exact.ty[e] - loose.ty[e])});
    scale = std::max(scale, std::abs(loose.tx[e]));
  }
  EXPECT_LE(worst, 1e-6 * scale);
}

TEST(OuterLoop, ALoosePassThatReturnsItsStartDoesNotEndTheLoop) {
  // A solve from a start within the loose pass's tolerance (the last step's answer, data 1e-4
  // apart): the loose pass returns the start unchanged, its coupling residual 0. That pair is
  // not a point of the fixed-point map; were it kept in the mixing's history, Anderson would
  // steer the next pass back to it, p and tau would not change, and the loop would stop on that
  // stall with the exact pass's coupling residual above its tolerance (an uncertified answer).
  // The loop must end certified with its residual below a hundredth of certificate_tol, at the
  // answer of a solve that starts exact.
  const Indentation in(0.0, 0.3);
  const NormalSpec load{Control::force, 0.5 * Indentation::P_max};
  const SolverOptions solver = test::native_tangential_solver();
  const double shift = 1e-7;
  for (const double correction : {1e-4, 3e-4}) {
    SCOPED_TRACE("data changed by " + std::to_string(correction));
    TangentialProblem problem = in.problem();
    const TangentialMemory before = problem.memory();
    expect_certified(problem.convected_step(load, {shift, 0.3 * shift, 0.0}, {0.0, 0.0}, solver));
    const std::array<double, 3> corrected = {shift * (1.0 + correction), 0.3 * shift, 0.0};
    problem.restore_history(before);
    const TangentialSolution loose = problem.convected_step(load, corrected, {0.0, 0.0}, solver);
    expect_certified(loose);
    EXPECT_LE(loose.outer.coupling_residual, 0.01 * solver.certificate_tol);
    problem.restore_history(before);
    problem.set_near_start(true);
    const TangentialSolution exact = problem.convected_step(load, corrected, {0.0, 0.0}, solver);
    double worst = 0.0, scale = 0.0;
    for (std::size_t e = 0; e < exact.tx.size(); ++e) {
      worst = std::max({worst, std::abs(exact.tx[e] - loose.tx[e]), std::abs(exact.ty[e] - loose.ty[e])});
      scale = std::max(scale, std::abs(exact.tx[e]));
    }
    EXPECT_LE(worst, 1e-6 * scale);
  }
}

}  // namespace
}  // namespace dc
