#include "body_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dc::dynamics {
namespace {
constexpr double kMiss = std::numeric_limits<double>::infinity();
}

OrientedShape EllipsoidShape::orient(const Eigen::Matrix3d& Q) {
  const Eigen::Vector3d inv2 = semi_.cwiseProduct(semi_).cwiseInverse();
  M_ = Q * inv2.asDiagonal() * Q.transpose();
  // S = M^-1 = Q diag(a^2, b^2, c^2) Q^T; the support in -e_z: depth sqrt(S_zz) = sqrt(a^2 n_x^2 +
  // b^2 n_y^2 + c^2 n_z^2) with n = Q^T e_z, the vertical in body axes.
  const Eigen::Vector3d n = Q.row(2).transpose();
  const Eigen::Vector3d Sn = semi_.cwiseProduct(semi_).cwiseProduct(n);
  const double depth = std::sqrt(n.dot(Sn));
  lowest_ = -(Q * Sn) / depth;
  inv_depth_ = 1.0 / depth;
  return {depth, lowest_.head<2>()};
}

double EllipsoidShape::height(double x, double y) const {
  // p = lowest + (xi, eta, t) on the surface, p^T M p = 1 with M lowest = -e_z / depth:
  // M_zz t^2 - 2 k t + q = 0, k = 1/depth - (M_xz xi + M_yz eta), q = the horizontal form.
  // Its lower root, rationalised (no cancellation near the lowest point): t = q / (k + sqrt(D)).
  const double xi = x - lowest_.x(), eta = y - lowest_.y();
  const double k = inv_depth_ - (M_(0, 2) * xi + M_(1, 2) * eta);
  const double q = M_(0, 0) * xi * xi + 2.0 * M_(0, 1) * xi * eta + M_(1, 1) * eta * eta;
  const double D = k * k - M_(2, 2) * q;
  if (D < 0.0) return kMiss;
  const double denominator = k + std::sqrt(D);
  return denominator > 0.0 ? std::max(0.0, q / denominator) : 0.0;
}

OrientedShape CylinderShape::orient(const Eigen::Vector3d& axis) {
  u_ = axis.normalized();
  const double uz = u_.z(), sigma = std::hypot(u_.x(), u_.y());  // sigma = cos(camber)
  depth_ = radius_ * sigma + half_length_ * std::abs(uz);
  // The lowest point: on the rim of the lower end face (the one at -sign(u_z) L/2 along u), in
  // the direction of -(e_z - u_z u) / sigma from the face's centre.
  const double end = uz > 0.0 ? -half_length_ : (uz < 0.0 ? half_length_ : 0.0);
  Eigen::Vector3d down = -(Eigen::Vector3d::UnitZ() - uz * u_);
  if (sigma > 0.0) down /= sigma;
  const Eigen::Vector3d lowest = end * u_ + radius_ * down;
  return {depth_, lowest.head<2>()};
}

double CylinderShape::height(double x, double y) const {
  // The vertical line p = (x, y, t) from the centre: inside the infinite cylinder when
  // |p|^2 - (p.u)^2 <= R^2, i.e. sigma^2 t^2 - 2 beta t + gamma <= 0; between the end faces when
  // |p.u| <= L/2. The lower end of both intervals, over the lowest point (t = -depth).
  const double wu = x * u_.x() + y * u_.y(), uz = u_.z();
  const double alpha = u_.x() * u_.x() + u_.y() * u_.y();
  const double beta = uz * wu, gamma = x * x + y * y - wu * wu - radius_ * radius_;
  double lo = -kMiss, hi = kMiss;
  if (alpha > 0.0) {
    const double D = beta * beta - alpha * gamma;
    if (D < 0.0) return kMiss;
    const double q = beta >= 0.0 ? beta + std::sqrt(D) : beta - std::sqrt(D);
    const double r1 = q / alpha, r2 = q != 0.0 ? gamma / q : 0.0;
    lo = std::min(r1, r2);
    hi = std::max(r1, r2);
  } else if (gamma > 0.0) {
    return kMiss;  // axis vertical: outside the circle
  }
  if (uz != 0.0) {
    const double t1 = (-half_length_ - wu) / uz, t2 = (half_length_ - wu) / uz;
    lo = std::max(lo, std::min(t1, t2));
    hi = std::min(hi, std::max(t1, t2));
  } else if (std::abs(wu) > half_length_) {
    return kMiss;
  }
  if (lo > hi) return kMiss;
  return std::max(0.0, lo + depth_);
}

}  // namespace dc::dynamics
