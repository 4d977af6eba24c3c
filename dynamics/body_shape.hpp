#pragma once
// The convex bodies whose gap (2.6) is defined at any orientation (docs/dynamics.md, "Body
// shapes"): an ellipsoid and a finite circular cylinder (a wheel), centred on the centre of mass.
// Given the body's rotation Q (body -> world), each gives the lowest point of the body and, for
// a vertical line at (x, y) from the centre of mass, the height of the body's lower surface over
// that lowest point (the lower intersection of the line with the convex body; +infinity when
// the line misses it).
#include <Eigen/Core>

namespace dc::dynamics {

/// The body at one orientation: what the gap needs.
struct OrientedShape {
  double centre_height = 0.0;  ///< height of the centre of mass over the lowest point (m)
  Eigen::Vector2d lowest{0.0, 0.0};  ///< horizontal position of the lowest point from the centre of mass (m)
};

/// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1 in body axes.
class EllipsoidShape {
 public:
  EllipsoidShape(double a, double b, double c) : semi_(a, b, c) {}
  /// Orients the body: the quadratic form M = Q diag(1/a^2, 1/b^2, 1/c^2) Q^T and the lowest
  /// point -S e_z / sqrt(S_zz), S = M^-1, at depth sqrt(S_zz) below the centre.
  OrientedShape orient(const Eigen::Matrix3d& Q);
  /// Height over the lowest point of the lower surface at (x, y) from the centre (orient first).
  double height(double x, double y) const;

 private:
  Eigen::Vector3d semi_;
  Eigen::Matrix3d M_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d lowest_ = Eigen::Vector3d::Zero();
  double inv_depth_ = 1.0;
};

/// Circular cylinder of radius R about the body's y axis, |y| <= length / 2 (length > 0).
class CylinderShape {
 public:
  CylinderShape(double radius, double length) : radius_(radius), half_length_(0.5 * length) {}
  /// Orients the body by its axis u = Q e_y: tilted (u_z != 0), the lowest point is on the rim of
  /// the lower end face, R sqrt(1 - u_z^2) + (length/2) |u_z| below the centre.
  OrientedShape orient(const Eigen::Vector3d& axis);
  double height(double x, double y) const;

 private:
  double radius_, half_length_;
  Eigen::Vector3d u_ = Eigen::Vector3d::UnitY();
  double depth_ = 0.0;
};

}  // namespace dc::dynamics
