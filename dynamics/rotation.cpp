#include "rotation.hpp"

#include <cmath>

namespace dc::dynamics {

Eigen::Quaterniond exp_map(const Eigen::Vector3d& phi) {
  const double angle = phi.norm();
  const double half = 0.5 * angle;
  // sin(half)/angle, with its Taylor series below 1e-4 rad (error < 1e-17).
  const double k = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
  return Eigen::Quaterniond(std::cos(half), k * phi.x(), k * phi.y(), k * phi.z());
}

Eigen::Vector3d log_map(const Eigen::Quaterniond& q_in) {
  // q and -q are the same rotation: take w >= 0 so that the angle is in [0, pi].
  const Eigen::Quaterniond q = q_in.w() < 0.0 ? Eigen::Quaterniond(-q_in.coeffs()) : q_in;
  const double s = q.vec().norm();
  const double angle = 2.0 * std::atan2(s, q.w());
  // angle / sin(angle/2) -> 2 / w as s -> 0 (error O(s^2)).
  const double k = s < 1e-8 ? 2.0 / q.w() : angle / s;
  return k * q.vec();
}

}  // namespace dc::dynamics
