// Steady rolling by semismooth Newton (see steady_rolling_solver.hpp).
//
// Scaled unknowns: t = tau / f_ref (f_ref the largest bound), radii rho = f / f_ref, and the
// slip in units of the slip one element's full traction produces, s^ = r s / f_ref with
// r = 1 / D_00. The amplitudes enter as a^_k = r alpha_k L_k / f_ref with m^_k = m_k / L_k
// (L_k the largest |m_k|), so that every unknown and every residual is O(1):
//   F_e = t_e - Pi_rho_e(z_e),  z_e = t_e - s^_e            (the friction law (2.4)-(2.5))
//   G_k = (sum_e m_k(e).t_e A f_ref - R_k) / capacity_k      (prescribed resultants)
// Generalised Jacobian, per element: stick (|z| <= rho): dF = ds^; slip: dF = dt -
// (rho/|z|)(I - zz'/|z|^2)(dt - ds^) (2-D: dF = dt); ds^ = r D dt + sum_k da^_k m^_k.
// Each Newton step solves J d = -(F, G) by GMRES to a relative residual min(0.1, |F|) (inexact
// Newton), right-preconditioned by the element blocks of J (D replaced by its diagonal), then
// backtracks on |(F, G)|_2. Cost: one apply of D per GMRES iteration and per trial point.
#include "steady_rolling_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gmres.hpp"
#include "interrupt.hpp"
#include "vector_ops.hpp"

namespace dc {

using Vec = std::vector<double>;

/// Newton's method on the steady equations; kept by a SteadyRollingWorkspace, so that its
/// vectors, the Krylov basis and the iterates serve the next solve (no allocation once sized).
class SteadyRollingNewton {
 public:
  /// Solves `p` into `out` (its vectors and message refilled).
  void solve(const SteadyRollingProgram& p, const SolveOptions& o, SteadyRollingOutcome& out) {
    p_ = &p;
    options_ = o;
    comps_ = p.comps;
    N_ = p.bound.size();
    n_ = comps_ * N_;
    m_ = p.modes.size();
    applies_ = 0;
    out.success = false;
    out.newton_iterations = out.operator_applies = 0;
    out.residual = 0.0;
    out.message.clear();
    iterate(out);
  }

 private:
  void iterate(SteadyRollingOutcome& out);

 private:
  // x = (t, a^): n_ + m_ entries.
  /// s^ of x into s_ (one apply of D).
  void slip(const Vec& x) {
    std::copy(x.begin(), x.begin() + n_, t_.begin());
    p_->D->apply(t_, s_);
    ++applies_;
    for (std::size_t i = 0; i < n_; ++i) {
      s_[i] = r_ * s_[i] + b_hat_[i];
      for (std::size_t k = 0; k < m_; ++k) s_[i] += x[n_ + k] * m_hat_[k][i];
    }
  }

  /// t onto the disks |t_e| <= rho_e (the amplitudes are free).
  void project(Vec& x) const {
    for (std::size_t e = 0; e < N_; ++e) {
      double mm = 0.0;
      for (int c = 0; c < comps_; ++c) mm += x[c * N_ + e] * x[c * N_ + e];
      const double mag = std::sqrt(mm);
      if (mag <= rho_[e]) continue;
      const double scale = mag > 0.0 ? rho_[e] / mag : 0.0;
      for (int c = 0; c < comps_; ++c) x[c * N_ + e] *= scale;
    }
  }

  /// (F, G) of x; also records z and the element states for the Jacobian.
  void residual(const Vec& x, Vec& out) {
    slip(x);
    out.assign(n_ + m_, 0.0);
    for (std::size_t e = 0; e < N_; ++e) {
      if (rho_[e] <= 0.0) {
        for (int c = 0; c < comps_; ++c) out[c * N_ + e] = x[c * N_ + e];
        continue;
      }
      double z[2] = {0.0, 0.0}, zz = 0.0;
      for (int c = 0; c < comps_; ++c) {
        z[c] = x[c * N_ + e] - s_[c * N_ + e];
        zz += z[c] * z[c];
      }
      const double mag = std::sqrt(zz);
      const double scale = mag > rho_[e] ? rho_[e] / mag : 1.0;
      for (int c = 0; c < comps_; ++c) out[c * N_ + e] = x[c * N_ + e] - scale * z[c];
    }
    for (std::size_t k = 0; k < m_; ++k) {
      double sum = 0.0;
      for (std::size_t i = 0; i < n_; ++i) sum += p_->modes[k][i] * x[i];
      out[n_ + k] = (sum * p_->area * f_ref_ - p_->resultants[k]) / capacity_[k];
    }
  }

  /// The element states and z at x (after residual(x)).
  void linearise(const Vec& x) {
    for (std::size_t e = 0; e < N_; ++e) {
      state_[e] = 0;  // free
      if (rho_[e] <= 0.0) continue;
      double zz = 0.0;
      for (int c = 0; c < comps_; ++c) {
        zhat_[c * N_ + e] = x[c * N_ + e] - s_[c * N_ + e];
        zz += zhat_[c * N_ + e] * zhat_[c * N_ + e];
      }
      const double mag = std::sqrt(zz);
      if (mag <= rho_[e]) {
        state_[e] = 1;  // stick
      } else {
        state_[e] = 2;  // slip
        ratio_[e] = rho_[e] / mag;
        for (int c = 0; c < comps_; ++c) zhat_[c * N_ + e] /= mag;
      }
    }
  }

  /// out = J v.
  void jacobian(const Vec& v, Vec& out) {
    std::copy(v.begin(), v.begin() + n_, t_.begin());
    p_->D->apply(t_, ds_);
    ++applies_;
    for (std::size_t i = 0; i < n_; ++i) {
      ds_[i] *= r_;
      for (std::size_t k = 0; k < m_; ++k) ds_[i] += v[n_ + k] * m_hat_[k][i];
    }
    out.assign(n_ + m_, 0.0);
    for (std::size_t e = 0; e < N_; ++e) {
      if (state_[e] == 1) {
        for (int c = 0; c < comps_; ++c) out[c * N_ + e] = ds_[c * N_ + e];
      } else if (state_[e] == 2 && comps_ == 2) {
        const double ux = v[e] - ds_[e], uy = v[N_ + e] - ds_[N_ + e];
        const double nx = zhat_[e], ny = zhat_[N_ + e];
        const double un = ux * nx + uy * ny;
        out[e] = v[e] - ratio_[e] * (ux - un * nx);
        out[N_ + e] = v[N_ + e] - ratio_[e] * (uy - un * ny);
      } else {
        for (int c = 0; c < comps_; ++c) out[c * N_ + e] = v[c * N_ + e];
      }
    }
    for (std::size_t k = 0; k < m_; ++k) {
      double sum = 0.0;
      for (std::size_t i = 0; i < n_; ++i) sum += p_->modes[k][i] * v[i];
      out[n_ + k] = sum * p_->area * f_ref_ / capacity_[k];
    }
  }

  /// out = M^-1 v with M the element blocks of J (D by its diagonal).
  void precondition(const Vec& v, Vec& out) const {
    out = v;
    for (std::size_t e = 0; e < N_; ++e) {
      if (state_[e] == 1) {
        for (int c = 0; c < comps_; ++c) out[c * N_ + e] = v[c * N_ + e] / g_[c];
      } else if (state_[e] == 2 && comps_ == 2) {
        // M = I - q (I - nn')(I - G), G = diag(g): solve the 2 x 2 system.
        const double q = ratio_[e], nx = zhat_[e], ny = zhat_[N_ + e];
        const double a11 = 1.0 - q * (1.0 - nx * nx) * (1.0 - g_[0]);
        const double a12 = q * nx * ny * (1.0 - g_[1]);
        const double a21 = q * nx * ny * (1.0 - g_[0]);
        const double a22 = 1.0 - q * (1.0 - ny * ny) * (1.0 - g_[1]);
        const double det = a11 * a22 - a12 * a21;
        if (std::abs(det) < 1e-12) continue;
        out[e] = (a22 * v[e] - a12 * v[N_ + e]) / det;
        out[N_ + e] = (a11 * v[N_ + e] - a21 * v[e]) / det;
      }
    }
  }

  const SteadyRollingProgram* p_ = nullptr;
  SolveOptions options_;
  int comps_ = 2;
  std::size_t N_ = 0, n_ = 0, m_ = 0;
  double f_ref_ = 1.0, r_ = 1.0;
  double g_[2] = {1.0, 1.0};
  Vec rho_, b_hat_, capacity_, scale_mode_;
  std::vector<Vec> m_hat_;
  Vec t_, s_, ds_, zhat_, ratio_;
  std::vector<unsigned char> state_;
  GmresWorkspace gmres_work_;  // the Newton iterations' Krylov basis, kept between solves
  Vec x_, F_, x_trial_, F_trial_, d_, rhs_, merits_;  // iterate()'s
  int applies_ = 0;
};

void SteadyRollingNewton::iterate(SteadyRollingOutcome& out) {
  out.amplitudes.assign(m_, 0.0);
  out.tau.assign(n_, 0.0);
  if (!p_->D || p_->D->rows() != n_ || p_->b.size() != n_ || p_->resultants.size() != m_ ||
      (!p_->tau0.empty() && p_->tau0.size() != n_)) {
    out.message = "invalid program";
    return;
  }
  f_ref_ = max_abs(p_->bound);
  if (!(f_ref_ > 0.0)) {
    out.success = m_ == 0;
    out.message = out.success ? "no friction: zero traction" : "no friction can carry the resultants";
    return;
  }
  const double d0 = p_->D->diagonal(0);
  if (!(d0 > 0.0)) {
    out.message = "invalid program: the convective compliance has no positive diagonal";
    return;
  }
  r_ = 1.0 / d0;
  for (int c = 0; c < comps_; ++c) g_[c] = r_ * p_->D->diagonal(c * N_);
  rho_.resize(N_);
  for (std::size_t e = 0; e < N_; ++e) rho_[e] = std::max(p_->bound[e], 0.0) / f_ref_;
  b_hat_.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) b_hat_[i] = r_ * p_->b[i] / f_ref_;
  m_hat_.resize(m_);
  scale_mode_.resize(m_);
  capacity_.resize(m_);
  for (std::size_t k = 0; k < m_; ++k) {
    if (p_->modes[k].size() != n_) {
      out.message = "invalid program: mode size";
      return;
    }
    scale_mode_[k] = std::max(max_abs(p_->modes[k]), 1e-300);
    m_hat_[k] = p_->modes[k];
    for (double& v : m_hat_[k]) v /= scale_mode_[k];
    double cap = 0.0;
    for (std::size_t e = 0; e < N_; ++e) {
      double mm = 0.0;
      for (int c = 0; c < comps_; ++c) mm += p_->modes[k][c * N_ + e] * p_->modes[k][c * N_ + e];
      cap += p_->bound[e] * std::sqrt(mm) * p_->area;
    }
    capacity_[k] = cap > 0.0 ? cap : 1.0;
  }
  t_.resize(n_);
  s_.resize(n_);
  ds_.resize(n_);
  zhat_.assign(n_, 0.0);
  ratio_.assign(N_, 0.0);
  state_.assign(N_, 0);

  Vec &x = x_, &F = F_, &x_trial = x_trial_, &F_trial = F_trial_, &d = d_, &rhs = rhs_;
  x.assign(n_ + m_, 0.0);
  if (!p_->tau0.empty())
    for (std::size_t i = 0; i < n_; ++i) x[i] = p_->tau0[i] / f_ref_;
  project(x);
  residual(x, F);
  // The tolerance is relative to the largest bound; a small creepage (or resultant) drives a
  // traction far below it, whose own certificate needs the residual relative to that level: below
  // a hundredth of the bound the tolerance follows the driving level (scale-free, as the problem
  // is linear in full stick), so a creepage of 1e-12 is solved as well as one of 1e-3.
  double level = max_abs(b_hat_);
  for (std::size_t k = 0; k < m_; ++k) level = std::max(level, std::abs(p_->resultants[k]) / capacity_[k]);
  const double tol = std::max(options_.tol, 1e-13) * std::clamp(100.0 * level, 1e-200, 1.0);
  // Non-monotone search: full (projected) Newton steps are taken while |(F, G)|_inf stays below
  // kGrowth times the largest of the last kMemory merits (the active set of a cold start moves
  // by many elements per step, which a monotone search would damp to a crawl); otherwise
  // backtrack against that reference. No new best merit in kStall iterations: give up.
  constexpr int kMemory = 4, kStall = 12;
  std::vector<double>& merits = merits_;
  merits.assign(1, max_abs(F));
  double best = merits.back();
  int since_best = 0, it = 0;
  for (; it < options_.max_iter; ++it) {
    throw_if_interrupted();
    out.residual = max_abs(F);
    if (options_.progress) options_.progress({it, 0.0, out.residual, tol});
    if (out.residual <= tol) {
      out.success = true;
      break;
    }
    linearise(x);
    rhs.resize(F.size());
    for (std::size_t i = 0; i < F.size(); ++i) rhs[i] = -F[i];
    d.assign(F.size(), 0.0);
    // Inexact Newton: a relative linear residual min(0.1, |F|), never tighter than needed to
    // reach the tolerance in this step.
    const double eta = std::clamp(std::max(out.residual, 0.1 * tol / out.residual), 1e-12, 0.1);
    gmres([this](const Vec& v, Vec& y) { jacobian(v, y); }, [this](const Vec& v, Vec& y) { precondition(v, y); },
          rhs, d, eta, 30, 1000, gmres_work_);
    const double reference = *std::max_element(merits.end() - std::min<std::ptrdiff_t>(kMemory, merits.size()),
                                               merits.end());
    double lambda = 1.0, phi_trial = 0.0;
    bool accepted = false;
    for (int k = 0; k < 10 && !accepted; ++k, lambda *= (accepted ? 1.0 : 0.5)) {
      x_trial = x;
      for (std::size_t i = 0; i < x.size(); ++i) x_trial[i] += lambda * d[i];
      project(x_trial);
      residual(x_trial, F_trial);
      phi_trial = max_abs(F_trial);
      accepted = phi_trial <= (1.0 - 1e-4 * lambda) * reference;
    }
    if (!accepted) {
      out.message = "line search failed";
      break;
    }
    x.swap(x_trial);
    F.swap(F_trial);
    merits.push_back(phi_trial);
    if (phi_trial < 0.99 * best) {
      best = phi_trial;
      since_best = 0;
    } else if (++since_best >= kStall) {
      out.message = "no progress in " + std::to_string(kStall) + " Newton iterations";
      break;
    }
  }
  out.newton_iterations = it;
  out.operator_applies = applies_;
  if (out.message.empty() && !out.success) out.message = "iteration limit";
  if (out.success) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "Newton converged: %d iterations, residual %.2e", it, out.residual);
    out.message = buf;
  }
  // Unscale; the traction is projected onto the disks (a residual-sized correction).
  for (std::size_t e = 0; e < N_; ++e) {
    double mm = 0.0;
    for (int c = 0; c < comps_; ++c) mm += x[c * N_ + e] * x[c * N_ + e];
    const double mag = std::sqrt(mm);
    const double scale = mag > rho_[e] ? (mag > 0.0 ? rho_[e] / mag : 0.0) : 1.0;
    for (int c = 0; c < comps_; ++c) out.tau[c * N_ + e] = scale * x[c * N_ + e] * f_ref_;
  }
  for (std::size_t k = 0; k < m_; ++k) out.amplitudes[k] = x[n_ + k] * f_ref_ / (r_ * scale_mode_[k]);
  return;
}

SteadyRollingWorkspace::SteadyRollingWorkspace() : newton_(std::make_unique<SteadyRollingNewton>()) {}
SteadyRollingWorkspace::~SteadyRollingWorkspace() = default;
SteadyRollingWorkspace::SteadyRollingWorkspace(SteadyRollingWorkspace&&) noexcept = default;
SteadyRollingWorkspace& SteadyRollingWorkspace::operator=(SteadyRollingWorkspace&&) noexcept = default;

SteadyRollingOutcome solve_steady_rolling(const SteadyRollingProgram& program, const SolveOptions& options) {
  SteadyRollingWorkspace work;
  SteadyRollingOutcome out;
  solve_steady_rolling(program, options, work, out);
  return out;
}

void solve_steady_rolling(const SteadyRollingProgram& program, const SolveOptions& options,
                          SteadyRollingWorkspace& work, SteadyRollingOutcome& out) {
  work.newton_->solve(program, options, out);
}

}  // namespace dc
