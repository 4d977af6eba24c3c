// The general backends (Ipopt, NLopt) on small quadratic programs with known answers:
//   min 1/2 x'Qx + c'x  s.t. bounds, a_k'x = b_k, x_ix^2 + x_iy^2 <= r^2,
// multipliers checked against  Qx + c = sum_k lambda_k a_k + z_l - z_u - sum_d 2 mu_d x_d.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "dense_matrix_operator.hpp"
#include "quadratic_program.hpp"

namespace dc {
namespace {

using test::DenseMatrixOperator;
using test::random_spd;

using BackendFunction = std::function<SolveOutcome(const QuadraticProgram&, const SolveOptions&)>;

struct NamedBackend {
  std::string name;
  BackendFunction solve;
};

std::vector<NamedBackend> backends() {
  return {{"ipopt", solve_with_ipopt}, {"nlopt", solve_with_nlopt}};
}

Eigen::VectorXd vec(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

std::vector<double> random_vector(int n, unsigned seed, double lo, double hi) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(lo, hi);
  std::vector<double> v(static_cast<std::size_t>(n));
  for (auto& x : v) x = uniform(rng);
  return v;
}

/// g = Qx + c - sum_k lambda_k a_k (the bound multipliers z_l - z_u at a KKT point).
Eigen::VectorXd reduced_gradient(const QuadraticProgram& qp, const Eigen::MatrixXd& q,
                                 const std::vector<double>& x, const std::vector<double>& lambda) {
  Eigen::VectorXd g = q * vec(x) + vec(qp.c);
  for (std::size_t k = 0; k < qp.equalities.size(); ++k) g -= lambda[k] * vec(qp.equalities[k].a);
  return g;
}

struct Reference {
  std::vector<double> x, lambda;
  int active = 0;  ///< bounds active at the solution
};

/// Exact solution of a small strictly convex QP with bounds and equalities by enumerating the
/// active sets (free / at lower / at upper) and solving the KKT system of each.
std::optional<Reference> enumerate_active_sets(const QuadraticProgram& qp, const Eigen::MatrixXd& q) {
  const int n = qp.n();
  const int m = static_cast<int>(qp.equalities.size());
  std::vector<int> state(static_cast<std::size_t>(n), 0);  // 0 free, 1 lower, 2 upper
  while (true) {
    bool valid = true;
    for (int i = 0; i < n; ++i) {
      const auto s = state[static_cast<std::size_t>(i)];
      if ((s == 1 && !std::isfinite(qp.lower[static_cast<std::size_t>(i)])) ||
          (s == 2 && !std::isfinite(qp.upper[static_cast<std::size_t>(i)])))
        valid = false;
    }
    if (valid) {
      // [Q  -A'; A 0] [x; lambda] = [-c; b] with the fixed rows replaced by x_i = bound.
      Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n + m, n + m);
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
      for (int i = 0; i < n; ++i) {
        const auto s = state[static_cast<std::size_t>(i)];
        if (s == 0) {
          k.row(i).head(n) = q.row(i);
          for (int e = 0; e < m; ++e) k(i, n + e) = -qp.equalities[static_cast<std::size_t>(e)].a[static_cast<std::size_t>(i)];
          rhs(i) = -qp.c[static_cast<std::size_t>(i)];
        } else {
          k(i, i) = 1.0;
          rhs(i) = s == 1 ? qp.lower[static_cast<std::size_t>(i)] : qp.upper[static_cast<std::size_t>(i)];
        }
      }
      for (int e = 0; e < m; ++e) {
        k.row(n + e).head(n) = vec(qp.equalities[static_cast<std::size_t>(e)].a).transpose();
        rhs(n + e) = qp.equalities[static_cast<std::size_t>(e)].b;
      }
      Eigen::FullPivLU<Eigen::MatrixXd> lu(k);
      if (lu.isInvertible()) {
        const Eigen::VectorXd sol = lu.solve(rhs);
        Reference ref;
        ref.x.assign(sol.data(), sol.data() + n);
        ref.lambda.assign(sol.data() + n, sol.data() + n + m);
        const Eigen::VectorXd z = reduced_gradient(qp, q, ref.x, ref.lambda);
        bool kkt = true;
        for (int i = 0; i < n; ++i) {
          const auto u = static_cast<std::size_t>(i);
          const auto s = state[u];
          if (s == 0) kkt &= ref.x[u] >= qp.lower[u] - 1e-12 && ref.x[u] <= qp.upper[u] + 1e-12;
          if (s == 1) kkt &= z(i) >= -1e-12;
          if (s == 2) kkt &= z(i) <= 1e-12;
          ref.active += s != 0;
        }
        if (kkt) return ref;
      }
    }
    int i = 0;  // next state combination
    while (i < n && ++state[static_cast<std::size_t>(i)] == 3) state[static_cast<std::size_t>(i++)] = 0;
    if (i == n) return std::nullopt;
  }
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  return (vec(a) - vec(b)).lpNorm<Eigen::Infinity>();
}

/// Box-constrained problem of (a): 0 <= x <= 0.4 with c chosen so both bounds bind somewhere.
struct BoxProblem {
  DenseMatrixOperator op;
  QuadraticProgram qp;
  explicit BoxProblem(int n, unsigned seed, double upper = 0.4) : op(random_spd(n, seed)) {
    qp.Q = &op;
    qp.c = random_vector(n, seed + 1, -1.0, 1.0);
    qp.lower.assign(static_cast<std::size_t>(n), 0.0);
    qp.upper.assign(static_cast<std::size_t>(n), upper);
  }
};

TEST(Backends, BoundConstrainedMatchesActiveSetEnumeration) {
  BoxProblem p(6, 11);
  const auto ref = enumerate_active_sets(p.qp, p.op.matrix());
  ASSERT_TRUE(ref.has_value());
  ASSERT_GE(ref->active, 2);      // the bounds matter
  ASSERT_LE(ref->active, 5);      // and some variables stay free
  for (const auto& backend : backends()) {
    const SolveOutcome out = backend.solve(p.qp, SolveOptions{});
    EXPECT_TRUE(out.success) << backend.name << ": " << out.message;
    ASSERT_EQ(out.x.size(), 6u) << backend.name;
    EXPECT_LT(max_abs_diff(out.x, ref->x), 1e-6) << backend.name;
    EXPECT_NEAR(out.objective, p.qp.objective(ref->x.data()), 1e-9) << backend.name;
    EXPECT_TRUE(out.equality_multipliers.empty()) << backend.name;
    EXPECT_GT(out.iterations, 0) << backend.name;
  }
}

TEST(Backends, EqualityMultiplierSignOnUnboundedProblem) {
  // min 1/2 |x|^2 s.t. sum x = b: x = b/n, and Qx + c = lambda a gives lambda = b/n > 0.
  DenseMatrixOperator op(Eigen::MatrixXd::Identity(4, 4));
  QuadraticProgram qp;
  qp.Q = &op;
  qp.c.assign(4, 0.0);
  qp.equalities.push_back({std::vector<double>(4, 1.0), 2.0});
  for (const auto& backend : backends()) {
    const SolveOutcome out = backend.solve(qp, SolveOptions{});
    EXPECT_TRUE(out.success) << backend.name << ": " << out.message;
    for (double xi : out.x) EXPECT_NEAR(xi, 0.5, 1e-7) << backend.name;
    ASSERT_EQ(out.equality_multipliers.size(), 1u) << backend.name;
    EXPECT_NEAR(out.equality_multipliers[0], 0.5, 1e-6) << backend.name;
  }
}

TEST(Backends, EqualityWithBoundsSatisfiesKkt) {
  BoxProblem p(6, 11, kInf);
  p.qp.equalities.push_back({std::vector<double>(6, 1.0), 1.5});
  const auto ref = enumerate_active_sets(p.qp, p.op.matrix());
  ASSERT_TRUE(ref.has_value());
  ASSERT_GE(ref->active, 1);
  ASSERT_GT(std::abs(ref->lambda[0]), 0.05);  // a sign error would show
  for (const auto& backend : backends()) {
    const SolveOutcome out = backend.solve(p.qp, SolveOptions{});
    EXPECT_TRUE(out.success) << backend.name << ": " << out.message;
    EXPECT_LT(max_abs_diff(out.x, ref->x), 1e-6) << backend.name;
    ASSERT_EQ(out.equality_multipliers.size(), 1u) << backend.name;
    EXPECT_NEAR(out.equality_multipliers[0], ref->lambda[0], 1e-5) << backend.name;
    double sum = 0.0;
    for (double xi : out.x) sum += xi;
    EXPECT_NEAR(sum, 1.5, 1e-7) << backend.name;
    // Qx + c - lambda a = z_l: >= 0 where x sits on 0, = 0 where x > 0.
    const Eigen::VectorXd z = reduced_gradient(p.qp, p.op.matrix(), out.x, out.equality_multipliers);
    for (int i = 0; i < 6; ++i) {
      EXPECT_GE(out.x[static_cast<std::size_t>(i)], -1e-8) << backend.name;
      if (ref->x[static_cast<std::size_t>(i)] > 0.0)
        EXPECT_NEAR(z(i), 0.0, 1e-5) << backend.name << " i=" << i;
      else
        EXPECT_GT(z(i), -1e-5) << backend.name << " i=" << i;
    }
  }
}

/// Pairs (2d, 2d+1) in disks of radius radii[d].
void add_disks(QuadraticProgram& qp, const std::vector<double>& radii) {
  for (std::size_t d = 0; d < radii.size(); ++d)
    qp.disks.push_back({static_cast<int>(2 * d), static_cast<int>(2 * d + 1), radii[d]});
}

TEST(Backends, SeparableDisksGiveProjection) {
  // min 1/2 |x|^2 - w.x over |x_d| <= r_d: x_d = w_d min(1, r_d / |w_d|).
  const std::vector<double> w = {3.0, -4.0, 0.1, 0.2, -1.0, 0.0, 0.3, 0.3};
  const std::vector<double> radii = {1.0, 0.5, 0.25, 2.0};
  DenseMatrixOperator op(Eigen::MatrixXd::Identity(8, 8));
  QuadraticProgram qp;
  qp.Q = &op;
  for (double wi : w) qp.c.push_back(-wi);
  add_disks(qp, radii);
  std::vector<double> expected(8);
  for (std::size_t d = 0; d < radii.size(); ++d) {
    const double norm = std::hypot(w[2 * d], w[2 * d + 1]);
    const double s = std::min(1.0, radii[d] / norm);
    expected[2 * d] = s * w[2 * d];
    expected[2 * d + 1] = s * w[2 * d + 1];
  }
  for (const auto& backend : backends()) {
    const SolveOutcome out = backend.solve(qp, SolveOptions{});
    EXPECT_TRUE(out.success) << backend.name << ": " << out.message;
    EXPECT_LT(max_abs_diff(out.x, expected), 1e-6) << backend.name;
  }
}

/// KKT of the disk program: per pair, g_d = (Qx + c)_d = -2 mu_d x_d with mu_d >= 0, and
/// mu_d = 0 (g_d = 0) where the disk is inactive. Returns the worst violation.
double disk_kkt_violation(const QuadraticProgram& qp, const Eigen::MatrixXd& q, const std::vector<double>& x,
                          int* active_count = nullptr) {
  const Eigen::VectorXd g = q * vec(x) + vec(qp.c);
  double worst = 0.0;
  int active = 0;
  for (const auto& d : qp.disks) {
    const Eigen::Vector2d xd(x[static_cast<std::size_t>(d.ix)], x[static_cast<std::size_t>(d.iy)]);
    const Eigen::Vector2d gd(g(d.ix), g(d.iy));
    worst = std::max(worst, xd.norm() - d.radius);  // feasibility
    if (xd.norm() > d.radius * (1.0 - 1e-6)) {
      ++active;
      const double two_mu = -gd.dot(xd) / xd.squaredNorm();
      worst = std::max({worst, -two_mu, (gd + two_mu * xd).norm()});
    } else {
      worst = std::max(worst, gd.norm());
    }
  }
  if (active_count != nullptr) *active_count = active;
  return worst;
}

TEST(Backends, CoupledDisksSatisfyKkt) {
  const int n = 12;
  DenseMatrixOperator op(random_spd(n, 5, 0.5));
  QuadraticProgram qp;
  qp.Q = &op;
  qp.c = random_vector(n, 6, -1.0, 1.0);
  add_disks(qp, {0.05, 2.0, 0.1, 3.0, 0.2, 5.0});
  for (const auto& backend : backends()) {
    for (const Hessian hessian : {Hessian::exact, Hessian::limited_memory}) {
      if (backend.name == "nlopt" && hessian == Hessian::limited_memory) continue;  // no such choice
      SolveOptions options;
      options.hessian = hessian;
      const SolveOutcome out = backend.solve(qp, options);
      EXPECT_TRUE(out.success) << backend.name << "/" << to_string(hessian) << ": " << out.message;
      int active = 0;
      EXPECT_LT(disk_kkt_violation(qp, op.matrix(), out.x, &active), 1e-5) << backend.name << "/" << to_string(hessian);
      EXPECT_GE(active, 2) << backend.name << "/" << to_string(hessian);  // some disks bind ...
      EXPECT_LE(active, 5) << backend.name << "/" << to_string(hessian);  // ... and some do not
    }
  }
}

TEST(Backends, DisksWithEqualityAgreeIncludingMultiplier) {
  // NLopt's multiplier is a least-squares estimate that must skip the components on active disks.
  const int n = 12;
  DenseMatrixOperator op(random_spd(n, 7, 0.5));
  QuadraticProgram qp;
  qp.Q = &op;
  qp.c = random_vector(n, 8, -1.0, 1.0);
  add_disks(qp, {0.05, 2.0, 0.1, 3.0, 0.2, 5.0});
  std::vector<double> a(n, 0.0);
  for (int i = 0; i < n; i += 2) a[static_cast<std::size_t>(i)] = 1.0;
  qp.equalities.push_back({a, 2.0});
  const SolveOutcome ref = solve_with_ipopt(qp, SolveOptions{});
  const SolveOutcome out = solve_with_nlopt(qp, SolveOptions{});
  ASSERT_TRUE(ref.success) << ref.message;
  EXPECT_TRUE(out.success) << out.message;
  EXPECT_LT(max_abs_diff(out.x, ref.x), 1e-6);
  ASSERT_EQ(out.equality_multipliers.size(), 1u);
  ASSERT_GT(std::abs(ref.equality_multipliers[0]), 0.05);
  EXPECT_NEAR(out.equality_multipliers[0], ref.equality_multipliers[0], 1e-5);
  int active = 0;
  disk_kkt_violation(qp, op.matrix(), ref.x, &active);
  EXPECT_GE(active, 1);  // the estimate had something to skip
}

TEST(Backends, IpoptAndNloptAgreeOnRandomBoxProblem) {
  BoxProblem p(40, 21, 0.5);
  const SolveOutcome a = solve_with_ipopt(p.qp, SolveOptions{});
  const SolveOutcome b = solve_with_nlopt(p.qp, SolveOptions{});
  ASSERT_TRUE(a.success) << a.message;
  ASSERT_TRUE(b.success) << b.message;
  const double scale = std::max(1.0, vec(a.x).lpNorm<Eigen::Infinity>());
  EXPECT_LT(max_abs_diff(a.x, b.x), 1e-6 * scale);
  EXPECT_NEAR(a.objective, b.objective, 1e-9 * std::max(1.0, std::abs(a.objective)));
  int at_lower = 0, at_upper = 0;
  for (double xi : a.x) {
    at_lower += xi < 1e-7;
    at_upper += xi > 0.5 - 1e-7;
  }
  EXPECT_GT(at_lower, 0);  // a problem where the bounds really act
  EXPECT_GT(at_upper, 0);
}

TEST(Backends, IpoptExactAndLimitedMemoryHessianAgree) {
  BoxProblem p(40, 31, 0.5);
  p.qp.equalities.push_back({random_vector(40, 32, 0.5, 1.5), 4.0});
  SolveOptions exact, lbfgs;
  exact.hessian = Hessian::exact;
  lbfgs.hessian = Hessian::limited_memory;
  const SolveOutcome a = solve_with_ipopt(p.qp, exact);
  const SolveOutcome b = solve_with_ipopt(p.qp, lbfgs);
  ASSERT_TRUE(a.success) << a.message;
  ASSERT_TRUE(b.success) << b.message;
  EXPECT_LT(max_abs_diff(a.x, b.x), 1e-6);
  ASSERT_EQ(a.equality_multipliers.size(), 1u);
  ASSERT_EQ(b.equality_multipliers.size(), 1u);
  EXPECT_NEAR(a.equality_multipliers[0], b.equality_multipliers[0], 1e-5);
  // "auto" follows the size limit: below it the exact run is reproduced iteration for iteration.
  SolveOptions automatic;
  automatic.exact_hessian_limit = 40;
  EXPECT_EQ(solve_with_ipopt(p.qp, automatic).iterations, a.iterations);
  automatic.exact_hessian_limit = 39;
  EXPECT_EQ(solve_with_ipopt(p.qp, automatic).iterations, b.iterations);
}

TEST(Backends, IterationLimitReportsFailureWithoutThrowing) {
  BoxProblem p(40, 41, 0.5);
  p.qp.equalities.push_back({std::vector<double>(40, 1.0), 3.0});
  SolveOptions options;
  options.max_iter = 1;
  for (const auto& backend : backends()) {
    SolveOutcome out;
    EXPECT_NO_THROW(out = backend.solve(p.qp, options)) << backend.name;
    EXPECT_FALSE(out.success) << backend.name << ": " << out.message;
    EXPECT_FALSE(out.message.empty()) << backend.name;
    EXPECT_EQ(out.x.size(), 40u) << backend.name;
  }
}

TEST(Backends, MalformedProgramReportsFailureWithoutThrowing) {
  DenseMatrixOperator op(Eigen::MatrixXd::Identity(4, 4));
  QuadraticProgram qp;
  qp.Q = &op;
  qp.c.assign(4, 0.0);
  qp.disks.push_back({0, 7, 1.0});  // index out of range
  for (const auto& backend : backends()) {
    SolveOutcome out;
    EXPECT_NO_THROW(out = backend.solve(qp, SolveOptions{})) << backend.name;
    EXPECT_FALSE(out.success) << backend.name;
    EXPECT_NE(out.message.find("invalid"), std::string::npos) << backend.name << ": " << out.message;
  }
}

TEST(Backends, ProgressCallbackIsCalled) {
  BoxProblem p(20, 51);
  for (const auto& backend : backends()) {
    std::vector<ProgressInfo> seen;
    SolveOptions options;
    options.progress = [&seen](const ProgressInfo& info) { seen.push_back(info); };
    const SolveOutcome out = backend.solve(p.qp, options);
    EXPECT_TRUE(out.success) << backend.name << ": " << out.message;
    ASSERT_FALSE(seen.empty()) << backend.name;
    for (std::size_t k = 1; k < seen.size(); ++k)
      EXPECT_GE(seen[k].iteration, seen[k - 1].iteration) << backend.name;
    EXPECT_LE(seen.back().iteration, out.iterations) << backend.name;
  }
}

TEST(Backends, IpoptCachesTheGradientApply) {
  // eval_f and eval_grad_f at the same x share one operator apply.
  BoxProblem p(20, 61);
  const SolveOutcome out = solve_with_ipopt(p.qp, SolveOptions{});
  ASSERT_TRUE(out.success) << out.message;
  // Uncached, every iteration costs two applies (f at the trial point, then its gradient).
  const auto it = static_cast<std::size_t>(out.iterations);
  EXPECT_LE(p.op.apply_count(), it + it / 2 + 3) << out.iterations << " iterations";
}

}  // namespace
}  // namespace dc
