#include "saddle_form.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include <Eigen/Sparse>

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include "interrupt.hpp"
#include "ipopt_shared.hpp"
#include "stress_equilibrium.hpp"

namespace dc {
namespace {

using Ipopt::Index;
using Ipopt::Number;
using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// The program in scaled unknowns x = (p / p_ref, s / s_ref, a_j / a_ref_j) (s: the weighted
/// stresses of stress_equilibrium.hpp): the pressure and stress blocks have Hessian diagonals of
/// order one, every equality row is of order one.
struct SaddleScaling {
  double p_ref = 1.0, s_ref = 1.0, f_ref = 1.0, force_ref = 1.0, n_ref = 1.0;
  Eigen::Matrix<double, 6, 1> a_ref, rigid_row;
};

class SaddleTnlp final : public Ipopt::TNLP {
 public:
  SaddleTnlp(const fe::ElasticBody& body, const fe::ContactFace& face, const LinearOperator& halfspace,
             const Grid& grid, const std::vector<double>& heights, const NormalSpec& control,
             const SolveOptions& options, bool exact)
      : body_(body), halfspace_(halfspace), heights_(heights), control_(control), options_(options),
        N_(static_cast<Index>(grid.size())), n_(static_cast<Index>(body.dofs())), area_(grid.area()),
        stresses_(fe::stress_equilibrium(body)), ns_(static_cast<Index>(stresses_.stresses())) {
    set_scales();
    build_jacobian(face);
    c_.assign(static_cast<std::size_t>(N_), 0.0);
    const double delta = control_.control == Control::approach ? control_.value : 0.0;
    for (Index i = 0; i < N_; ++i)
      if (std::isfinite(heights_[i])) c_[i] = s_.p_ref * area_ * (heights_[i] - delta) / s_.f_ref;
    if (exact) build_hessian();
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag, IndexStyleEnum& style) override {
    n = N_ + ns_ + 6;
    m = static_cast<Index>(J_.rows());
    nnz_jac_g = static_cast<Index>(J_.nonZeros());
    nnz_h_lag = static_cast<Index>(h_rows_.size());
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l, Number* g_u) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = -1e19;
      x_u[i] = 1e19;
    }
    for (Index i = 0; i < N_; ++i) {
      x_l[i] = 0.0;
      if (!std::isfinite(heights_[i])) x_u[i] = 0.0;  // cannot touch
    }
    for (Index k = 0; k < m; ++k) g_l[k] = g_u[k] = 0.0;
    if (control_.control == Control::force) g_l[m - 1] = g_u[m - 1] = 1.0;  // sum p A / (A p_ref n_ref)
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*, Index, bool init_lambda,
                          Number*) override {
    if (init_z || init_lambda) return false;
    if (!init_x) return true;
    std::fill(x, x + n, 0.0);
    Index n_free = 0;
    for (Index i = 0; i < N_; ++i) n_free += std::isfinite(heights_[i]) ? 1 : 0;
    for (Index i = 0; i < N_; ++i)
      if (std::isfinite(heights_[i])) x[i] = s_.n_ref / static_cast<double>(n_free);  // the force row holds
    return true;
  }

  bool eval_f(Index n, const Number* x, bool, Number& f) override {
    evaluate(n, x);
    f = f_;
    return true;
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* g) override {
    evaluate(n, x);
    std::copy(grad_.begin(), grad_.end(), g);
    return true;
  }

  bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
    Eigen::Map<Eigen::VectorXd>(g, m) = J_ * Eigen::Map<const Eigen::VectorXd>(x, n);
    return true;
  }

  bool eval_jac_g(Index, const Number*, bool, Index, Index, Index* rows, Index* cols, Number* values) override {
    Index e = 0;
    for (Eigen::Index r = 0; r < J_.outerSize(); ++r)
      for (RowMatrix::InnerIterator it(J_, r); it; ++it, ++e) {
        if (values) {
          values[e] = it.value();
        } else {
          rows[e] = static_cast<Index>(it.row());
          cols[e] = static_cast<Index>(it.col());
        }
      }
    return true;
  }

  bool eval_h(Index, const Number*, bool, Number obj_factor, Index, const Number*, bool, Index, Index* rows,
              Index* cols, Number* values) override {
    if (h_rows_.empty()) return false;  // limited memory never asks
    if (!values) {
      std::copy(h_rows_.begin(), h_rows_.end(), rows);
      std::copy(h_cols_.begin(), h_cols_.end(), cols);
      return true;
    }
    for (std::size_t e = 0; e < h_values_.size(); ++e) values[e] = obj_factor * h_values_[e];
    return true;  // the constraints are linear
  }

  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number*, const Number*, Index m,
                         const Number*, const Number* lambda, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    x_.assign(x, x + n);
    lambda_.assign(lambda, lambda + m);
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number obj, Number inf_pr, Number, Number, Number,
                             Number, Number, Number, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    iterations_ = std::max(iterations_, static_cast<int>(iter));
    if (options_.progress) options_.progress(ProgressInfo{static_cast<int>(iter), obj, inf_pr});
    return !interrupt_requested();
  }

  /// The result in physical units (empty pressure when Ipopt never finished).
  void unscale(SaddleNormalOutcome& out) const {
    if (x_.empty()) return;
    out.pressure.resize(static_cast<std::size_t>(N_));
    for (Index i = 0; i < N_; ++i) out.pressure[i] = std::max(x_[i], 0.0) * s_.p_ref;
    // The equilibrium rows' multipliers are the displacement of the supported body: stationarity
    // in sigma gives H sigma = Gt'(-lambda f_ref / force_ref), i.e. sigma = C B u with v = that.
    // u = v - R (R'M R)^-1 (M R)'v: the displacement relative to the body's mean rigid motion.
    Eigen::VectorXd v = Eigen::VectorXd::Zero(n_);
    for (Index dof = 0; dof < n_; ++dof)
      if (row_of_dof_[static_cast<std::size_t>(dof)] >= 0)
        v(dof) = -s_.f_ref / s_.force_ref * lambda_[static_cast<std::size_t>(row_of_dof_[static_cast<std::size_t>(dof)])];
    const Eigen::Matrix<double, 6, 1> r = body_.rigid_mass().ldlt().solve(body_.mass_rigid_modes().transpose() * v);
    out.body_displacement = v - body_.rigid_modes() * r;
    std::vector<double> w_hs;
    halfspace_.apply(out.pressure, w_hs);
    out.displacement.assign(static_cast<std::size_t>(N_), 0.0);
    for (Eigen::Index k = 0; k < Bt_.outerSize(); ++k) {
      double s = 0.0;
      for (RowMatrix::InnerIterator it(Bt_, k); it; ++it) s += it.value() * out.body_displacement(3 * it.col() + 2);
      out.displacement[static_cast<std::size_t>(k)] = w_hs[static_cast<std::size_t>(k)] + s / area_;
    }
    out.iterations = iterations_;
  }

 private:
  void set_scales() {
    Index n_free = 0;
    for (Index i = 0; i < N_; ++i) n_free += std::isfinite(heights_[i]) ? 1 : 0;
    const double c0 = halfspace_.diagonal(0);
    // As NormalProblem scales (4.7): p_ref is the pressure of the force on a quarter of the grid.
    s_.n_ref = std::max(1.0, 0.25 * static_cast<double>(n_free));
    s_.p_ref = control_.control == Control::force ? control_.value / (area_ * s_.n_ref)
                                                   : control_.value / (c0 * std::sqrt(s_.n_ref));
    s_.f_ref = area_ * c0 * s_.p_ref * s_.p_ref;
    double mean_compliance = 0.0;
    for (const auto& H : stresses_.compliance) mean_compliance += H(0, 0) / static_cast<double>(stresses_.compliance.size());
    s_.s_ref = std::sqrt(s_.f_ref / mean_compliance);
    s_.force_ref = s_.p_ref * area_;        // the force on one grid element
    const double total = s_.force_ref * s_.n_ref;
    const Eigen::Matrix<double, 6, 6>& RMR = body_.rigid_mass();
    for (int j = 0; j < 6; ++j) {
      const double lever = j < 3 ? 1.0 : std::sqrt(RMR(j, j) / body_.mass());  // radius of gyration
      s_.rigid_row(j) = 1.0 / (total * lever);
      s_.a_ref(j) = total * lever / RMR(j, j);
    }
  }

  /// The equality rows, scaled: the body's equilibrium Gt sigma = B p - M R a at every dof but
  /// the six held ones (their rows follow from the rigid-mode rows), rigid modes (6), force
  /// (force control).
  void build_jacobian(const fe::ContactFace& face) {
    Bt_ = face.transfer();
    const Eigen::MatrixXd& MR = body_.mass_rigid_modes();
    const Eigen::MatrixXd& R = body_.rigid_modes();
    row_of_dof_.assign(static_cast<std::size_t>(n_), 0);
    for (int s : body_.supports()) row_of_dof_[static_cast<std::size_t>(s)] = -1;
    Index equilibrium_rows = 0;
    for (auto& r : row_of_dof_)
      if (r >= 0) r = equilibrium_rows++;
    const Index col_s = N_, col_a = N_ + ns_;
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(stresses_.forces.nonZeros() + 7 * n_ + 7 * N_));
    const double ks = s_.s_ref / s_.force_ref;
    for (Eigen::Index c = 0; c < stresses_.forces.outerSize(); ++c)  // Gt sigma
      for (Eigen::SparseMatrix<double>::InnerIterator it(stresses_.forces, c); it; ++it) {
        const Index row = row_of_dof_[static_cast<std::size_t>(it.row())];
        if (row >= 0) t.emplace_back(row, col_s + it.col(), ks * it.value());
      }
    Eigen::Matrix<double, 6, Eigen::Dynamic> RtB = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, N_);
    const double kp = s_.p_ref / s_.force_ref;
    for (Eigen::Index k = 0; k < Bt_.outerSize(); ++k)
      for (RowMatrix::InnerIterator it(Bt_, k); it; ++it) {
        const Eigen::Index dof = 3 * it.col() + 2;  // the pressure pushes the body up (+z)
        RtB.col(k) += it.value() * R.row(dof).transpose();
        const Index row = row_of_dof_[static_cast<std::size_t>(dof)];
        if (row >= 0) t.emplace_back(row, k, -kp * it.value());
      }
    for (Index dof = 0; dof < n_; ++dof)  // + M R a: the inertia relief
      if (const Index row = row_of_dof_[static_cast<std::size_t>(dof)]; row >= 0)
        for (int j = 0; j < 6; ++j)
          if (MR(dof, j) != 0.0) t.emplace_back(row, col_a + j, s_.a_ref(j) / s_.force_ref * MR(dof, j));
    const Eigen::Matrix<double, 6, 6>& RMR = body_.rigid_mass();
    for (int j = 0; j < 6; ++j) {
      for (int l = 0; l < 6; ++l)
        if (RMR(j, l) != 0.0) t.emplace_back(equilibrium_rows + j, col_a + l, s_.rigid_row(j) * s_.a_ref(l) * RMR(j, l));
      for (Index k = 0; k < N_; ++k)
        if (RtB(j, k) != 0.0) t.emplace_back(equilibrium_rows + j, k, -s_.rigid_row(j) * s_.p_ref * RtB(j, k));
    }
    Index rows = equilibrium_rows + 6;
    if (control_.control == Control::force) {
      for (Index k = 0; k < N_; ++k)
        if (std::isfinite(heights_[k])) t.emplace_back(rows, k, 1.0 / s_.n_ref);
      ++rows;
    }
    J_.resize(rows, N_ + ns_ + 6);
    J_.setFromTriplets(t.begin(), t.end());
  }

  /// Lower triangle of the objective's Hessian: the dense half-space block and the stresses'
  /// 6 x 6 complementary-energy blocks H_q.
  void build_hessian() {
    const Eigen::MatrixXd C = halfspace_.to_dense(static_cast<std::size_t>(N_) * static_cast<std::size_t>(N_));
    const double kp = s_.p_ref * s_.p_ref * area_ / s_.f_ref, ks = s_.s_ref * s_.s_ref / s_.f_ref;
    for (Index i = 0; i < N_; ++i)
      for (Index j = 0; j <= i; ++j) {
        h_rows_.push_back(i);
        h_cols_.push_back(j);
        h_values_.push_back(kp * 0.5 * (C(i, j) + C(j, i)));
      }
    for (std::size_t q = 0; q < stresses_.compliance.size(); ++q) {
      const Index base = N_ + 6 * static_cast<Index>(q);
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j <= i; ++j) {
          h_rows_.push_back(base + i);
          h_cols_.push_back(base + j);
          h_values_.push_back(ks * stresses_.compliance[q](i, j));
        }
    }
  }

  /// f and its gradient at x (one half-space apply and one sparse product), cached.
  void evaluate(Index n, const Number* x) {
    if (have_cache_ && std::equal(x, x + n, cached_x_.begin())) return;
    cached_x_.assign(x, x + n);
    grad_.assign(static_cast<std::size_t>(n), 0.0);
    std::vector<double> xp(x, x + N_), w;
    halfspace_.apply(xp, w);
    const double kp = s_.p_ref * s_.p_ref * area_ / s_.f_ref, ks = s_.s_ref * s_.s_ref / s_.f_ref;
    f_ = 0.0;
    for (Index i = 0; i < N_; ++i) {
      grad_[i] = kp * w[i] + c_[i];
      f_ += x[i] * (0.5 * kp * w[i] + c_[i]);
    }
    for (std::size_t q = 0; q < stresses_.compliance.size(); ++q) {
      const Eigen::Map<const Eigen::Matrix<double, 6, 1>> xs(x + N_ + 6 * q);
      Eigen::Map<Eigen::Matrix<double, 6, 1>> gs(grad_.data() + N_ + 6 * q);
      gs.noalias() = ks * (stresses_.compliance[q] * xs);
      f_ += 0.5 * xs.dot(gs);
    }
    have_cache_ = true;
  }

  const fe::ElasticBody& body_;
  const LinearOperator& halfspace_;
  const std::vector<double>& heights_;
  const NormalSpec& control_;
  const SolveOptions& options_;
  Index N_, n_;
  double area_;
  fe::StressEquilibrium stresses_;
  Index ns_;
  std::vector<Index> row_of_dof_;  // equilibrium row of each dof (-1: held)
  SaddleScaling s_;
  RowMatrix J_, Bt_;
  std::vector<double> c_;
  std::vector<Index> h_rows_, h_cols_;
  std::vector<double> h_values_;
  std::vector<double> cached_x_, grad_, x_, lambda_;
  double f_ = 0.0;
  bool have_cache_ = false;
  int iterations_ = 0;
};

}  // namespace

SaddleNormalOutcome solve_saddle_normal(const fe::ElasticBody& body, const fe::ContactFace& face,
                                        const LinearOperator& halfspace, const Grid& grid,
                                        const std::vector<double>& heights, const NormalSpec& control,
                                        const SolveOptions& options) {
  SaddleNormalOutcome out;
  const bool exact = options.hessian == "exact" || (options.hessian != "limited-memory" && grid.size() <= kSaddleExactLimit);
  out.exact_hessian = exact;
  try {
    const std::lock_guard<std::mutex> lock(ipopt_mutex());
    Ipopt::SmartPtr<SaddleTnlp> tnlp = new SaddleTnlp(body, face, halfspace, grid, heights, control, options, exact);
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
    auto opts = app->Options();
    bool ok = true;
    ok &= opts->SetNumericValue("tol", options.tol);
    ok &= opts->SetIntegerValue("max_iter", options.max_iter);
    ok &= opts->SetIntegerValue("print_level", options.verbose ? 5 : 0);
    // MUMPS's automatic ordering fills the rows of the inertia relief's dense columns (M R a)
    // in: minutes per factorisation for 2k dofs. QAMD (6) keeps dense rows for last: seconds.
    ok &= opts->SetIntegerValue("mumps_pivot_order", 6);
    ok &= opts->SetStringValue("sb", "yes");
    // With the exact Hessian the program is a convex QP: Mehrotra's predictor-corrector takes
    // 11 iterations on a 10k-dof body where the default barrier update took 14 (each one a
    // factorisation). The limited-memory Hessian keeps the globalised line search.
    if (exact)
      ok &= opts->SetStringValue("mehrotra_algorithm", "yes");
    else
      ok &= opts->SetStringValue("mu_strategy", "adaptive");
    ok &= opts->SetStringValue("jac_c_constant", "yes");
    ok &= opts->SetStringValue("jac_d_constant", "yes");
    ok &= opts->SetStringValue("hessian_approximation", exact ? "exact" : "limited-memory");
    ok &= opts->SetStringValue("hessian_constant", exact ? "yes" : "no");
    if (!ok) {
      out.message = "Ipopt (sparse form): an option was rejected";
      return out;
    }
    Ipopt::ApplicationReturnStatus status = app->Initialize("");
    if (status == Ipopt::Solve_Succeeded) status = app->OptimizeTNLP(Ipopt::GetRawPtr(tnlp));
    out.success = status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
    out.message = "Ipopt (sparse form, " + std::string(exact ? "exact" : "limited-memory") +
                  " Hessian): " + ipopt_status_name(status);
    tnlp->unscale(out);
    if (out.pressure.empty()) out.success = false;
  } catch (const Ipopt::IpoptException& e) {
    out.success = false;
    out.message = "Ipopt exception: " + e.Message();
  } catch (const std::exception& e) {
    out.success = false;
    out.message = std::string("Ipopt (sparse form) error: ") + e.what();
  }
  return out;
}

}  // namespace dc
