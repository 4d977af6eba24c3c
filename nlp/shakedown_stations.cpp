// Program (1') of shakedown_stations.hpp as an Ipopt TNLP over a working set of samples,
// constraint generation around it, and the certificate (2) on every sample.
// Unknowns x = (lambda, theta); Ipopt minimises -lambda. Constraint r is sample (s, i) = rows[r]:
// g = |lambda u_si + W_s theta[I_s]|^2 <= 1, with (v = lambda u + W_s theta[I_s])
//   dg/dlambda = 2 u.v,  dg/dtheta[I_s] = 2 W_s'v,
//   d2g = 2 [u'u, u'W_s; W_s'u, W_s'W_s]  on (lambda, theta[I_s]).
// Ipopt's Lagrangian is f + sum mu g, so its multipliers of the active constraints g <= 1 are
// >= 0: the mu of (2) (zero for the samples outside the working set).
//
// Why a working set: with every sample (64 x 256) the KKT matrix has 16384 slack rows coupled
// through the dense lambda column; MUMPS's analysis and factorisations took 1 s of CPU for the
// 13-16 iterations. Few samples of a station ever bind (the peaks of the orthogonal shear), so
// the working set stays at a few per station and each Ipopt solve is small.
#include "shakedown_stations.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include "interrupt.hpp"
#include "ipopt_shared.hpp"
#include "solver_report.hpp"

namespace dc {

namespace {

constexpr double kShakedownIpoptInf = 1e19;  // Ipopt's default nlp_upper_bound_inf
constexpr double kShakedownInf = std::numeric_limits<double>::infinity();

struct SampleIndex {
  int station = 0, position = 0;
};

class ShakedownTnlp final : public Ipopt::TNLP {
 public:
  using Index = Ipopt::Index;
  using Number = Ipopt::Number;

  /// `rows` sorted by station; `start` the starting point (1 + unknowns values).
  ShakedownTnlp(const ShakedownStations& s, const std::vector<SampleIndex>& rows, const std::vector<double>& start)
      : s_(s), rows_(rows), start_(start) {
    // The Hessian's lower triangle: (0, 0), and per station of the working set the pairs of
    // (lambda, theta[I_s]); entry e of station s's local lower triangle maps to slot_[s][e].
    std::vector<int> present;
    for (const SampleIndex& r : rows_)
      if (present.empty() || present.back() != r.station) present.push_back(r.station);
    std::vector<std::pair<Index, Index>> pairs{{0, 0}};
    for (const int st : present) {
      const std::vector<int>& idx = s_.index[static_cast<std::size_t>(st)];
      for (std::size_t a = 0; a < idx.size(); ++a) {
        pairs.emplace_back(1 + idx[a], 0);
        for (std::size_t b = 0; b <= a; ++b) pairs.emplace_back(1 + idx[a], 1 + idx[b]);
      }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    hess_ = pairs;
    slot_.assign(static_cast<std::size_t>(s_.stations), {});
    wtw_.assign(static_cast<std::size_t>(s_.stations), Eigen::MatrixXd());
    const auto find = [&](Index r, Index c) {
      return static_cast<Index>(std::lower_bound(hess_.begin(), hess_.end(), std::make_pair(r, c)) - hess_.begin());
    };
    for (const int st : present) {
      const std::vector<int>& idx = s_.index[static_cast<std::size_t>(st)];
      std::vector<Index>& slots = slot_[static_cast<std::size_t>(st)];
      for (std::size_t a = 0; a < idx.size(); ++a) {
        slots.push_back(find(1 + idx[a], 0));
        for (std::size_t b = 0; b <= a; ++b) slots.push_back(find(1 + idx[a], 1 + idx[b]));
      }
      const Eigen::MatrixXd& w = s_.w[static_cast<std::size_t>(st)];
      wtw_[static_cast<std::size_t>(st)] = w.transpose() * w;
    }
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag, IndexStyleEnum& style) override {
    n = 1 + s_.unknowns;
    m = static_cast<Index>(rows_.size());
    nnz_jac_g = 0;
    for (const SampleIndex& r : rows_) nnz_jac_g += 1 + static_cast<Index>(s_.index[static_cast<std::size_t>(r.station)].size());
    nnz_h_lag = static_cast<Index>(hess_.size());
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
        for (const int c : idx(r)) {
          rows[e] = r;
          cols[e++] = 1 + c;
        }
      }
      return true;
    }
    for (Index r = 0; r < m; ++r) {
      const Eigen::VectorXd vr = v(x, r);
      values[e++] = 2.0 * u(r).dot(vr);
      const Eigen::VectorXd wv = 2.0 * w(r).transpose() * vr;
      for (Eigen::Index c = 0; c < wv.size(); ++c) values[e++] = wv(c);
    }
    return true;
  }

  bool eval_h(Index, const Number*, bool, Number, Index m, const Number* mu, bool, Index, Index* rows, Index* cols,
              Number* values) override {
    if (values == nullptr) {
      for (std::size_t e = 0; e < hess_.size(); ++e) {
        rows[e] = hess_[e].first;
        cols[e] = hess_[e].second;
      }
      return true;
    }
    // The objective is linear: only the constraints' curvature, 2 mu [u'u, u'W; W'u, W'W].
    std::fill(values, values + hess_.size(), 0.0);
    for (Index r = 0; r < m; ++r) {
      const int st = rows_[static_cast<std::size_t>(r)].station;
      const Eigen::VectorXd ur = u(r);
      const Eigen::VectorXd wu = w(r).transpose() * ur;
      const Eigen::MatrixXd& wtw = wtw_[static_cast<std::size_t>(st)];
      const std::vector<Index>& slots = slot_[static_cast<std::size_t>(st)];
      const double c = 2.0 * mu[r];
      values[0] += c * ur.squaredNorm();
      std::size_t e = 0;
      for (Eigen::Index a = 0; a < wu.size(); ++a) {
        values[slots[e++]] += c * wu(a);
        for (Eigen::Index b = 0; b <= a; ++b) values[slots[e++]] += c * wtw(a, b);
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
  const std::vector<int>& idx(Index r) const { return s_.index[static_cast<std::size_t>(rows_[static_cast<std::size_t>(r)].station)]; }
  const Eigen::MatrixXd& w(Index r) const { return s_.w[static_cast<std::size_t>(rows_[static_cast<std::size_t>(r)].station)]; }
  Eigen::Ref<const Eigen::VectorXd> u(Index r) const {
    const SampleIndex& k = rows_[static_cast<std::size_t>(r)];
    return s_.sample(k.station, k.position);
  }
  /// lambda u + W_s theta[I_s] of constraint r.
  Eigen::VectorXd v(const Number* x, Index r) const {
    Eigen::VectorXd out = x[0] * u(r);
    const std::vector<int>& ix = idx(r);
    const Eigen::MatrixXd& wr = w(r);
    for (std::size_t c = 0; c < ix.size(); ++c) out += wr.col(static_cast<Eigen::Index>(c)) * x[1 + ix[c]];
    return out;
  }

  const ShakedownStations& s_;
  const std::vector<SampleIndex>& rows_;
  const std::vector<double>& start_;
  std::vector<std::pair<Index, Index>> hess_;
  std::vector<std::vector<Index>> slot_;
  std::vector<Eigen::MatrixXd> wtw_;
};

/// W_s theta[I_s] of station s at the unknowns theta (x + 1).
Eigen::VectorXd station_residual(const ShakedownStations& s, int st, const double* theta) {
  const std::vector<int>& ix = s.index[static_cast<std::size_t>(st)];
  const Eigen::MatrixXd& w = s.w[static_cast<std::size_t>(st)];
  Eigen::VectorXd out = Eigen::VectorXd::Zero(s.u.rows());
  for (std::size_t c = 0; c < ix.size(); ++c) out += w.col(static_cast<Eigen::Index>(c)) * theta[ix[c]];
  return out;
}

/// Q = min_theta sum_si mu_si |u_si + W_s theta[I_s]|^2 (shakedown_stations.hpp; mu empty: every
/// weight 1; else one per sample, station-major), summed as non-negative terms at the least-squares
/// minimiser. The minimiser solves the normal equations
///   (sum_s m_s W_s'W_s) theta = -sum_s W_s' b_s
/// (sparse; singular where no weighted station sees an unknown, consistent all the same), by a
/// sparse LDL' of the matrix shifted by 1e-14 of its largest diagonal and three steps of iterative
/// refinement on the unshifted one: Q at that theta exceeds the minimum by a term quadratic in the
/// solve's error, far below the certificate's tolerance.
double weighted_station_residual(const ShakedownStations& s, const std::vector<double>& mu) {
  const int n = s.positions;
  const Eigen::Index q = s.u.rows();
  const auto weight = [&](int st, int i) {
    return mu.empty() ? 1.0 : mu[static_cast<std::size_t>(st) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)];
  };
  std::vector<int> weighted;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(s.unknowns);
  for (int st = 0; st < s.stations; ++st) {
    double m = 0.0;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(q);
    for (int i = 0; i < n; ++i)
      if (const double wgt = weight(st, i); wgt != 0.0) {
        m += wgt;
        b += wgt * s.sample(st, i);
      }
    if (!(m > 0.0)) continue;
    weighted.push_back(st);
    const std::vector<int>& ix = s.index[static_cast<std::size_t>(st)];
    const Eigen::MatrixXd& w = s.w[static_cast<std::size_t>(st)];
    const Eigen::MatrixXd wtw = m * (w.transpose() * w);
    const Eigen::VectorXd wtb = w.transpose() * b;
    for (std::size_t a = 0; a < ix.size(); ++a) {
      rhs(ix[a]) -= wtb(static_cast<Eigen::Index>(a));
      for (std::size_t c = 0; c < ix.size(); ++c)
        if (const double v = wtw(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(c)); v != 0.0)
          entries.emplace_back(ix[a], ix[c], v);
    }
  }
  if (weighted.empty()) return 0.0;
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(s.unknowns);
  if (s.unknowns > 0 && !entries.empty()) {
    Eigen::SparseMatrix<double> h(s.unknowns, s.unknowns);
    h.setFromTriplets(entries.begin(), entries.end());
    const double shift = 1e-14 * std::max(h.diagonal().maxCoeff(), std::numeric_limits<double>::min());
    Eigen::SparseMatrix<double> shifted = h;
    for (Eigen::Index k = 0; k < s.unknowns; ++k) shifted.coeffRef(k, k) += shift;
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(shifted);
    if (ldlt.info() == Eigen::Success) {
      theta = ldlt.solve(rhs);
      for (int step = 0; step < 3; ++step) theta += ldlt.solve(rhs - h * theta);
      if (!theta.allFinite()) theta.setZero();
    }
  }
  double total = 0.0;
  for (const int st : weighted) {
    const Eigen::VectorXd wy = station_residual(s, st, theta.data());
    for (int i = 0; i < n; ++i)
      if (const double wgt = weight(st, i); wgt != 0.0) total += wgt * (s.sample(st, i) + wy).squaredNorm();
  }
  return total;
}

/// True when no station limits lambda: one theta absorbs every sample (u_si = -W_s theta[I_s]).
/// A station whose samples no vector of W_s's range absorbs (relative 1e-20 of its own size)
/// settles it at once; when every station can on its own and they share no unknown, they all
/// can together; else Q with unit weights decides.
bool residual_absorbs_everything(const ShakedownStations& s) {
  const Eigen::Index q = s.u.rows();
  std::vector<int> owner(static_cast<std::size_t>(s.unknowns), -1);
  bool shared = false;
  for (int st = 0; st < s.stations; ++st) {
    const Eigen::MatrixXd& w = s.w[static_cast<std::size_t>(st)];
    Eigen::MatrixXd basis(q, 0);
    if (w.cols() > 0) {
      const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(w);
      basis = qr.householderQ() * Eigen::MatrixXd::Identity(q, qr.rank());
    }
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(q);
    double size = 0.0;
    for (int i = 0; i < s.positions; ++i) {
      mean += s.sample(st, i) / s.positions;
      size += s.sample(st, i).squaredNorm();
    }
    const Eigen::VectorXd absorbed = basis * (basis.transpose() * mean);
    double left = 0.0;
    for (int i = 0; i < s.positions; ++i) left += (s.sample(st, i) - absorbed).squaredNorm();
    if (left > 1e-20 * size) return false;
    for (const int id : s.index[static_cast<std::size_t>(st)]) {
      int& o = owner[static_cast<std::size_t>(id)];
      shared = shared || (o >= 0 && o != st);
      o = st;
    }
  }
  return !shared || !(weighted_station_residual(s, {}) > 1e-20 * s.u.squaredNorm());
}

/// The yield function |lambda u_si + W_s theta| of every sample at x, station-major.
std::vector<double> station_yield_values(const ShakedownStations& s, const std::vector<double>& x) {
  std::vector<double> f(static_cast<std::size_t>(s.stations) * static_cast<std::size_t>(s.positions));
  for (int st = 0; st < s.stations; ++st) {
    const Eigen::VectorXd wy = station_residual(s, st, x.data() + 1);
    for (int i = 0; i < s.positions; ++i)
      f[static_cast<std::size_t>(st) * static_cast<std::size_t>(s.positions) + static_cast<std::size_t>(i)] =
          (x[0] * s.sample(st, i) + wy).norm();
  }
  return f;
}

/// The first working set: per station the sample of largest |u| (first yield), the extremes of
/// the projections on an orthonormal basis of W_s's range, and the largest part across it.
std::vector<std::vector<int>> first_station_working_set(const ShakedownStations& s) {
  const Eigen::Index q = s.u.rows();
  std::vector<std::vector<int>> set(static_cast<std::size_t>(s.stations));
  for (int st = 0; st < s.stations; ++st) {
    const Eigen::MatrixXd& w = s.w[static_cast<std::size_t>(st)];
    Eigen::Index p = 0;
    Eigen::MatrixXd basis(q, 0);
    if (w.cols() > 0) {
      const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(w);
      p = qr.rank();
      basis = qr.householderQ() * Eigen::MatrixXd::Identity(q, p);
    }
    std::vector<int> pick(static_cast<std::size_t>(2 + 2 * p), 0);
    std::vector<double> best(pick.size(), -kShakedownInf);
    for (int i = 0; i < s.positions; ++i) {
      const Eigen::VectorXd u = s.sample(st, i);
      const Eigen::VectorXd along = basis.transpose() * u;
      std::vector<double> score{u.squaredNorm(), (u - basis * along).squaredNorm()};
      for (Eigen::Index c = 0; c < p; ++c) {
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
    set[static_cast<std::size_t>(st)] = std::move(pick);
  }
  return set;
}

struct IpoptRun {
  bool finalized = false;
  std::string status;
  int iterations = 0;
  std::vector<double> x, mu;  // mu: one per row
};

IpoptRun run_shakedown_ipopt(const ShakedownStations& s, const std::vector<SampleIndex>& rows,
                             const std::vector<double>& start, const ShakedownOptions& options) {
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

}  // namespace

ShakedownStations depth_stations(const ShakedownSamples& samples) {
  ShakedownStations s;
  s.stations = samples.depths;
  s.positions = samples.positions;
  const int p = samples.p();
  s.unknowns = samples.depths * p;
  s.u = samples.u;
  s.index.resize(static_cast<std::size_t>(s.stations));
  s.w.assign(static_cast<std::size_t>(s.stations), samples.w);
  for (int j = 0; j < s.stations; ++j)
    for (int c = 0; c < p; ++c) s.index[static_cast<std::size_t>(j)].push_back(j * p + c);
  return s;
}

void set_shakedown_verdict(ShakedownResult& r) {
  if (r.elastic_limit >= 1.0)
    r.verdict = ShakedownVerdict::elastic;
  else if (r.status == ShakedownStatus::unbounded || r.certificate.lower_bound >= 1.0)
    r.verdict = ShakedownVerdict::elastic_shakedown;
  else if (r.status != ShakedownStatus::failed && r.limit_upper_bound < 1.0)
    r.verdict = ShakedownVerdict::beyond_shakedown;
  else
    r.verdict = ShakedownVerdict::undetermined;
}

ShakedownResult solve_shakedown_stations(const ShakedownStations& s, const ShakedownOptions& options,
                                         std::vector<double>& theta) {
  const int m = s.stations, n = s.positions;
  const std::size_t un = static_cast<std::size_t>(n);
  ShakedownResult out;
  theta.assign(static_cast<std::size_t>(s.unknowns), 0.0);

  // First yield: the largest |u_si|.
  Eigen::Index worst = 0;
  const double fmax = std::sqrt(s.u.colwise().squaredNorm().maxCoeff(&worst));
  out.elastic_limit = fmax > 0.0 ? 1.0 / fmax : kShakedownInf;
  out.elastic_limit_depth = static_cast<int>(worst / n);
  out.elastic_limit_position = static_cast<int>(worst % n);

  if (residual_absorbs_everything(s)) {
    out.status = ShakedownStatus::unbounded;
    out.message = "unbounded: the residual stress absorbs the stress of every depth";
    out.load_factor = out.certificate.lower_bound = out.certificate.upper_bound = kShakedownInf;
    return out;
  }

  // The working set, by station (positions sorted).
  std::vector<std::vector<int>> set(static_cast<std::size_t>(m));
  if (options.constraint_generation) {
    set = first_station_working_set(s);
  } else {
    for (auto& d : set) {
      d.resize(un);
      std::iota(d.begin(), d.end(), 0);
    }
  }
  std::vector<double> x(static_cast<std::size_t>(1 + s.unknowns), 0.0), f;
  x[0] = 0.5 * out.elastic_limit;  // strictly inside: every g <= 1/4
  std::vector<double> mu;          // one per sample, station-major
  const double add_above = 1.0 + 0.1 * options.certificate_tol;
  try {
    IpoptRun run;
    for (bool last = false; !last;) {
      std::vector<SampleIndex> rows;
      for (int j = 0; j < m; ++j)
        for (const int i : set[static_cast<std::size_t>(j)]) rows.push_back({j, i});
      // The last round's program holds every sample: after max_rounds, or when it already did.
      last = rows.size() == static_cast<std::size_t>(m) * un;
      run = run_shakedown_ipopt(s, rows, x, options);
      throw_if_interrupted();  // Ipopt stopped at the request: unwind (Interrupted is no std::exception)
      ++out.rounds;
      out.iterations += run.iterations;
      out.constraints = static_cast<int>(rows.size());
      out.message = "Ipopt: " + run.status;
      if (!run.finalized) {
        out.message += "; no finite point";
        return out;
      }
      x = run.x;
      mu.assign(static_cast<std::size_t>(m) * un, 0.0);
      for (std::size_t r = 0; r < rows.size(); ++r)
        mu[static_cast<std::size_t>(rows[r].station) * un + static_cast<std::size_t>(rows[r].position)] =
            std::max(run.mu[r], 0.0);
      f = station_yield_values(s, x);
      // Add, per station, the four samples outside the set most violated beyond certificate_tol / 10.
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
    theta.assign(x.begin() + 1, x.end());

    // Primal: the largest yield function at Ipopt's point, over every sample.
    const double vmax = *std::max_element(f.begin(), f.end());
    ShakedownCertificate& cert = out.certificate;
    cert.yield_violation = std::max(vmax - 1.0, 0.0);
    cert.lower_bound = vmax > 0.0 ? std::max(x[0], 0.0) / vmax : 0.0;

    // Dual: (2) from the clipped multipliers; the critical station carries most of them.
    double total = 0.0, heaviest = -1.0;
    for (int j = 0; j < m; ++j) {
      const double* mu_j = mu.data() + static_cast<std::size_t>(j) * un;
      const double mass = std::accumulate(mu_j, mu_j + n, 0.0);
      total += mass;
      if (mass > heaviest) {
        heaviest = mass;
        out.critical_depth = j;
      }
    }
    const double q = weighted_station_residual(s, mu);
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
  return out;
}

}  // namespace dc
