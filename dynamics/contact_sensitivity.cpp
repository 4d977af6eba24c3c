#include "contact_sensitivity.hpp"

#include <algorithm>
#include <cmath>

#include "gmres.hpp"

namespace dc::dynamics {
namespace {

/// Rigid mode k at element e, component c: x, y translation, rotation about z (the grid origin).
double mode(const Grid& grid, int k, std::size_t e, int c) {
  if (k == 0) return c == 0 ? 1.0 : 0.0;
  if (k == 1) return c == 1 ? 1.0 : 0.0;
  const int i = static_cast<int>(e % grid.nx), j = static_cast<int>(e / grid.nx);
  return c == 0 ? -grid.yc(j) : grid.xc(i);
}

}  // namespace

void TangentialSensitivity::solve_stick(const LinearOperator& op, bool symmetric, const Grid& grid,
                                        const TangentialSolution& s, int l) {
  const std::size_t N = grid.size();
  const int comps = grid.dimension == 2 ? 1 : 2;
  const std::size_t n = comps * N;
  auto stick = [&](std::size_t e) { return s.state[e] == 1; };
  std::fill(x_.begin(), x_.end(), 0.0);
  double rr = 0.0;
  for (std::size_t e = 0; e < N; ++e)
    for (int c = 0; c < comps; ++c) {
      const double b = stick(e) ? -mode(grid, l, e, c) : 0.0;
      r_[c * N + e] = b;
      p_[c * N + e] = b;
      rr += b * b;
    }
  if (!(rr > 0.0)) return;
  if (!symmetric) {
    const auto rows = [&](const std::vector<double>& in, std::vector<double>& out) {
      op.apply(in, out);
      for (std::size_t e = 0; e < N; ++e)
        for (int c = 0; c < comps; ++c)
          if (!stick(e)) out[c * N + e] = in[c * N + e];  // identity off the stick set
    };
    // std::function holds a closure of one reference in its own buffer (no allocation per call).
    const VectorMap apply = [&rows](const std::vector<double>& in, std::vector<double>& out) { rows(in, out); };
    gmres(apply, {}, r_, x_, 1e-8, 40, 400, gmres_work_);
    return;
  }
  const double b2 = rr;
  for (int it = 0; it < 400 && rr > 1e-16 * b2; ++it) {
    op.apply(p_.data(), q_.data());
    double pq = 0.0;
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c) {
        const std::size_t i = c * N + e;
        if (!stick(e)) q_[i] = 0.0;
        pq += p_[i] * q_[i];
      }
    if (!(pq > 0.0)) break;
    const double alpha = rr / pq;
    double rr_new = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      x_[i] += alpha * p_[i];
      r_[i] -= alpha * q_[i];
      rr_new += r_[i] * r_[i];
    }
    const double beta = rr_new / rr;
    rr = rr_new;
    for (std::size_t i = 0; i < n; ++i) p_[i] = r_[i] + beta * p_[i];
  }
}

void TangentialSensitivity::slip_response(const LinearOperator& Ct, const Grid& grid, const TangentialSolution& s,
                                          int l, std::vector<double>& tau) const {
  const std::size_t N = grid.size();
  const int comps = grid.dimension == 2 ? 1 : 2;
  tau.assign(comps * N, 0.0);
  if (comps == 1) return;
  for (std::size_t e = 0; e < N; ++e) {
    if (s.state[e] != 2) continue;
    const double sx = s.sx[e], sy = s.sy[e], slip = std::hypot(sx, sy);
    if (!(slip > 0.0)) continue;
    // In series with the element's own compliance: a barely slipping element is no stiffer
    // than a sticking one.
    const double ux = sx / slip, uy = sy / slip, k = s.bound[e] / (slip + s.bound[e] * Ct.diagonal(e));
    const double mx = mode(grid, l, e, 0), my = mode(grid, l, e, 1);
    const double along = mx * ux + my * uy;
    tau[e] = -k * (mx - along * ux);
    tau[N + e] = -k * (my - along * uy);
  }
}

Eigen::Matrix3d TangentialSensitivity::compute_full(const LinearOperator& Ct, const Coupling& coupling,
                                                    const FrictionLaw& law, const Grid& grid,
                                                    const TangentialSolution& s) {
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  const std::size_t N = grid.size();
  const int comps = grid.dimension == 2 ? 1 : 2;
  const int modes = grid.dimension == 2 ? 1 : 3;
  const bool coupled = coupling.C && coupling.B21 && coupling.B32;
  // Unknowns: dtau (every element; 0 off the contact), then with coupling dp and d delta.
  const std::size_t n = comps * N, m = coupled ? n + N + 1 : n;
  const std::vector<double>& p = s.normal.pressure;
  if (s.state.size() != N || p.size() != N) return G;
  auto stick = [&](std::size_t e) { return s.state[e] == 1; };
  auto slip = [&](std::size_t e) { return s.state[e] == 2; };
  auto contact = [&](std::size_t e) { return p[e] > 0.0; };
  // Slipping elements: tau = -f(p) ds/|ds|, so dtau = -(f/|ds|)(I - s s') d(ds) + f'(p) dp tau/|tau|
  // (3-D; in 2-D only the second term). gain_ = f/|ds|, dir_ = s, slope_ = f'(p) tau/|tau|.
  gain_.assign(N, 0.0);
  dir_.assign(n, 0.0);
  slope_.assign(n, 0.0);
  for (std::size_t e = 0; e < N; ++e) {
    if (!slip(e)) continue;
    const double mag = comps == 1 ? std::abs(s.tx[e]) : std::hypot(s.tx[e], s.ty[e]);
    const double h = 1e-6 * p[e];
    const double df = h > 0.0 ? (law.bound(p[e] + h) - law.bound(p[e] - h)) / (2.0 * h) : 0.0;
    if (mag > 0.0) {
      slope_[e] = df * s.tx[e] / mag;
      if (comps == 2) slope_[N + e] = df * s.ty[e] / mag;
    }
    if (comps == 1) continue;
    const double ds = std::hypot(s.sx[e], s.sy[e]);
    if (!(ds > 0.0)) continue;
    gain_[e] = s.bound[e] / ds;
    dir_[e] = s.sx[e] / ds;
    dir_[N + e] = s.sy[e] / ds;
  }
  const double ct0 = Ct.diagonal(0), c0 = coupled ? coupling.C->diagonal(0) : 0.0;
  wt_.assign(n, 0.0);
  extra_t_.assign(n, 0.0);
  wn_.assign(N, 0.0);
  extra_n_.assign(N, 0.0);
  dp_.assign(N, 0.0);
  full_.assign(n, 0.0);
  // The slip rows scaled by the element compliance, so that every row is a displacement (m).
  auto slip_rows = [&](const std::vector<double>& in, const std::vector<double>& dds, std::vector<double>& out) {
    for (std::size_t e = 0; e < N; ++e) {
      if (!slip(e)) continue;
      double along = 0.0;
      if (comps == 2) along = dir_[e] * dds[e] + dir_[N + e] * dds[N + e];
      for (int c = 0; c < comps; ++c) {
        const std::size_t i = c * N + e;
        const double turn = comps == 2 ? gain_[e] * (dds[i] - along * dir_[i]) : 0.0;
        out[i] = ct0 * (in[i] + turn - slope_[i] * dp_[e]);
      }
    }
  };
  const auto rows = [&](const std::vector<double>& in, std::vector<double>& out) {
    out.assign(m, 0.0);
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c) full_[c * N + e] = contact(e) ? in[c * N + e] : 0.0;
    Ct.apply(full_, wt_);
    if (coupled) {
      for (std::size_t e = 0; e < N; ++e) dp_[e] = contact(e) ? in[n + e] : 0.0;
      coupling.B21->apply(dp_, extra_t_);
      for (std::size_t i = 0; i < n; ++i) wt_[i] += extra_t_[i];
    }
    // wt_ = d(ds) without the rigid part; stick: d(ds) = 0; free: dtau = 0.
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c) {
        const std::size_t i = c * N + e;
        out[i] = stick(e) ? wt_[i] : in[i];
      }
    slip_rows(in, wt_, out);
    if (!coupled) return;
    coupling.C->apply(dp_, wn_);
    coupling.B32->apply(full_, extra_n_);
    double sum = 0.0;
    for (std::size_t e = 0; e < N; ++e) {
      out[n + e] = contact(e) ? wn_[e] + extra_n_[e] - in[n + N] : in[n + e];  // the gap stays closed
      if (contact(e)) sum += dp_[e];
    }
    out[n + N] = coupling.force_control ? c0 * sum : in[n + N];  // the load or the approach held
  };
  // Block-Jacobi preconditioner: each element's own rows (stick: c_ee; slip: ct0 (I + g c_ee P),
  // whose inverse is (I - g c_ee/(1 + g c_ee) P)/ct0 with P = I - s s' a projector; normal: c0).
  const auto block_jacobi = [&](const std::vector<double>& in, std::vector<double>& out) {
    out = in;
    for (std::size_t e = 0; e < N; ++e) {
      if (stick(e)) {
        for (int c = 0; c < comps; ++c) out[c * N + e] = in[c * N + e] / Ct.diagonal(c * N + e);
      } else if (slip(e)) {
        const double g = gain_[e] * Ct.diagonal(e), shrink = g / (1.0 + g);
        double along = 0.0;
        if (comps == 2) along = dir_[e] * in[e] + dir_[N + e] * in[N + e];
        for (int c = 0; c < comps; ++c) {
          const std::size_t i = c * N + e;
          const double projected = comps == 2 ? in[i] - along * dir_[i] : 0.0;
          out[i] = (in[i] - shrink * projected) / ct0;
        }
      }
      if (coupled && contact(e)) out[n + e] = in[n + e] / c0;
    }
  };
  // std::function holds a closure of one reference in its own buffer (no allocation per call).
  const VectorMap apply = [&rows](const std::vector<double>& in, std::vector<double>& out) { rows(in, out); };
  const VectorMap precondition = [&block_jacobi](const std::vector<double>& in, std::vector<double>& out) {
    block_jacobi(in, out);
  };
  b_.assign(m, 0.0);
  x_.assign(m, 0.0);
  tau0_.assign(m, 0.0);
  for (int l = 0; l < modes; ++l) {
    // Right-hand side: minus the rows' response to the rigid mode alone (dtau = 0, dp = 0).
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c) tau0_[c * N + e] = mode(grid, l, e, c);
    std::fill(dp_.begin(), dp_.end(), 0.0);
    std::fill(b_.begin(), b_.end(), 0.0);
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c)
        if (stick(e)) b_[c * N + e] = -tau0_[c * N + e];
    std::fill(x_.begin(), x_.end(), 0.0);
    slip_rows(x_, tau0_, b_);
    for (std::size_t i = 0; i < n; ++i) b_[i] = stick(i % N) ? b_[i] : -b_[i];
    // From the last call's solution for this mode (same size): the sensitivity of the previous
    // iterate or step, a few GMRES iterations from this one's.
    std::vector<double>& last = last_solution_[l];
    if (last.size() == m) x_ = last;
    // The Jacobian only steers Newton (the residual is exact): a relative error e makes its
    // convergence linear with rate ~e, so 1e-6 costs no iteration.
    const GmresResult gm = gmres(apply, precondition, b_, x_, 1e-6, 60, 600, gmres_work_);
    iterations_ += gm.iterations;
    last = x_;
    for (int k = 0; k < modes; ++k) {
      double sum = 0.0;
      for (std::size_t e = 0; e < N; ++e)
        if (contact(e))
          for (int c = 0; c < comps; ++c) sum += mode(grid, k, e, c) * x_[c * N + e];
      G(k, l) = sum * grid.area();
    }
  }
  return G;
}

Eigen::Matrix3d TangentialSensitivity::assemble(const LinearOperator& op, bool symmetric, const LinearOperator& Ct,
                                                const Grid& grid, const TangentialSolution& s) {
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  const std::size_t N = grid.size();
  const int comps = grid.dimension == 2 ? 1 : 2;
  const int modes = grid.dimension == 2 ? 1 : 3;
  const std::size_t n = comps * N;
  if (s.state.size() != N) return G;
  x_.assign(n, 0.0);
  r_.assign(n, 0.0);
  p_.assign(n, 0.0);
  q_.assign(n, 0.0);
  for (int l = 0; l < modes; ++l) {
    solve_stick(op, symmetric, grid, s, l);
    // Slip set: the traction turns with the slip direction (3-D).
    slip_response(Ct, grid, s, l, tau0_);
    for (std::size_t e = 0; e < N; ++e)
      if (s.state[e] == 2)
        for (int c = 0; c < comps; ++c) x_[c * N + e] = tau0_[c * N + e];
    for (int k = 0; k < modes; ++k) {
      double sum = 0.0;
      for (std::size_t e = 0; e < N; ++e)
        for (int c = 0; c < comps; ++c) sum += mode(grid, k, e, c) * x_[c * N + e];
      G(k, l) = sum * grid.area();
    }
  }
  return G;
}

Eigen::Matrix3d TangentialSensitivity::compute(const LinearOperator& Ct, const Grid& grid,
                                               const TangentialSolution& s) {
  return assemble(Ct, true, Ct, grid, s);
}

Eigen::Matrix3d TangentialSensitivity::compute_steady(const LinearOperator& D, const LinearOperator& Ct,
                                                      const Grid& grid, const TangentialSolution& s) {
  // ds per element of travel dx: an increment dx * xi of the rigid slip per unit creepage.
  return grid.dx * assemble(D, false, Ct, grid, s);
}

}  // namespace dc::dynamics
