#include "step_size_control.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace dc::dynamics {

TrajectoryPoint trajectory_point(const RigidBody& body, const RigidBodyState& state, const Wrench& w) {
  const double rho = body.gyration_radius();
  const Eigen::Matrix3d I = body.inertia_world(state.orientation);
  TrajectoryPoint p;
  p.time = state.time;
  p.position = state.position;
  p.velocity = state.velocity;
  p.rho_omega = rho * state.omega;
  p.acceleration = w.force / body.mass();
  // d(I_w Omega)/dt = M with dI_w/dt Omega = Omega x I_w Omega.
  p.rho_alpha = rho * I.inverse() * (w.moment - state.omega.cross(I * state.omega));
  return p;
}

void LocalErrorEstimate::note_speed(const TrajectoryPoint& p) {
  speed_ref_ = std::max({speed_ref_, p.velocity.norm(), p.rho_omega.norm()});
}

void LocalErrorEstimate::restart(const TrajectoryPoint& p) {
  last_ = p;
  has_previous_ = false;
  note_speed(p);
}

void LocalErrorEstimate::accept(const TrajectoryPoint& p) {
  previous_ = last_;
  last_ = p;
  has_previous_ = true;
  note_speed(p);
}

double LocalErrorEstimate::error(const RigidBodyState& end, Scheme scheme, const StepSizeOptions& o) const {
  const double h = end.time - last_.time;
  const Eigen::Vector3d rho_omega = rho_ * end.omega;
  // The predictor y_p of the step's own order from the accepted points, and Milne's constant
  // C = K / (K + D): the corrector's error K y^(p+1) and the predictor's D y^(p+1) give
  // y_c - y_exact ~ C (y_c - y_p).
  double C = 0.5;
  double lin = h, quad = 0.0;  // y_p = y_n + lin y'_n + quad (y_{n-1} - y_n + h_prev y'_n)
  if (scheme == Scheme::bdf2 && has_previous_) {
    // bdf2 with w = h / h_prev: K = h^3 (1+w)^2 / (6 w (1+2w)) (its truncation error); the
    // Hermite quadratic through y_{n-1}, y_n, y'_n: D = h^2 (h + h_prev) / 6; C = (1+w)/(2+3w)
    // (2/5 at w = 1).
    const double h_prev = last_.time - previous_.time;
    const double w = h / h_prev;
    C = (1.0 + w) / (2.0 + 3.0 * w);
    quad = w * w;
  }
  // bdf1: K = h^2/2 (backward Euler), y_p = y_n + h y'_n (forward Euler): D = h^2/2, C = 1/2.
  auto predicted = [&](const Eigen::Vector3d& y, const Eigen::Vector3d& dy, const Eigen::Vector3d& y_prev) {
    Eigen::Vector3d p = y + lin * dy;
    if (quad != 0.0) p += quad * (y_prev - y + (last_.time - previous_.time) * dy);
    return p;
  };
  const Eigen::Vector3d e_R = C * (end.position - predicted(last_.position, last_.velocity, previous_.position));
  const Eigen::Vector3d e_V = C * (end.velocity - predicted(last_.velocity, last_.acceleration, previous_.velocity));
  const Eigen::Vector3d e_W = C * (rho_omega - predicted(last_.rho_omega, last_.rho_alpha, previous_.rho_omega));
  // Weights (one scale per vector: a component crossing zero keeps it): velocities
  // atol + rtol v_ref, positions (atol + rtol v_ref) h.
  const double speed = std::max({speed_ref_, end.velocity.norm(), rho_omega.norm()});
  const double w_V = o.atol + o.rtol * speed;
  const double w_R = w_V * h;
  const double sum = (e_R / w_R).squaredNorm() + (e_V / w_V).squaredNorm() + (e_W / w_V).squaredNorm();
  return std::sqrt(sum / 9.0);
}

double propose_step(double h, double err, int order, bool after_rejection, const StepSizeOptions& o) {
  const double grow = after_rejection ? 1.0 : o.max_growth;
  double factor = grow;
  if (err > 0.0) factor = std::clamp(o.safety * std::pow(err, -1.0 / (order + 1)), o.max_shrink, grow);
  return std::clamp(h * factor, o.dt_min, o.dt_max);
}

double event_share(double g_start, double g_end) {
  if (!(std::isfinite(g_start) && std::isfinite(g_end)) || g_start * g_end > 0.0 || g_start == g_end) return 0.5;
  return std::clamp(g_start / (g_start - g_end), 0.0, 1.0);
}

}  // namespace dc::dynamics
