// The shakedown program (1) of shakedown_problem.hpp as an Ipopt TNLP over a working set of
// samples, constraint generation around it, and the certificate (2) on every sample.
// Unknowns x = (lambda, y_0, .., y_{m-1}), y_j in R^p the residual of depth j over k; Ipopt
// minimises -lambda. Constraint r is sample (j, i) = rows[r]: g = |lambda u_ij + W y_j|^2 <= 1, with
//   dg/dlambda = 2 u.v,  dg/dy_j = 2 W'v  (v = lambda u + W y_j),
//   d2g = 2 [u'u, u'W; W'u, W'W]  on (lambda, y_j).
// Ipopt's Lagrangian is f + sum mu g, so its multipliers of the active constraints g <= 1 are
// >= 0: the mu of (2) (zero for the samples outside the working set).
//
// Why a working set: with every sample (64 x 256) the KKT matrix has 16384 slack rows coupled
// through the dense lambda column; MUMPS's analysis and factorisations took 1 s of CPU for the
// 13-16 iterations. Few samples of a depth ever bind (the peaks of the orthogonal shear), so the
// working set stays at a few per depth and each Ipopt solve is small.
#include "shakedown_problem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include "interrupt.hpp"
#include "ipopt_shared.hpp"
#include "shakedown_samples.hpp"
#include "solver_report.hpp"

namespace dc {

namespace {

constexpr double kShakedownIpoptInf = 1e19;  // Ipopt's default nlp_upper_bound_inf
constexpr double kShakedownInf = std::numeric_limits<double>::infinity();

struct SampleIndex {
  int depth = 0, position = 0;
};

class ShakedownTnlp final : public Ipopt::TNLP {
 public:
  using Index = Ipopt::Index;
  using Number = Ipopt::Number;

  /// `rows` sorted by depth; `start` the starting point (1 + m p values).
  ShakedownTnlp(const ShakedownSamples& s, const std::vector<SampleIndex>& rows, const std::vector<double>& start)
      : s_(s), rows_(rows), start_(start), m_(s.depths), p_(s.p()), wtw_(s.w.transpose() * s.w) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag, IndexStyleEnum& style) override {
    n = 1 + m_ * p_;
    m = static_cast<Index>(rows_.size());
    nnz_jac_g = m * (1 + p_);
    nnz_h_lag = 1 + m_ * (p_ + p_ * (p_ + 1) / 2);
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l, Number* g_u) override {
    std::fill(x_l, x_l + n, -kShakedownIpoptInf);
    std::fill(x_u, x_u + n, kShakedownIpoptInf);
    std::fill(g_l, g_l + m, -kShakedownIpoptInf);
    std::fill(g_u, g_u + m, 1.0);
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*, Index, bool init_lambda,
                          Number*) override {
    if (init_z || init_lambda) return false;
    if (init_x) std::copy(start_.begin(), start_.begin() + n, x);
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& f) override {
    f = -x[0];
    return true;
  }

  bool eval_grad_f(Index n, const Number*, bool, Number* g) override {
    std::fill(g, g + n, 0.0);
    g[0] = -1.0;
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index m, Number* g) override {
    for (Index r = 0; r < m; ++r) g[r] = v(x, r).squaredNorm();
    return true;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index m, Index, Index* rows, Index* cols, Number* values) override {
    Index e = 0;
    if (values == nullptr) {
      for (Index r = 0; r < m; ++r) {
        rows[e] = r;
        cols[e++] = 0;
        for (Index c = 0; c < p_; ++c) {
          rows[e] = r;
          cols[e++] = 1 + depth(r) * p_ + c;
        }
      }
      return true;
    }
    for (Index r = 0; r < m; ++r) {
      const Eigen::VectorXd vr = v(x, r);
      values[e++] = 2.0 * u(r).dot(vr);
      for (Index c = 0; c < p_; ++c) values[e++] = 2.0 * s_.w.col(c).dot(vr);
    }
    return true;
  }

  bool eval_h(Index, const Number*, bool, Number, Index m, const Number* mu, bool, Index, Index* rows, Index* cols,
              Number* values) override {
    Index e = 0;
    if (values == nullptr) {
      rows[e] = 0;
      cols[e++] = 0;
      for (Index j = 0; j < m_; ++j)
        for (Index c = 0; c < p_; ++c) {
          rows[e] = 1 + j * p_ + c;
          cols[e++] = 0;
          for (Index c2 = 0; c2 <= c; ++c2) {
            rows[e] = 1 + j * p_ + c;
            cols[e++] = 1 + j * p_ + c2;
          }
        }
      return true;
    }
    // The objective is linear: only the constraints' curvature, 2 mu [u'u, u'W; W'u, W'W],
    // gathered by depth (the rows are sorted by depth).
    std::fill(values, values + 1 + m_ * (p_ + p_ * (p_ + 1) / 2), 0.0);
    const Index per_depth = p_ + p_ * (p_ + 1) / 2;
    for (Index r = 0; r < m; ++r) {
      const Eigen::VectorXd ur = u(r);
      values[0] += 2.0 * mu[r] * ur.squaredNorm();
      Number* block = values + 1 + depth(r) * per_depth;
      for (Index c = 0; c < p_; ++c) {
        *block++ += 2.0 * mu[r] * s_.w.col(c).dot(ur);
        for (Index c2 = 0; c2 <= c; ++c2) *block++ += 2.0 * mu[r] * wtw_(c, c2);
      }
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number*, const Number*, Index m,
                         const Number*, const Number* mu, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    x_.assign(x, x + n);
    mu_.assign(mu, mu + m);
    finalized_ = true;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number, Number, Number, Number, Number, Number,
                             Number, Number, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    iterations_ = std::max(iterations_, static_cast<int>(iter));
    return !interrupt_requested();
  }

  std::vector<double> x_, mu_;
  int iterations_ = 0;
  bool finalized_ = false;

 private:
  Index depth(Index r) const { return rows_[static_cast<std::size_t>(r)].depth; }
  Eigen::Ref<const Eigen::VectorXd> u(Index r) const {
    const SampleIndex& k = rows_[static_cast<std::size_t>(r)];
    return s_.sample(k.depth, k.position);
  }
  /// lambda u + W y_j of constraint r.
  Eigen::VectorXd v(const Number* x, Index r) const {
    return x[0] * u(r) + s_.w * Eigen::Map<const Eigen::VectorXd>(x + 1 + depth(r) * p_, p_);
  }

  const ShakedownSamples& s_;
  const std::vector<SampleIndex>& rows_;
  const std::vector<double>& start_;
  Index m_, p_;
  Eigen::MatrixXd wtw_;
};

/// min_y sum_i mu_i |u_ij + W y|^2 over the samples of depth j (the Q_j of (2); mu = nullptr:
/// every weight 1; else mu has one value per position of the depth), summed as non-negative terms
/// at the least-squares minimiser. With unit weights it is zero when one residual y absorbs every
/// sample of the depth (u_ij = -W y).
double weighted_residual(const ShakedownSamples& s, int j, const double* mu) {
  const int p = s.p();
  double mass = 0.0;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(p);
  for (int i = 0; i < s.positions; ++i) {
    const double w = mu == nullptr ? 1.0 : mu[i];
    mass += w;
    if (p > 0 && w != 0.0) rhs -= w * (s.w.transpose() * s.sample(j, i));
  }
  if (!(mass > 0.0)) return 0.0;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(p);
  if (p > 0) y = (mass * (s.w.transpose() * s.w)).ldlt().solve(rhs);
  const Eigen::VectorXd wy = s.w * y;
  double q = 0.0;
  for (int i = 0; i < s.positions; ++i) {
    const double w = mu == nullptr ? 1.0 : mu[i];
    if (w != 0.0) q += w * (s.sample(j, i) + wy).squaredNorm();
  }
  return q;
}

/// The yield function |lambda u_ij + W y_j| of every sample at x, depth-major.
std::vector<double> yield_values(const ShakedownSamples& s, const std::vector<double>& x) {
  std::vector<double> f(static_cast<std::size_t>(s.depths) * static_cast<std::size_t>(s.positions));
  const int p = s.p();
  for (int j = 0; j < s.depths; ++j) {
    const Eigen::VectorXd wy = s.w * Eigen::Map<const Eigen::VectorXd>(x.data() + 1 + j * p, p);
    for (int i = 0; i < s.positions; ++i)
      f[static_cast<std::size_t>(j) * static_cast<std::size_t>(s.positions) + static_cast<std::size_t>(i)] =
          (x[0] * s.sample(j, i) + wy).norm();
  }
  return f;
}

/// The first working set: per depth the sample of largest |u| (first yield), the extremes of
/// the projections on an orthonormal basis of W's range, and the largest part across it.
std::vector<std::vector<int>> first_working_set(const ShakedownSamples& s) {
  const int p = s.p();
  Eigen::MatrixXd basis(s.u.rows(), p);
  if (p > 0) basis = s.w.householderQr().householderQ() * Eigen::MatrixXd::Identity(s.u.rows(), p);
  std::vector<std::vector<int>> set(static_cast<std::size_t>(s.depths));
  for (int j = 0; j < s.depths; ++j) {
    std::vector<int> pick(static_cast<std::size_t>(2 + 2 * p), 0);
    std::vector<double> best(pick.size(), -kShakedownInf);
    for (int i = 0; i < s.positions; ++i) {
      const Eigen::VectorXd u = s.sample(j, i);
      const Eigen::VectorXd along = basis.transpose() * u;
      std::vector<double> score{u.squaredNorm(), (u - basis * along).squaredNorm()};
      for (int c = 0; c < p; ++c) {
        score.push_back(along(c));
        score.push_back(-along(c));
      }
      for (std::size_t k = 0; k < pick.size(); ++k)
        if (score[k] > best[k]) {
          best[k] = score[k];
          pick[k] = i;
        }
    }
    std::sort(pick.begin(), pick.end());
    pick.erase(std::unique(pick.begin(), pick.end()), pick.end());
    set[static_cast<std::size_t>(j)] = std::move(pick);
  }
  return set;
}

struct IpoptRun {
  bool finalized = false;
  std::string status;
  int iterations = 0;
  std::vector<double> x, mu;  // mu: one per row
};

IpoptRun run_ipopt(const ShakedownSamples& s, const std::vector<SampleIndex>& rows, const std::vector<double>& start,
                   const ShakedownOptions& options) {
  IpoptRun run;
  const std::lock_guard<std::mutex> lock(ipopt_mutex());
  Ipopt::SmartPtr<ShakedownTnlp> tnlp = new ShakedownTnlp(s, rows, start);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  auto opts = app->Options();
  bool ok = set_common_ipopt_options(*opts, options.tol, options.max_iter, options.verbose);
  if (options.verbose) ok &= opts->SetStringValue("print_timing_statistics", "yes");
  ok &= opts->SetStringValue("mu_strategy", "adaptive");
  ok &= opts->SetStringValue("hessian_approximation", "exact");
  if (!ok) {
    run.status = "an option was rejected";
    return run;
  }
  Ipopt::ApplicationReturnStatus status = app->Initialize("");
  if (status == Ipopt::Solve_Succeeded) status = app->OptimizeTNLP(Ipopt::GetRawPtr(tnlp));
  run.status = ipopt_status_name(status);
  run.iterations = tnlp->iterations_;
  run.finalized = tnlp->finalized_ && all_finite(tnlp->x_) && all_finite(tnlp->mu_);
  run.x = tnlp->x_;
  run.mu = tnlp->mu_;
  return run;
}

void set_verdict(ShakedownResult& r) {
  if (r.elastic_limit >= 1.0)
    r.verdict = ShakedownVerdict::elastic;
  else if (r.status == ShakedownStatus::unbounded || r.certificate.lower_bound >= 1.0)
    r.verdict = ShakedownVerdict::elastic_shakedown;
  else if (r.status != ShakedownStatus::failed && r.certificate.upper_bound < 1.0)
    r.verdict = ShakedownVerdict::beyond_shakedown;
  else
    r.verdict = ShakedownVerdict::undetermined;
}

}  // namespace

ShakedownResult solve_shakedown(const StressHistory& history, const YieldCriterion& criterion,
                                const ResidualModel& model, const ShakedownOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (const std::string why = options.validate(); !why.empty()) throw std::invalid_argument("shakedown: " + why);
  const ShakedownSamples s = shakedown_samples(history, criterion, model);
  const int m = s.depths, n = s.positions, p = s.p();
  const std::size_t un = static_cast<std::size_t>(n);

  ShakedownResult out;
  out.residual.assign(static_cast<std::size_t>(m), Voigt{});
  const auto finish = [&]() -> ShakedownResult {
    set_verdict(out);
    out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  };

  // First yield: the largest |u_ij|.
  Eigen::Index worst = 0;
  const double fmax = std::sqrt(s.u.colwise().squaredNorm().maxCoeff(&worst));
  out.elastic_limit = fmax > 0.0 ? 1.0 / fmax : kShakedownInf;
  out.elastic_limit_depth = static_cast<int>(worst / n);
  out.elastic_limit_position = static_cast<int>(worst % n);

  // A depth whose samples the residual absorbs entirely (u_ij = -W y for one y) never limits
  // lambda; when no depth limits it the program is unbounded.
  bool bounded = false;
  for (int j = 0; j < m && !bounded; ++j) {
    double size = 0.0;
    for (int i = 0; i < n; ++i) size += s.sample(j, i).squaredNorm();
    bounded = weighted_residual(s, j, nullptr) > 1e-20 * size;
  }
  if (!bounded) {
    out.status = ShakedownStatus::unbounded;
    out.message = "unbounded: the residual stress absorbs the stress of every depth";
    out.load_factor = out.certificate.lower_bound = out.certificate.upper_bound = kShakedownInf;
    return finish();
  }

  // The working set, by depth (positions sorted).
  std::vector<std::vector<int>> set(static_cast<std::size_t>(m));
  if (options.constraint_generation) {
    set = first_working_set(s);
  } else {
    for (auto& d : set) {
      d.resize(un);
      std::iota(d.begin(), d.end(), 0);
    }
  }
  std::vector<double> x(static_cast<std::size_t>(1 + m * p), 0.0), f;
  x[0] = 0.5 * out.elastic_limit;  // strictly inside: every g <= 1/4
  std::vector<double> mu;          // one per sample, depth-major
  const double add_above = 1.0 + 0.1 * options.certificate_tol;
  try {
    IpoptRun run;
    for (bool last = false; !last;) {
      std::vector<SampleIndex> rows;
      for (int j = 0; j < m; ++j)
        for (const int i : set[static_cast<std::size_t>(j)]) rows.push_back({j, i});
      // The last round's program holds every sample: after max_rounds, or when it already did.
      last = static_cast<int>(rows.size()) == m * n;
      run = run_ipopt(s, rows, x, options);
      throw_if_interrupted();  // Ipopt stopped at the request: unwind (Interrupted is no std::exception)
      ++out.rounds;
      out.iterations += run.iterations;
      out.constraints = static_cast<int>(rows.size());
      out.message = "Ipopt: " + run.status;
      if (!run.finalized) {
        out.message += "; no finite point";
        return finish();
      }
      x = run.x;
      mu.assign(static_cast<std::size_t>(m) * un, 0.0);
      for (std::size_t r = 0; r < rows.size(); ++r)
        mu[static_cast<std::size_t>(rows[r].depth) * un + static_cast<std::size_t>(rows[r].position)] =
            std::max(run.mu[r], 0.0);
      f = yield_values(s, x);
      // Add, per depth, the four samples outside the set most violated beyond certificate_tol / 10.
      bool added = false;
      for (int j = 0; j < m; ++j) {
        const auto& members = set[static_cast<std::size_t>(j)];
        std::vector<int> violated;
        for (int i = 0; i < n; ++i)
          if (f[static_cast<std::size_t>(j) * un + static_cast<std::size_t>(i)] > add_above &&
              !std::binary_search(members.begin(), members.end(), i))
            violated.push_back(i);
        const std::size_t keep = std::min<std::size_t>(violated.size(), 4);
        std::partial_sort(violated.begin(), violated.begin() + static_cast<std::ptrdiff_t>(keep), violated.end(),
                          [&](int a, int b) {
                            return f[static_cast<std::size_t>(j) * un + static_cast<std::size_t>(a)] >
                                   f[static_cast<std::size_t>(j) * un + static_cast<std::size_t>(b)];
                          });
        auto& d = set[static_cast<std::size_t>(j)];
        for (std::size_t k = 0; k < keep; ++k) d.push_back(violated[k]);
        std::sort(d.begin(), d.end());
        added = added || keep > 0;
      }
      if (!added) break;
      if (out.rounds >= options.max_rounds)
        for (auto& d : set) {
          d.resize(un);
          std::iota(d.begin(), d.end(), 0);
        }
      // The next start: this point scaled strictly inside every yield condition.
      const double fm = *std::max_element(f.begin(), f.end());
      if (fm > 0.0)
        for (double& v : x) v *= 0.9 / fm;
    }

    x = run.x;  // f and mu are this point's
    out.load_factor = x[0];
    for (int j = 0; j < m; ++j) out.residual[static_cast<std::size_t>(j)] = s.residual(x.data() + 1 + j * p);

    // Primal: the largest yield function at Ipopt's point, over every sample.
    const double vmax = *std::max_element(f.begin(), f.end());
    ShakedownCertificate& cert = out.certificate;
    cert.yield_violation = std::max(vmax - 1.0, 0.0);
    cert.lower_bound = vmax > 0.0 ? std::max(x[0], 0.0) / vmax : 0.0;

    // Dual: (2) from the clipped multipliers; the critical depth carries most of them.
    double total = 0.0, q = 0.0, heaviest = -1.0;
    for (int j = 0; j < m; ++j) {
      const double* mu_j = mu.data() + static_cast<std::size_t>(j) * un;
      const double mass = std::accumulate(mu_j, mu_j + n, 0.0);
      total += mass;
      if (mass > heaviest) {
        heaviest = mass;
        out.critical_depth = j;
      }
      q += weighted_residual(s, j, mu_j);
    }
    cert.upper_bound = q > 0.0 ? std::sqrt(total / q) : kShakedownInf;
    cert.duality_gap = std::isfinite(cert.upper_bound) && cert.upper_bound > 0.0
                           ? (cert.upper_bound - cert.lower_bound) / cert.upper_bound
                           : kShakedownInf;

    const bool certified = cert.yield_violation <= options.certificate_tol &&
                           std::abs(cert.duality_gap) <= options.certificate_tol;
    out.status = certified ? ShakedownStatus::optimal : ShakedownStatus::not_converged;
    if (!certified)
      out.message += "; certificate: yield violation " + format_number(cert.yield_violation) + ", duality gap " +
                     format_number(cert.duality_gap) + " (tolerance " + format_number(options.certificate_tol) + ")";
  } catch (const Ipopt::IpoptException& e) {
    out.status = ShakedownStatus::failed;
    out.message = "Ipopt exception: " + e.Message();
  } catch (const std::exception& e) {
    out.status = ShakedownStatus::failed;
    out.message = std::string("shakedown: ") + e.what();
  }
  return finish();
}

}  // namespace dc
