#include "shakedown_by_depth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

#include "enclosing_ball.hpp"
#include "interrupt.hpp"

namespace dc {

namespace {

constexpr double kDepthInf = std::numeric_limits<double>::infinity();

/// One depth's samples split along W's range: proj.col(i) = Q'u_i, perp2(i) = |u_perp,i|^2.
struct DepthGeometry {
  Eigen::MatrixXd proj;
  Eigen::VectorXd perp2;
  double max_norm2 = 0.0;  ///< max_i |u_i|^2 (p = 0)
};

DepthGeometry depth_geometry(const ShakedownSamples& s, int depth) {
  const int p = s.p(), n = s.positions;
  const Eigen::Index q = s.u.rows();
  DepthGeometry g;
  g.proj.resize(p, n);
  g.perp2.resize(n);
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(q, p);
  if (p > 0) basis = s.w.householderQr().householderQ() * Eigen::MatrixXd::Identity(q, p);
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd u = s.sample(depth, i);
    const Eigen::VectorXd along = basis.transpose() * u;
    g.proj.col(i) = along;
    g.perp2(i) = (u - basis * along).squaredNorm();
    g.max_norm2 = std::max(g.max_norm2, u.squaredNorm());
  }
  return g;
}

bool safe(const DepthGeometry& g, double lambda) {
  const Eigen::Index p = g.proj.rows(), n = g.proj.cols();
  if (p == 0) return lambda * lambda * g.max_norm2 <= 1.0;
  Eigen::VectorXd w(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    w(i) = 1.0 - lambda * lambda * g.perp2(i);
    if (w(i) < 0.0) return false;
  }
  if (p == 1) {  // the intervals [c_i - sqrt w_i, c_i + sqrt w_i], c_i = -lambda Q'u_i
    double lo = -kDepthInf, hi = kDepthInf;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double c = -lambda * g.proj(0, i), r = std::sqrt(w(i));
      lo = std::max(lo, c - r);
      hi = std::min(hi, c + r);
    }
    return lo <= hi;
  }
  return minimax_power_distance(-lambda * g.proj, w).value <= 0.0;
}

}  // namespace

bool depth_is_safe(const ShakedownSamples& samples, int depth, double load_factor) {
  return safe(depth_geometry(samples, depth), load_factor);
}

DepthShakedownLimits shakedown_by_depth(const StressHistory& history, const YieldCriterion& criterion,
                                        const ResidualModel& model, double relative_tol) {
  if (!(relative_tol > 0.0 && relative_tol <= 0.1))
    throw std::invalid_argument("shakedown by depth: relative_tol must lie in (0, 0.1]");
  const ShakedownSamples s = shakedown_samples(history, criterion, model);
  DepthShakedownLimits out;
  out.load_factor.assign(static_cast<std::size_t>(s.depths), kDepthInf);
  out.min_load_factor = kDepthInf;
  for (int j = 0; j < s.depths; ++j) {
    throw_if_interrupted();
    const DepthGeometry g = depth_geometry(s, j);
    // The bracket's top: a safe lambda needs every w_i >= 0 and the c_i within 1 of a common t.
    double top = kDepthInf;
    if (g.proj.rows() == 0) {
      if (g.max_norm2 > 0.0) top = 1.0 / std::sqrt(g.max_norm2);
    } else {
      const double perp = std::sqrt(g.perp2.maxCoeff());
      if (perp > 0.0) top = 1.0 / perp;
      const double radius = g.proj.rows() == 1 ? 0.5 * (g.proj.maxCoeff() - g.proj.minCoeff())
                                               : smallest_enclosing_ball(g.proj).radius();
      if (radius > 0.0) top = std::min(top, 1.0 / radius);
    }
    double lambda = top;
    if (std::isfinite(top) && !safe(g, top)) {
      double lo = 0.0, hi = top;
      int steps = 0;
      while (hi - lo > relative_tol * hi && steps < 200) {
        const double mid = 0.5 * (lo + hi);
        (safe(g, mid) ? lo : hi) = mid;
        ++steps;
      }
      out.bisection_steps = std::max(out.bisection_steps, steps);
      lambda = lo;
    }
    out.load_factor[static_cast<std::size_t>(j)] = lambda;
    if (lambda < out.min_load_factor) {
      out.min_load_factor = lambda;
      out.critical_depth = j;
    }
  }
  return out;
}

}  // namespace dc
