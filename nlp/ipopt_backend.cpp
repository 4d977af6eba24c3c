// Ipopt backend: the quadratic program as an Ipopt TNLP.
//   min f(x) = 1/2 x'Qx + c'x   s.t.  g_k(x) = a_k'x = b_k,  g_d(x) = x_ix^2 + x_iy^2 <= r_d^2,
//   lower <= x <= upper;
// with a sparse block (sparse_block.hpp) over (x, y): + 1/2 y'Hy, and the rows J (x, y) = 0
// after the equalities.
// Ipopt's Lagrangian is f + lambda'g, so its KKT reads Qx + c = -J'lambda + z_L - z_U; our
// equality multipliers (quadratic_program.hpp) are therefore lambda_k = -lambda_ipopt_k.
#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include "ipopt_shared.hpp"
#include "quadratic_program.hpp"
#include "sparse_block.hpp"
#include "sparse_factorisation_hooks.hpp"
#include "interrupt.hpp"

namespace dc {

std::string ipopt_status_name(int code) {
  switch (static_cast<Ipopt::ApplicationReturnStatus>(code)) {
    case Ipopt::Solve_Succeeded: return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level: return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected: return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates: return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop: return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found: return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded: return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed: return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation: return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition: return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option: return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected: return "Invalid_Number_Detected";
    case Ipopt::Unrecoverable_Exception: return "Unrecoverable_Exception";
    case Ipopt::NonIpopt_Exception_Thrown: return "NonIpopt_Exception_Thrown";
    case Ipopt::Insufficient_Memory: return "Insufficient_Memory";
    case Ipopt::Internal_Error: return "Internal_Error";
  }
  return "unknown Ipopt status";
}

bool set_common_ipopt_options(Ipopt::OptionsList& options, double tol, int max_iter, bool verbose) {
  bool ok = options.SetNumericValue("tol", tol);
  ok &= options.SetIntegerValue("max_iter", max_iter);
  ok &= options.SetIntegerValue("print_level", verbose ? 5 : 0);
  ok &= options.SetStringValue("sb", "yes");
  return ok;
}

std::mutex& ipopt_mutex() {
  static std::mutex mutex;
  return mutex;
}

namespace {

using Ipopt::Index;
using Ipopt::Number;
using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

constexpr Number kIpoptInf = 1e19;  // Ipopt's default nlp_{lower,upper}_bound_inf

double bound_or(const std::vector<double>& bounds, int i, double fallback) {
  return bounds.empty() ? fallback : bounds[static_cast<std::size_t>(i)];
}

/// Start: qp.x0 if given, else zero; projected on the bounds either way.
std::vector<double> starting_point(const QuadraticProgram& qp) {
  const int n = qp.n();
  std::vector<double> x(static_cast<std::size_t>(n), 0.0);
  if (qp.x0.size() == x.size()) x = qp.x0;
  for (int i = 0; i < n; ++i) {
    auto& xi = x[static_cast<std::size_t>(i)];
    xi = std::clamp(xi, bound_or(qp.lower, i, -kInf), bound_or(qp.upper, i, kInf));
  }
  return x;
}

class QpTnlp final : public Ipopt::TNLP {
 public:
  /// `hessian` is the dense Q for the exact Hessian, or empty for limited memory.
  QpTnlp(const QuadraticProgram& qp, const SolveOptions& options, const Eigen::MatrixXd& hessian)
      : qp_(qp), options_(options), n_(qp.n()), n_eq_(static_cast<Index>(qp.equalities.size())),
        n_disk_(static_cast<Index>(qp.disks.size())), n_block_(qp.block ? qp.block->n : 0),
        m_block_(qp.block ? static_cast<Index>(qp.block->rows.rows()) : 0), disk_row0_(n_eq_ + m_block_),
        start_(starting_point(qp)) {
    start_.resize(static_cast<std::size_t>(n_ + n_block_), 0.0);  // the block's unknowns start at 0
    if (qp.block) block_hessian_ = qp.block->hessian.selfadjointView<Eigen::Lower>();
    for (Index k = 0; k < n_eq_; ++k) {
      const auto& a = qp.equalities[static_cast<std::size_t>(k)].a;
      for (Index j = 0; j < n_; ++j)
        if (a[static_cast<std::size_t>(j)] != 0.0) eq_nonzeros_.push_back({k, j});
    }
    if (hessian.size() > 0) {
      // Lower triangle of Q, structural zeros dropped but every diagonal kept (disk terms).
      diag_index_.assign(static_cast<std::size_t>(n_), -1);
      for (Index i = 0; i < n_; ++i)
        for (Index j = 0; j <= i; ++j) {
          const double v = 0.5 * (hessian(i, j) + hessian(j, i));
          if (v == 0.0 && i != j) continue;
          if (i == j) diag_index_[static_cast<std::size_t>(i)] = static_cast<Index>(h_rows_.size());
          h_rows_.push_back(i);
          h_cols_.push_back(j);
          h_values_.push_back(v);
        }
      if (qp.block) {  // H, lower triangle, after Q
        const Eigen::SparseMatrix<double>& H = qp.block->hessian;
        for (Eigen::Index c = 0; c < H.outerSize(); ++c)
          for (Eigen::SparseMatrix<double>::InnerIterator it(H, c); it; ++it)
            if (it.row() >= it.col()) {
              h_rows_.push_back(n_ + static_cast<Index>(it.row()));
              h_cols_.push_back(n_ + static_cast<Index>(it.col()));
              h_values_.push_back(it.value());
            }
      }
    }
    x_.assign(start_.begin(), start_.begin() + n_);
    multipliers_.assign(static_cast<std::size_t>(n_eq_), 0.0);
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = n_ + n_block_;
    m = disk_row0_ + n_disk_;
    nnz_jac_g = static_cast<Index>(eq_nonzeros_.size()) + 2 * n_disk_ +
                (qp_.block ? static_cast<Index>(qp_.block->rows.nonZeros()) : 0);
    nnz_h_lag = static_cast<Index>(h_rows_.size());
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index, Number* g_l, Number* g_u) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = i < n_ ? std::max(bound_or(qp_.lower, i, -kInf), -kIpoptInf) : -kIpoptInf;
      x_u[i] = i < n_ ? std::min(bound_or(qp_.upper, i, kInf), kIpoptInf) : kIpoptInf;
    }
    for (Index k = 0; k < n_eq_; ++k) g_l[k] = g_u[k] = qp_.equalities[static_cast<std::size_t>(k)].b;
    for (Index k = n_eq_; k < disk_row0_; ++k) g_l[k] = g_u[k] = 0.0;
    for (Index d = 0; d < n_disk_; ++d) {
      const double r = qp_.disks[static_cast<std::size_t>(d)].radius;
      g_l[disk_row0_ + d] = -kIpoptInf;
      g_u[disk_row0_ + d] = r * r;
    }
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*, Index,
                          bool init_lambda, Number*) override {
    if (init_z || init_lambda) return false;  // no warm start of multipliers
    if (init_x) std::copy(start_.begin(), start_.begin() + n, x);
    return true;
  }

  bool eval_f(Index n, const Number* x, bool, Number& obj_value) override {
    evaluate(n, x);
    obj_value = f_;
    return true;
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad_f) override {
    evaluate(n, x);
    std::copy(g_.begin(), g_.end(), grad_f);
    return true;
  }

  bool eval_g(Index n, const Number* x, bool, Index, Number* g) override {
    for (Index k = 0; k < n_eq_; ++k) g[k] = 0.0;
    for (const auto& [k, j] : eq_nonzeros_)
      g[k] += qp_.equalities[static_cast<std::size_t>(k)].a[static_cast<std::size_t>(j)] * x[j];
    if (qp_.block)
      Eigen::Map<Eigen::VectorXd>(g + n_eq_, m_block_) = qp_.block->rows * Eigen::Map<const Eigen::VectorXd>(x, n);
    for (Index d = 0; d < n_disk_; ++d) {
      const auto& disk = qp_.disks[static_cast<std::size_t>(d)];
      g[disk_row0_ + d] = x[disk.ix] * x[disk.ix] + x[disk.iy] * x[disk.iy];
    }
    return true;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* i_row, Index* j_col,
                  Number* values) override {
    Index e = 0;
    if (values == nullptr) {
      const auto put = [&](Index row, Index col) {
        i_row[e] = row;
        j_col[e++] = col;
      };
      for (const auto& [k, j] : eq_nonzeros_) put(k, j);
      if (qp_.block)
        for (Eigen::Index r = 0; r < qp_.block->rows.outerSize(); ++r)
          for (RowMatrix::InnerIterator it(qp_.block->rows, r); it; ++it)
            put(n_eq_ + static_cast<Index>(it.row()), static_cast<Index>(it.col()));
      for (Index d = 0; d < n_disk_; ++d) {
        const auto& disk = qp_.disks[static_cast<std::size_t>(d)];
        put(disk_row0_ + d, disk.ix);
        put(disk_row0_ + d, disk.iy);
      }
      return true;
    }
    for (const auto& [k, j] : eq_nonzeros_)
      values[e++] = qp_.equalities[static_cast<std::size_t>(k)].a[static_cast<std::size_t>(j)];
    if (qp_.block)
      for (Eigen::Index r = 0; r < qp_.block->rows.outerSize(); ++r)
        for (RowMatrix::InnerIterator it(qp_.block->rows, r); it; ++it) values[e++] = it.value();
    for (Index d = 0; d < n_disk_; ++d) {  // grad (x_ix^2 + x_iy^2) = 2 (x_ix, x_iy)
      const auto& disk = qp_.disks[static_cast<std::size_t>(d)];
      values[e++] = 2.0 * x[disk.ix];
      values[e++] = 2.0 * x[disk.iy];
    }
    return true;
  }

  /// Hessian of the Lagrangian: sigma Q + sum_d 2 lambda_d (e_ix e_ix' + e_iy e_iy').
  bool eval_h(Index, const Number*, bool, Number obj_factor, Index, const Number* lambda, bool,
              Index, Index* i_row, Index* j_col, Number* values) override {
    if (h_rows_.empty()) return false;  // limited-memory mode never asks
    if (values == nullptr) {
      std::copy(h_rows_.begin(), h_rows_.end(), i_row);
      std::copy(h_cols_.begin(), h_cols_.end(), j_col);
      return true;
    }
    for (std::size_t e = 0; e < h_values_.size(); ++e) values[e] = obj_factor * h_values_[e];
    for (Index d = 0; d < n_disk_; ++d) {
      const auto& disk = qp_.disks[static_cast<std::size_t>(d)];
      values[diag_index_[static_cast<std::size_t>(disk.ix)]] += 2.0 * lambda[disk_row0_ + d];
      values[diag_index_[static_cast<std::size_t>(disk.iy)]] += 2.0 * lambda[disk_row0_ + d];
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number*, const Number*,
                         Index, const Number*, const Number* lambda, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    x_.assign(x, x + n_);
    block_x_.assign(x + n_, x + n);
    for (Index k = 0; k < n_eq_; ++k) multipliers_[static_cast<std::size_t>(k)] = -lambda[k];
    finalized_ = true;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number obj_value, Number inf_pr,
                             Number, Number, Number, Number, Number, Number, Index,
                             const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    iterations_ = std::max(iterations_, static_cast<int>(iter));
    if (options_.progress) options_.progress(ProgressInfo{static_cast<int>(iter), obj_value, inf_pr, options_.tol});
    return !interrupt_requested();  // false stops Ipopt; run_backend then throws Interrupted
  }

  std::vector<double> x_, multipliers_, block_x_;
  int iterations_ = 0;
  bool finalized_ = false;

 private:
  /// f and g = Qx + c at x: one operator apply, cached for the next call at the same x.
  void evaluate(Index n, const Number* x) {
    if (have_cache_ && std::equal(x, x + n, cached_x_.begin())) return;
    cached_x_.assign(x, x + n);
    g_.resize(static_cast<std::size_t>(n));
    f_ = qp_.gradient(x, g_.data());
    if (qp_.block) {  // + 1/2 y'Hy
      const Eigen::Map<const Eigen::VectorXd> y(x + n_, n_block_);
      Eigen::Map<Eigen::VectorXd> gy(g_.data() + n_, n_block_);
      gy.noalias() = block_hessian_ * y;
      f_ += 0.5 * y.dot(gy);
    }
    have_cache_ = true;
  }

  struct Nonzero {
    Index row, col;
  };

  const QuadraticProgram& qp_;
  const SolveOptions& options_;
  Index n_, n_eq_, n_disk_, n_block_, m_block_, disk_row0_;
  std::vector<double> start_;
  Eigen::SparseMatrix<double> block_hessian_;  // H, both triangles
  std::vector<Nonzero> eq_nonzeros_;
  std::vector<Index> h_rows_, h_cols_, diag_index_;
  std::vector<double> h_values_;
  std::vector<double> cached_x_, g_;
  double f_ = 0.0;
  bool have_cache_ = false;
};

bool use_exact_hessian(const QuadraticProgram& qp, const SolveOptions& options) {
  if (options.hessian == Hessian::exact) return true;
  if (options.hessian == Hessian::limited_memory) return false;
  return qp.n() <= options.exact_hessian_limit;
}


}  // namespace

SolveOutcome solve_with_ipopt(const QuadraticProgram& qp, const SolveOptions& options) {
  SolveOutcome out;
  if (const std::string why = qp.invalid_reason(); !why.empty()) {
    out.message = "Ipopt: invalid program: " + why;
    return out;
  }
  out.x = starting_point(qp);
  out.equality_multipliers.assign(qp.equalities.size(), 0.0);
  if (qp.n() == 0) {
    out.success = true;
    out.message = "Ipopt: empty program";
    return out;
  }
  try {
    // One Ipopt application at a time (threaded tables); the lock outlives the application.
    const std::lock_guard<std::mutex> lock(ipopt_mutex());
    // The finite body's saddle form: the program's tuning of MUMPS's factorisations, if it
    // installed one (sparse_factorisation_hooks.hpp: METIS's ordering, the freed memory kept;
    // mumps_pivot_order below is what MUMPS does without it), left after the application
    // (declared after this guard) is gone.
    std::optional<SparseFactorisationScope> tuned;
    if (qp.block) tuned.emplace();
    const bool exact = use_exact_hessian(qp, options);
    const bool disks = !qp.disks.empty();
    const Eigen::MatrixXd dense_q = exact ? qp.Q->to_dense() : Eigen::MatrixXd();

    Ipopt::SmartPtr<QpTnlp> tnlp = new QpTnlp(qp, options, dense_q);
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
    auto opts = app->Options();
    bool ok = set_common_ipopt_options(*opts, options.tol, options.max_iter, options.verbose);
    // The finite body's sparse form with the exact Hessian is a convex QP: Mehrotra's
    // predictor-corrector takes 11 iterations on a 10k-dof body where the default barrier
    // update took 14, each a factorisation of the KKT matrix. Its least-squares start (primal
    // and duals) costs one more factorisation: without it, the same 11 and 12 iterations at 10k
    // and 50k dofs, Ipopt's own time at 50k 52 -> 47 s (docs/finite.md, "Performance").
    if (qp.block && exact && !disks) {
      ok &= opts->SetStringValue("mehrotra_algorithm", "yes");
      ok &= opts->SetStringValue("least_square_init_primal", "no");
      ok &= opts->SetStringValue("least_square_init_duals", "no");
    } else
      ok &= opts->SetStringValue("mu_strategy", "adaptive");
    ok &= opts->SetStringValue("jac_c_constant", "yes");
    ok &= opts->SetStringValue("jac_d_constant", disks ? "no" : "yes");
    ok &= opts->SetStringValue("hessian_approximation", exact ? "exact" : "limited-memory");
    ok &= opts->SetStringValue("hessian_constant", exact && !disks ? "yes" : "no");
    // A sparse block (the finite body's saddle form): MUMPS's orderings of the KKT matrix of a
    // 10k-dof body on a 32^2 grid took, per factorisation, AMF 1.5e12 flops (its automatic
    // choice filled the rows of the dense inertia-relief columns M R a in), QAMD 2.0e10, AMD
    // 7.0e9 and nested dissection 3.5e9-4.9e9 (0.3 s); at 50k dofs nested dissection 4.7e10,
    // AMD 1.2e11, QAMD 1.5e11. Debian's sequential MUMPS has no METIS: 5 orders with SCOTCH (as
    // 3), whose analysis, once per solve, costs four to seven factorisations (docs/finite.md,
    // "Performance": PORD crashed at 50k dofs; SCOTCH on one thread or on stresses grouped by
    // element ordered worse); Ipopt factorises once per iteration.
    if (qp.block) ok &= opts->SetIntegerValue("mumps_pivot_order", 5);
    if (!ok) {
      out.message = "Ipopt: an option was rejected";
      return out;
    }
    // Initialize("") skips reading an ipopt.opt that may lie in the working directory.
    Ipopt::ApplicationReturnStatus status = app->Initialize("");
    if (status == Ipopt::Solve_Succeeded) status = app->OptimizeTNLP(Ipopt::GetRawPtr(tnlp));

    out.success = status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
    out.message = "Ipopt: " + ipopt_status_name(status);
    out.iterations = tnlp->iterations_;
    if (tnlp->finalized_) {
      out.x = tnlp->x_;
      out.block_x = tnlp->block_x_;
      out.equality_multipliers = tnlp->multipliers_;
    } else {
      out.success = false;
    }
    // Ipopt's own value is taken before x is moved back inside the (relaxed) bounds.
    out.objective = qp.objective(out.x.data());
    if (qp.block && static_cast<int>(out.block_x.size()) == qp.block->n) {
      const Eigen::Map<const Eigen::VectorXd> y(out.block_x.data(), qp.block->n);
      out.objective += 0.5 * y.dot(qp.block->hessian.selfadjointView<Eigen::Lower>() * y);
    }
  } catch (const Ipopt::IpoptException& e) {
    out.success = false;
    out.message = "Ipopt exception: " + e.Message();
  } catch (const std::exception& e) {
    out.success = false;
    out.message = std::string("Ipopt backend error: ") + e.what();
  }
  return out;
}

}  // namespace dc
