#include "contact_sensitivity.hpp"

#include <algorithm>
#include <cmath>

namespace dc::dynamics {

Eigen::Matrix3d TangentialSensitivity::compute(const LinearOperator& Ct, const Grid& grid,
                                               const TangentialSolution& s) {
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  const std::size_t N = grid.size();
  const int comps = grid.dimension == 2 ? 1 : 2;
  const int modes = grid.dimension == 2 ? 1 : 3;
  const std::size_t n = comps * N;
  if (s.state.size() != N) return G;
  const double A = grid.area();
  auto mode = [&](int k, std::size_t e, int c) {
    if (k == 0) return c == 0 ? 1.0 : 0.0;
    if (k == 1) return c == 1 ? 1.0 : 0.0;
    const int i = static_cast<int>(e % grid.nx), j = static_cast<int>(e / grid.nx);
    return c == 0 ? -grid.yc(j) : grid.xc(i);
  };
  auto stick = [&](std::size_t e) { return s.state[e] == 1; };
  x_.assign(n, 0.0);
  r_.assign(n, 0.0);
  p_.assign(n, 0.0);
  q_.assign(n, 0.0);
  full_.assign(n, 0.0);
  const bool any_stick = std::any_of(s.state.begin(), s.state.end(), [](int v) { return v == 1; });
  for (int l = 0; l < modes; ++l) {
    // Stick set: Ct_SS dtau = -m_l on S (conjugate gradients, masked operator).
    std::fill(x_.begin(), x_.end(), 0.0);
    double rr = 0.0, b2 = 0.0;
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c) {
        const double b = stick(e) ? -mode(l, e, c) : 0.0;
        r_[c * N + e] = b;
        p_[c * N + e] = b;
        rr += b * b;
      }
    b2 = rr;
    for (int it = 0; any_stick && it < 200 && rr > 1e-16 * b2; ++it) {
      Ct.apply(p_.data(), q_.data());
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
    // Slip set: the traction turns with the slip direction.
    for (std::size_t e = 0; e < N; ++e) {
      if (s.state[e] != 2) continue;
      const double sx = s.sx[e], sy = comps == 2 ? s.sy[e] : 0.0, slip = std::hypot(sx, sy);
      if (!(slip > 0.0) || comps == 1) continue;
      // In series with the element's own compliance: a barely slipping element is no stiffer
      // than a sticking one.
      const double ux = sx / slip, uy = sy / slip, k = s.bound[e] / (slip + s.bound[e] * Ct.diagonal(e));
      const double mx = mode(l, e, 0), my = mode(l, e, 1);
      const double along = mx * ux + my * uy;
      x_[e] = -k * (mx - along * ux);
      x_[N + e] = -k * (my - along * uy);
    }
    for (int k = 0; k < modes; ++k) {
      double sum = 0.0;
      for (std::size_t e = 0; e < N; ++e)
        for (int c = 0; c < comps; ++c) sum += mode(k, e, c) * x_[c * N + e];
      G(k, l) = sum * A;
    }
  }
  return G;
}

}  // namespace dc::dynamics
