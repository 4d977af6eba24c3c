// Variational equivalence for the normal problem (4.7), Section 3 (3.21)-(3.24):
// the minimiser satisfies the contact conditions (2.2)-(2.3), and a solution of those
// conditions (found independently, by an active-set method) minimises the functional.
// Also: the backends agree, and the certificate catches a wrong answer.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "backend_choice.hpp"
#include "errors.hpp"
#include "normal_problem.hpp"
#include "profile.hpp"

namespace dc {
namespace {

struct SmallSphere {
  Grid grid = Grid::make(3, 14, 12, -0.3e-3, 0.3e-3, -0.25e-3, 0.25e-3);
  MaterialPair materials{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(7e10, 0.33)};
  std::vector<double> heights;
  double force = 50.0;
  SmallSphere() {
    ProfileSpec prof;
    prof.type = ProfileType::ellipsoid;
    prof.radius_x = 0.01;
    prof.radius_y = 0.015;
    heights = profile_heights(prof, grid);
  }
};

SolverOptions tight_backend_options(Backend backend) {
  SolverOptions s;
  s.backend = backend;
  s.fallback = false;
  s.tol = 1e-10;
  s.max_iter = 3000;
  return s;
}

/// The functional (4.7) under force control (the approach term is constant): 1/2 p'Cp + h'p.
double functional(const Eigen::MatrixXd& C, const std::vector<double>& h, const std::vector<double>& p) {
  const Eigen::Map<const Eigen::VectorXd> pv(p.data(), p.size()), hv(h.data(), h.size());
  return 0.5 * pv.dot(C * pv) + hv.dot(pv);
}

/// Solves the complementarity conditions g = Cp + h - delta >= 0, p >= 0, pg = 0, sum p A = P
/// directly, by the active-set method (no optimisation): guess the contact set, solve the
/// linear system, drop negative pressures, add penetrating points, repeat.
std::vector<double> complementarity_solution(const Eigen::MatrixXd& C, const std::vector<double>& h, double A,
                                             double P) {
  const int n = static_cast<int>(h.size());
  std::vector<char> active(n, 0);
  const int centre = static_cast<int>(std::min_element(h.begin(), h.end()) - h.begin());
  active[centre] = 1;
  std::vector<double> p(n, 0.0);
  for (int sweep = 0; sweep < 200; ++sweep) {
    std::vector<int> idx;
    for (int i = 0; i < n; ++i)
      if (active[i]) idx.push_back(i);
    const int m = static_cast<int>(idx.size());
    // Unknowns scaled to O(1): q = p / ps, d = delta / (c0 ps).
    const double c0 = C(0, 0), ps = P / (A * m);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m + 1, m + 1);
    Eigen::VectorXd rhs(m + 1);
    for (int a = 0; a < m; ++a) {
      for (int b = 0; b < m; ++b) K(a, b) = C(idx[a], idx[b]) / c0;
      K(a, m) = -1.0;
      K(m, a) = 1.0;
      rhs(a) = -h[idx[a]] / (c0 * ps);
    }
    rhs(m) = m;
    Eigen::VectorXd sol = K.fullPivLu().solve(rhs);
    for (int a = 0; a < m; ++a) sol(a) *= ps;
    sol(m) *= c0 * ps;
    std::fill(p.begin(), p.end(), 0.0);
    bool changed = false;
    for (int a = 0; a < m; ++a) {
      if (sol(a) < 0.0) {
        active[idx[a]] = 0;
        changed = true;
      } else {
        p[idx[a]] = sol(a);
      }
    }
    if (changed) continue;
    const double delta = sol(m);
    const Eigen::VectorXd g = C * Eigen::Map<const Eigen::VectorXd>(p.data(), n) +
                              Eigen::Map<const Eigen::VectorXd>(h.data(), n) - Eigen::VectorXd::Constant(n, delta);
    for (int i = 0; i < n; ++i)
      if (!active[i] && g(i) < 0.0) {
        active[i] = 1;
        changed = true;
      }
    if (!changed) return p;
  }
  ADD_FAILURE() << "active-set method did not settle";
  return p;
}

TEST(NormalVariational, MinimiserSatisfiesContactConditions) {
  SmallSphere c;
  for (const Backend backend : {Backend::ipopt, Backend::native, Backend::nlopt}) {
    NormalProblem problem(c.grid, c.materials, c.heights);
    const NormalSolution s = problem.solve({Control::force, c.force}, tight_backend_options(backend));
    ASSERT_EQ(s.report.status, SolveStatus::converged) << to_string(backend) << ": " << s.report.message;
    double p_max = 0.0;
    for (double p : s.pressure) p_max = std::max(p_max, p);
    const double c0 = problem.compliance().diagonal(0);
    for (std::size_t i = 0; i < s.pressure.size(); ++i) {
      EXPECT_GE(s.pressure[i], 0.0);                                  // (2.3)
      EXPECT_GE(s.gap[i], -1e-6 * c0 * p_max) << to_string(backend);   // no interpenetration
      EXPECT_LE(std::min(s.pressure[i], s.gap[i] / c0), 1e-6 * p_max) << to_string(backend);  // (2.2)
    }
    EXPECT_NEAR(s.force, c.force, 1e-6 * c.force);
  }
}

TEST(NormalVariational, ComplementaritySolutionMinimisesTheFunctional) {
  SmallSphere c;
  NormalProblem problem(c.grid, c.materials, c.heights);
  const Eigen::MatrixXd C = problem.compliance().to_dense();
  const std::vector<double> p_star = complementarity_solution(C, c.heights, c.grid.area(), c.force);
  const double f_star = functional(C, c.heights, p_star);
  // Random admissible perturbations (p >= 0, same force) never lower the functional.
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double p_max = 0.0;
  for (double p : p_star) p_max = std::max(p_max, p);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> p = p_star;
    const double eps = (trial % 2 ? 1e-3 : 1e-1) * p_max;
    for (double& v : p) v = std::max(0.0, v + eps * (u(rng) - 0.5) * (u(rng) < 0.3 ? 1.0 : 0.0));
    double sum = 0.0;
    for (double v : p) sum += v * c.grid.area();
    for (double& v : p) v *= c.force / sum;
    EXPECT_GE(functional(C, c.heights, p), f_star * (1 - 1e-14) - 1e-14 * std::abs(f_star));
  }
  // And the optimiser finds the same field.
  const NormalSolution s = problem.solve({Control::force, c.force}, tight_backend_options(Backend::ipopt));
  for (std::size_t i = 0; i < p_star.size(); ++i) EXPECT_NEAR(s.pressure[i], p_star[i], 1e-5 * p_max);
}

TEST(NormalVariational, BackendsAgree) {
  SmallSphere c;
  std::vector<NormalSolution> sols;
  for (const Backend backend : {Backend::ipopt, Backend::nlopt, Backend::native}) {
    NormalProblem problem(c.grid, c.materials, c.heights);
    sols.push_back(problem.solve({Control::force, c.force}, tight_backend_options(backend)));
    ASSERT_EQ(sols.back().report.status, SolveStatus::converged) << to_string(backend);
    EXPECT_EQ(sols.back().report.backend, to_string(backend));
  }
  double p_max = 0.0;
  for (double p : sols[0].pressure) p_max = std::max(p_max, p);
  for (std::size_t k = 1; k < sols.size(); ++k) {
    for (std::size_t i = 0; i < sols[0].pressure.size(); ++i)
      EXPECT_NEAR(sols[k].pressure[i], sols[0].pressure[i], 1e-5 * p_max) << sols[k].report.backend;
    EXPECT_NEAR(sols[k].approach, sols[0].approach, 1e-6 * sols[0].approach);
  }
}

TEST(NormalVariational, ApproachControlIsTheSameProblem) {
  // Solving under the approach found by force control returns the same force.
  SmallSphere c;
  NormalProblem problem(c.grid, c.materials, c.heights);
  const NormalSolution by_force = problem.solve({Control::force, c.force}, tight_backend_options(Backend::native));
  for (const Backend backend : {Backend::ipopt, Backend::native}) {
    NormalProblem again(c.grid, c.materials, c.heights);
    const NormalSolution by_approach = again.solve({Control::approach, by_force.approach}, tight_backend_options(backend));
    ASSERT_EQ(by_approach.report.status, SolveStatus::converged) << to_string(backend);
    EXPECT_NEAR(by_approach.force, c.force, 1e-5 * c.force) << to_string(backend);
  }
}

TEST(NormalVariational, CertificateRejectsAWrongField) {
  SmallSphere c;
  NormalProblem problem(c.grid, c.materials, c.heights);
  const NormalSolution s = problem.solve({Control::force, c.force}, tight_backend_options(Backend::native));
  EXPECT_LT(s.report.certificate.worst(), 1e-6);
  std::vector<double> wrong = s.pressure;
  for (double& p : wrong) p *= 1.01;  // 1 % too much: the force and complementarity fail
  const Certificate bad = problem.certify(wrong, s.approach, {Control::force, c.force});
  EXPECT_GT(bad.force_residual, 5e-3);
  EXPECT_GT(bad.complementarity, 1e-3);
}

TEST(NormalVariational, IterationLimitIsReportedNotHidden) {
  SmallSphere c;
  NormalProblem problem(c.grid, c.materials, c.heights);
  SolverOptions s = tight_backend_options(Backend::native);
  s.max_iter = 2;
  const NormalSolution sol = problem.solve({Control::force, c.force}, s);
  EXPECT_NE(sol.report.status, SolveStatus::converged);
  EXPECT_FALSE(sol.report.message.empty());
}

TEST(NormalVariational, AutoFallsBackAndSaysSo) {
  SmallSphere c;
  NormalProblem problem(c.grid, c.materials, c.heights);
  SolverOptions s = tight_backend_options(Backend::automatic);
  s.fallback = true;
  const NormalSolution sol = problem.solve({Control::force, c.force}, s);
  EXPECT_EQ(sol.report.status, SolveStatus::converged);
  EXPECT_EQ(sol.report.backend, "ipopt");  // small problem: Ipopt first
  EXPECT_FALSE(sol.report.fallback_used);
  // When Ipopt and native run out of iterations, NLopt (last) is tried, its point finished by
  // the active-set polish; the report names each attempt. (Every backend failing:
  // test_forced_failures.cpp.) A fresh problem: the first one would warm-start from its field.
  s.max_iter = 1;
  NormalProblem fresh(c.grid, c.materials, c.heights);
  const NormalSolution fb = fresh.solve({Control::force, c.force}, s);
  EXPECT_TRUE(fb.report.fallback_used);
  EXPECT_EQ(fb.report.backend, "nlopt");
  EXPECT_NE(fb.report.message.find("ipopt: not_converged"), std::string::npos) << fb.report.message;
  EXPECT_NE(fb.report.message.find("native: not_converged"), std::string::npos) << fb.report.message;
  if (fb.report.status == SolveStatus::converged) {
    EXPECT_TRUE(fb.report.polished) << fb.report.message;
  }
}

TEST(NormalVariational, BackendOrder) {
  EXPECT_EQ(backend_order(Backend::automatic, 100, true), (std::vector<std::string>{"ipopt", "native", "nlopt"}));
  EXPECT_EQ(backend_order(Backend::automatic, 100000, true), (std::vector<std::string>{"native", "ipopt", "nlopt"}));
  EXPECT_EQ(backend_order(Backend::nlopt, 10, false), (std::vector<std::string>{"nlopt"}));
  EXPECT_FALSE(backend_from_string("cplex"));  // an unknown name is the case reader's InputError
}

}  // namespace
}  // namespace dc
