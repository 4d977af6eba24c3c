// TangentialProblem's certificates: the slip increment (3.8), the resultants, the friction law
// (2.4)-(2.5) as a fixed point and the gap function (4.24)-(4.25) (certify_friction), the step's
// certificate with the prescribed resultants, and a solution's fields and states (finish).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "quadratic_program.hpp"
#include "support_window.hpp"
#include "tangential_problem_impl.hpp"

namespace dc {
namespace {

/// |(x, y)| for the certificates' tractions and slips, without std::hypot's guards against
/// overflow (a tenth of a dynamic step's time on a 64^2 grid): their squares stay far inside
/// the double range, and a certificate of non-finite values fails anyway.
double certificate_norm(double x, double y) { return std::sqrt(x * x + y * y); }

/// The fields a friction certificate reads, as views of n values each (a step's tau and ds are
/// stacked x then y: no copies).
struct FrictionFields {
  const double *tx, *ty, *sx, *sy, *bound;
  std::size_t n;
};

bool all_finite_n(const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

/// The traction level T: max |tau| where friction acts.
double traction_level(const FrictionFields& f) {
  double level = 0.0;
  for (std::size_t e = 0; e < f.n; ++e)
    if (f.bound[e] > 0.0) level = std::max(level, certificate_norm(f.tx[e], f.ty[e]));
  return level;
}

/// TangentialProblem::certify_friction on views.
Certificate friction_certificate(const Grid& grid, const FrictionFields& fields, double compliance) {
  const double *tx = fields.tx, *ty = fields.ty, *sx = fields.sx, *sy = fields.sy, *bound = fields.bound;
  const std::size_t n = fields.n;
  if (!all_finite_n(tx, n) || !all_finite_n(ty, n) || !all_finite_n(sx, n) || !all_finite_n(sy, n) ||
      !all_finite_n(bound, n))
    return Certificate::not_finite();
  Certificate cert;
  const double A = grid.area();
  const double c_t = compliance;  // slip per unit traction of one element
  // Scales of the solution itself, not of the bound: the traction level T (max |tau| where
  // friction acts) and the slip level S (max |ds|, at least c_t T). max f(p) or sum f |ds| A
  // would vanish or explode in full stick, for mu -> 0 or mu -> infinity.
  double T = traction_level(fields), S = 0.0, f_area = 0.0;
  for (std::size_t e = 0; e < n; ++e)
    if (bound[e] > 0.0) {
      S = std::max(S, certificate_norm(sx[e], sy[e]));
      f_area += bound[e] * A;
    }
  if (!(T > 0.0)) T = S / c_t;  // no traction at all: any slip where friction acts is an error
  if (!(T > 0.0)) return cert;  // nothing loaded, nothing slipping
  S = std::max(S, c_t * T);
  double law = 0.0, gap = 0.0;
  for (std::size_t e = 0; e < n; ++e) {
    const double f = bound[e];
    if (f == 0.0 && tx[e] == 0.0 && ty[e] == 0.0) continue;  // no friction, no traction: both terms 0
    // (2.4)-(2.5) as a fixed point: tau = proj_{|t| <= f}(tau - ds / c_t).
    double zx = tx[e] - sx[e] / c_t, zy = ty[e] - sy[e] / c_t;
    project_onto_disk(zx, zy, std::max(f, 0.0));
    law = std::max(law, certificate_norm(tx[e] - zx, ty[e] - zy));
    law = std::max(law, certificate_norm(tx[e], ty[e]) - f);
    // (4.24): g = sum [f |ds| - tau- . ds] A, with the paper's tau- = -tau+ on the substrate
    // ((3.12), (3.25)); it vanishes when tau+ = -f ds/|ds| on slip, ds = 0 on stick.
    gap += (f * certificate_norm(sx[e], sy[e]) + (tx[e] * sx[e] + ty[e] * sy[e])) * A;
  }
  cert.friction_law = law / T;
  // g against the largest it could be at this slip level: sum f A times S.
  cert.gap_function = f_area > 0.0 ? std::abs(gap) / (f_area * S) : 0.0;
  return cert;
}

}  // namespace

/// The slip increment of a step (3.8): ds = W + rigid + Ct tau, rigid = sum_k increment_k mode_k.
std::vector<double> TangentialProblem::Impl::slip_increment(const std::vector<double>& W,
                                                             const std::vector<double>& tau,
                                                             const std::array<double, 3>& increment) const {
  std::vector<double> ds;
  Ct->apply(tau, ds);
  add_rigid_and_load(W, increment, ds);
  return ds;
}

void TangentialProblem::Impl::slip_increment(const std::vector<double>& W, const std::vector<double>& tau,
                                             const std::array<double, 3>& increment, std::vector<double>& ds,
                                             std::vector<double>& ct_tau) const {
  Ct->apply(tau, ct_tau);
  ds = ct_tau;
  add_rigid_and_load(W, increment, ds);
}

/// ds += W + rigid, rigid = sum_k increment_k mode_k (3.8).
void TangentialProblem::Impl::add_rigid_and_load(const std::vector<double>& W, const std::array<double, 3>& increment,
                                                 std::vector<double>& ds) const {
  for (std::size_t e = 0; e < N; ++e)
    for (int c = 0; c < comps; ++c) {
      double rigid = 0.0;
      for (int k = 0; k < n_modes(); ++k) rigid += increment[k] * mode(k, e, c);
      ds[c * N + e] += W[c * N + e] + rigid;
    }
}

/// The slip increment (3.8) of a traction that vanishes outside `window`, computed on the
/// window's elements; W + rigid outside (where f = 0, so tau = 0 and the slip is not certified).
/// Into ds, with the window's vectors the Impl's (no allocation once sized).
void TangentialProblem::Impl::windowed_slip_increment(const std::vector<double>& W, const std::vector<double>& tau,
                                                      const SupportWindow& window, const LinearOperator& ct_window,
                                                      const std::array<double, 3>& increment,
                                                      std::vector<double>& ds) const {
  const std::size_t Nw = window.size();
  std::vector<double>&tau_window = window_tau_work, &ds_window = window_ds_work;
  tau_window.resize(comps * Nw);
  for (std::size_t l = 0; l < Nw; ++l)
    for (int c = 0; c < comps; ++c) tau_window[c * Nw + l] = tau[c * N + window.global(grid, l)];
  ct_window.apply(tau_window, ds_window);
  ds.assign(comps * N, 0.0);
  add_rigid_and_load(W, increment, ds);
  for (std::size_t l = 0; l < Nw; ++l)
    for (int c = 0; c < comps; ++c) ds[c * N + window.global(grid, l)] += ds_window[c * Nw + l];
}

/// Resultants F_x, F_y, M_z of a traction field.
std::array<double, 3> TangentialProblem::Impl::resultants(const std::vector<double>& tau) const {
  // The modes written out (mode(k, e, c) per term divides e by nx: a twentieth of a 64^2 step).
  double fx = 0.0, fy = 0.0, mz = 0.0;
  for (int j = 0; j < grid.ny; ++j) {
    const double y = grid.yc(j);
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j);
      fx += tau[e];
      if (comps == 2) {
        fy += tau[N + e];
        mz += grid.xc(i) * tau[N + e] - y * tau[e];
      }
    }
  }
  const double A = grid.area();
  return {fx * A, comps == 2 ? fy * A : 0.0, comps == 2 ? mz * A : 0.0};
}

/// The tangential certificate of a step: friction law and gap function (certify_friction), and
/// the prescribed resultants, relative to the resultant itself or, when that is 0, to what the
/// traction level could carry (T sum |m_k| A).
Certificate TangentialProblem::Impl::step_certificate(const std::vector<double>& tau, const std::vector<double>& ds,
                                                      const std::vector<double>& f,
                                                      const std::array<ModeControl, 3>& modes) const {
  // Views of the stacked components (2-D: y is a zero field).
  if (comps == 1 && zero_component.size() != N) zero_component.assign(N, 0.0);
  const double* zeros = zero_component.data();
  const FrictionFields fields{tau.data(), comps == 2 ? tau.data() + N : zeros, ds.data(),
                              comps == 2 ? ds.data() + N : zeros, f.data(), N};
  Certificate cert = friction_certificate(grid, fields, Ct->diagonal(0));
  const double T = traction_level(fields);
  const std::array<double, 3> r = resultants(tau);
  for (int k = 0; k < n_modes(); ++k) {
    if (modes[k].kind != ModeControl::Kind::resultant) continue;
    double reach = 0.0;
    for (std::size_t e = 0; e < N; ++e)
      if (f[e] > 0.0) {
        double m2 = 0.0;
        for (int c = 0; c < comps; ++c) m2 += mode(k, e, c) * mode(k, e, c);
        reach += T * std::sqrt(m2) * grid.area();
      }
    const double scale = std::max(std::abs(modes[k].value), reach);
    const double miss = std::abs(r[k] - modes[k].value);
    cert.force_residual = std::max(cert.force_residual, scale > 0.0 ? miss / scale : miss > 0.0 ? 1.0 : 0.0);
  }
  return cert;
}

/// Fills the fields, states, resultants and the certificate of a solution from tau, the slip
/// ds and the bound f; the status becomes not_converged when the certificate fails.
void TangentialProblem::Impl::finish(TangentialSolution& sol, const std::vector<double>& tau,
                                     const std::vector<double>& ds, const std::vector<double>& f,
                                     const std::array<ModeControl, 3>& modes, const SolverOptions& solver) const {
  sol.tx.assign(N, 0.0);
  sol.ty.assign(N, 0.0);
  sol.sx.assign(N, 0.0);
  sol.sy.assign(N, 0.0);
  sol.bound = f;
  sol.state.assign(N, 0);
  sol.n_stick = sol.n_slip = 0;
  sol.stick_area = 0.0;
  for (std::size_t e = 0; e < N; ++e) {
    sol.tx[e] = tau[e];
    sol.sx[e] = ds[e];
    if (comps == 2) {
      sol.ty[e] = tau[N + e];
      sol.sy[e] = ds[N + e];
    }
  }
  const double A = grid.area();
  // Slip against the slip of the traction level (never against the bound: full stick at huge mu).
  const double slip_scale = Ct->diagonal(0) * TangentialProblem::traction_scale(sol.tx, sol.ty, f);
  for (std::size_t e = 0; e < N; ++e) {
    if (f[e] <= 0.0) continue;
    const bool slipping = certificate_norm(sol.sx[e], sol.sy[e]) > 1e-5 * slip_scale;
    sol.state[e] = slipping ? 2 : 1;
    (slipping ? sol.n_slip : sol.n_stick) += 1;
    if (!slipping) sol.stick_area += A;
  }
  sol.resultants = resultants(tau);
  const Certificate friction = step_certificate(tau, ds, f, modes);
  // The normal part of the certificate comes from the normal solve of the last iterate.
  sol.report.certificate = sol.normal.report.certificate;
  sol.report.certificate.friction_law = friction.friction_law;
  sol.report.certificate.gap_function = friction.gap_function;
  sol.report.certificate.force_residual = std::max(sol.normal.report.certificate.force_residual, friction.force_residual);
  const bool certified = sol.report.certificate.worst() <= solver.certificate_tol && sol.outer.converged &&
                         sol.normal.report.status == SolveStatus::converged;
  if (sol.report.status != SolveStatus::failed)
    sol.report.status = certified ? SolveStatus::converged : SolveStatus::not_converged;
  if (!sol.outer.converged)
    sol.report.message += " [outer loop (4.26)-(4.27)/(3.31)-(3.32) did not converge in " +
                          std::to_string(sol.outer.iterations) + " iterations: last change " +
                          format_number(sol.outer.last_change) + "; the results are its last iterate]";
}

double TangentialProblem::traction_scale(const std::vector<double>& tx, const std::vector<double>& ty,
                                         const std::vector<double>& bound) {
  return traction_level({tx.data(), ty.data(), nullptr, nullptr, bound.data(), bound.size()});
}

Certificate TangentialProblem::certify_friction(const Grid& grid, const std::vector<double>& tx,
                                                const std::vector<double>& ty, const std::vector<double>& sx,
                                                const std::vector<double>& sy, const std::vector<double>& bound,
                                                double compliance) {
  return friction_certificate(grid, {tx.data(), ty.data(), sx.data(), sy.data(), bound.data(), bound.size()},
                              compliance);
}

}  // namespace dc
