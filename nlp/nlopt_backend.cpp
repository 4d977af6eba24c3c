// NLopt backend: bounds only -> LD_LBFGS; equalities only -> AUGLAG_EQ over LD_CCSAQ;
// disks (with or without equalities) -> AUGLAG over LD_TNEWTON_PRECOND_RESTART, each disk as
// x_ix^2 + x_iy^2 - r^2 <= 0. The subsidiary optimizer keeps the bounds.
// Programs with a sparse block (sparse_block.hpp) are refused.
// NLopt returns no multipliers: the equality multipliers are estimated afterwards by least
// squares of  Qx + c = sum_k lambda_k a_k  over the free components (see estimate_multipliers).
// NLopt then stops near, not at, the solution: its point is finished by the active-set polish
// (active_set_polish.hpp) and the polished point kept when its KKT residual is smaller.
#include <algorithm>
#include <climits>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlopt.hpp>

#include "active_set_polish.hpp"
#include "quadratic_program.hpp"
#include "interrupt.hpp"

namespace dc {
namespace {

const char* result_name(nlopt::result result) {
  switch (result) {
    case nlopt::FAILURE: return "FAILURE";
    case nlopt::INVALID_ARGS: return "INVALID_ARGS";
    case nlopt::OUT_OF_MEMORY: return "OUT_OF_MEMORY";
    case nlopt::ROUNDOFF_LIMITED: return "ROUNDOFF_LIMITED";
    case nlopt::FORCED_STOP: return "FORCED_STOP";
    case nlopt::SUCCESS: return "SUCCESS";
    case nlopt::STOPVAL_REACHED: return "STOPVAL_REACHED";
    case nlopt::FTOL_REACHED: return "FTOL_REACHED";
    case nlopt::XTOL_REACHED: return "XTOL_REACHED";
    case nlopt::MAXEVAL_REACHED: return "MAXEVAL_REACHED";
    case nlopt::MAXTIME_REACHED: return "MAXTIME_REACHED";
    default: return "unknown NLopt result";
  }
}

struct Problem {
  const QuadraticProgram& qp;
  const SolveOptions& options;
  std::vector<double> lower, upper;  ///< size n, +-infinity where unbounded
  std::vector<double> scratch;       ///< gradient when NLopt asks for f only
  int evaluations = 0;
};

struct EqualityData {
  const LinearEquality* row;
};

struct DiskData {
  const DiskConstraint* disk;
};

/// Worst violation: of the projected-gradient condition (bounds only) or of the constraints.
double residual(const Problem& p, const double* x, const double* g) {
  double r = 0.0;
  const std::size_t n = p.lower.size();
  if (p.qp.equalities.empty() && p.qp.disks.empty()) {
    for (std::size_t i = 0; i < n; ++i) {  // |x - P(x - g)|
      const double step = std::clamp(x[i] - g[i], p.lower[i], p.upper[i]);
      r = std::max(r, std::abs(x[i] - step));
    }
    return r;
  }
  for (const auto& eq : p.qp.equalities) {
    double ax = -eq.b;
    for (std::size_t i = 0; i < n; ++i) ax += eq.a[i] * x[i];
    r = std::max(r, std::abs(ax));
  }
  for (const auto& d : p.qp.disks)
    r = std::max(r, x[d.ix] * x[d.ix] + x[d.iy] * x[d.iy] - d.radius * d.radius);
  return r;
}

/// f = 1/2 x'Qx + c'x, grad = Qx + c (one operator apply).
double objective(unsigned, const double* x, double* grad, void* data) {
  auto& p = *static_cast<Problem*>(data);
  if (interrupt_requested()) throw nlopt::forced_stop();  // run_backend then throws Interrupted
  double* g = grad != nullptr ? grad : p.scratch.data();
  const double f = p.qp.gradient(x, g);
  ++p.evaluations;
  if (p.options.progress && (p.evaluations == 1 || p.evaluations % 10 == 0))
    p.options.progress(ProgressInfo{p.evaluations, f, residual(p, x, g)});
  return f;
}

/// h_k(x) = a_k'x - b_k = 0.
double equality(unsigned n, const double* x, double* grad, void* data) {
  const LinearEquality& eq = *static_cast<EqualityData*>(data)->row;
  double h = -eq.b;
  for (unsigned i = 0; i < n; ++i) h += eq.a[i] * x[i];
  if (grad != nullptr) std::copy(eq.a.begin(), eq.a.end(), grad);
  return h;
}

/// c_d(x) = x_ix^2 + x_iy^2 - r^2 <= 0.
double disk_constraint(unsigned n, const double* x, double* grad, void* data) {
  const DiskConstraint& d = *static_cast<DiskData*>(data)->disk;
  if (grad != nullptr) {
    std::fill(grad, grad + n, 0.0);
    grad[d.ix] += 2.0 * x[d.ix];
    grad[d.iy] += 2.0 * x[d.iy];
  }
  return x[d.ix] * x[d.ix] + x[d.iy] * x[d.iy] - d.radius * d.radius;
}

/// Start: qp.x0 or zero, projected on each disk and then on the bounds.
std::vector<double> starting_point(const Problem& p) {
  std::vector<double> x(p.lower.size(), 0.0);
  if (p.qp.x0.size() == x.size()) x = p.qp.x0;
  for (const auto& d : p.qp.disks) project_onto_disk(x[d.ix], x[d.iy], d.radius);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], p.lower[i], p.upper[i]);
  return x;
}

/// Least-squares estimate of lambda in  g = Qx + c = sum_k lambda_k a_k  over the components
/// where the bound and disk multipliers vanish: strictly inside their bounds (margin
/// 1e-6 (1 + |bound|)) and not on a disk within 1e-4 of its radius.
std::vector<double> estimate_multipliers(const Problem& p, const std::vector<double>& x,
                                         const std::vector<double>& g) {
  const auto& eqs = p.qp.equalities;
  if (eqs.empty()) return {};
  const std::size_t n = x.size();
  std::vector<char> free(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    if (x[i] <= p.lower[i] + 1e-6 * (1.0 + std::abs(p.lower[i]))) free[i] = 0;
    if (x[i] >= p.upper[i] - 1e-6 * (1.0 + std::abs(p.upper[i]))) free[i] = 0;
  }
  for (const auto& d : p.qp.disks)
    if (std::hypot(x[d.ix], x[d.iy]) >= d.radius * (1.0 - 1e-4)) free[d.ix] = free[d.iy] = 0;
  const auto rows = static_cast<Eigen::Index>(std::count(free.begin(), free.end(), 1));
  const auto m = static_cast<Eigen::Index>(eqs.size());
  if (rows == 0) return std::vector<double>(eqs.size(), 0.0);  // undetermined: every x bound
  Eigen::MatrixXd a(rows, m);
  Eigen::VectorXd rhs(rows);
  Eigen::Index r = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!free[i]) continue;
    for (Eigen::Index k = 0; k < m; ++k) a(r, k) = eqs[static_cast<std::size_t>(k)].a[i];
    rhs(r++) = g[i];
  }
  const Eigen::VectorXd lambda = a.completeOrthogonalDecomposition().solve(rhs);
  return std::vector<double>(lambda.data(), lambda.data() + m);
}


}  // namespace

SolveOutcome solve_with_nlopt(const QuadraticProgram& qp, const SolveOptions& options) {
  SolveOutcome out;
  if (const std::string why = qp.invalid_reason(); !why.empty()) {
    out.message = "NLopt: invalid program: " + why;
    return out;
  }
  if (qp.block) {
    out.message = "NLopt: a sparse block is not taken (its equality algorithms would hold the rows densely)";
    return out;
  }
  const int n = qp.n();
  Problem p{qp, options, qp.lower, qp.upper, std::vector<double>(static_cast<std::size_t>(n)), 0};
  if (p.lower.empty()) p.lower.assign(static_cast<std::size_t>(n), -kInf);
  if (p.upper.empty()) p.upper.assign(static_cast<std::size_t>(n), kInf);
  out.x = starting_point(p);
  out.equality_multipliers.assign(qp.equalities.size(), 0.0);
  if (n == 0) {
    out.success = true;
    out.message = "NLopt: empty program";
    return out;
  }

  const bool constrained = !qp.equalities.empty() || !qp.disks.empty();
  const double tol = options.tol;
  // Function evaluations >> iterations: 50 per requested iteration.
  const int maxeval = static_cast<int>(std::min<long long>(50LL * std::max(options.max_iter, 1), INT_MAX));
  std::vector<EqualityData> eq_data;
  std::vector<DiskData> disk_data;
  for (const auto& eq : qp.equalities) eq_data.push_back({&eq});
  for (const auto& d : qp.disks) disk_data.push_back({&d});

  try {
    const auto un = static_cast<unsigned>(n);
    // ftol is tightened to tol^2: on a QP f - f* ~ |dx|^2, so ftol = tol stops too early.
    const auto configure = [&](nlopt::opt& o) {
      o.set_ftol_rel(tol * tol);
      o.set_xtol_rel(tol);
    };
    nlopt::opt opt(nlopt::LD_LBFGS, un);
    std::string label = "LD_LBFGS";
    if (!constrained) {
      opt.set_vector_storage(20);
    } else {
      // Subsidiary optimizers (both keep the bounds): L-BFGS proved fragile under AUGLAG
      // (its roundoff failure aborts the outer loop), so equalities use CCSAQ and disks TNEWTON.
      const bool disks = !qp.disks.empty();
      opt = nlopt::opt(disks ? nlopt::AUGLAG : nlopt::AUGLAG_EQ, un);
      nlopt::opt local(disks ? nlopt::LD_TNEWTON_PRECOND_RESTART : nlopt::LD_CCSAQ, un);
      configure(local);
      opt.set_local_optimizer(local);
      label = disks ? "AUGLAG/LD_TNEWTON_PRECOND_RESTART" : "AUGLAG_EQ/LD_CCSAQ";
      for (auto& e : eq_data)
        opt.add_equality_constraint(equality, &e, tol * std::max(1.0, std::abs(e.row->b)));
      for (auto& d : disk_data)
        opt.add_inequality_constraint(disk_constraint, &d, tol * std::max(1.0, d.disk->radius * d.disk->radius));
    }
    configure(opt);
    opt.set_lower_bounds(p.lower);
    opt.set_upper_bounds(p.upper);
    opt.set_min_objective(objective, &p);
    opt.set_maxeval(maxeval);

    std::vector<double> x = out.x;
    double f = 0.0;
    nlopt::result result = nlopt::FAILURE;
    std::string detail;
    try {
      result = opt.optimize(x, f);
    } catch (const nlopt::roundoff_limited&) {
      result = nlopt::ROUNDOFF_LIMITED;  // x holds the best point found
    } catch (const std::exception& e) {
      result = opt.last_optimize_result();
      detail = std::string(" (") + e.what() + ")";
    }
    out.x = x;
    std::vector<double> g(static_cast<std::size_t>(n));
    qp.gradient(out.x.data(), g.data());
    out.equality_multipliers = estimate_multipliers(p, out.x, g);
    out.iterations = p.evaluations;
    out.success = result == nlopt::SUCCESS || result == nlopt::FTOL_REACHED ||
                  result == nlopt::XTOL_REACHED || result == nlopt::STOPVAL_REACHED;
    out.message = "NLopt " + label + ": " + result_name(result) + detail;
    // NLopt stops near the solution, not at it: finish on its active set, kept when better.
    const PolishResult polish = polish_on_active_set(qp, out.x, out.equality_multipliers);
    out.iterations += polish.applies;
    if (polish.improved) {
      out.polished = true;  // success stays NLopt's own verdict: the certificate decides
      out.message += "; " + polish_summary(polish);
    }
    out.objective = qp.objective(out.x.data());
  } catch (const std::exception& e) {
    out.success = false;
    out.iterations = p.evaluations;
    out.message = std::string("NLopt backend error: ") + e.what();
  }
  return out;
}

}  // namespace dc
