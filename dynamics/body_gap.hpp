#pragma once
// The undeformed gap (2.6) of the moving body on the grid that follows it (origin under the
// centre of mass), at the body's current orientation (docs/dynamics.md, "Body shapes"):
// - sphere, and every 2-D case: invariant, computed once;
// - ellipsoid (radius_x, radius_y at its lowest point, depth body.radius = c): the ellipsoid of
//   semi-axes sqrt(radius_x c), sqrt(radius_y c), c; upright (turned about z only) it keeps the
//   profile's quadratic gap, tilted its exact lower surface;
// - cylinder (3-D, a wheel about the body's y axis): invariant under rolling about its axis;
//   cambered, the exact lower surface of the finite cylinder (it touches with its rim);
// - flat_punch, quadratic, table: defined upright only; a tilt beyond kRejectTilt is an input
//   error naming the time.
// The heights live in one buffer, rewritten only when the orientation changes the gap.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "body_shape.hpp"
#include "grid.hpp"
#include "profile.hpp"
#include "profile_turned.hpp"

namespace dc::dynamics {

/// How the body's lowest point moves as it turns: per unit rotation vector theta of
/// q -> exp(theta) q (world frame, columns x, y, z).
struct GapSensitivity {
  Eigen::RowVector3d centre_height = Eigen::RowVector3d::Zero();  ///< d centre_height / d theta (m/rad)
  Eigen::Matrix<double, 2, 3> lowest = Eigen::Matrix<double, 2, 3>::Zero();  ///< d lowest point / d theta (m/rad)
};

class BodyGap {
 public:
  /// Below this tilt (rad) a body counts as upright: the profile's own gap, turned about z.
  static constexpr double kUprightTilt = 1e-12;
  /// Beyond this tilt (rad) a body whose gap is defined upright only is rejected.
  static constexpr double kRejectTilt = 1e-6;
  /// Turns smaller than this (rad, or in the components of a unit axis) leave the gap as it is:
  /// a rolling wheel's axis, recomputed each step, wanders by round-off only.
  static constexpr double kSameTurn = 1e-14;

  /// `centre_height`: body.radius, the height of the centre of mass over the upright body's
  /// lowest point.
  BodyGap(const ProfileSpec& profile, const Grid& grid, double centre_height);

  /// The gap at orientation q (body -> world) at time t (for messages). Returns true when the
  /// heights changed. Throws InputError for a tilt the profile cannot take.
  bool update(const Eigen::Quaterniond& q, double t);

  /// Height over the body's lowest point of its lower surface above each element (m, >= 0;
  /// +infinity where the body is not above the element).
  const std::vector<double>& heights() const { return heights_; }
  /// Height of the centre of mass over the lowest point: the approach at centre height z is
  /// centre_height() - z.
  double centre_height() const { return oriented_.centre_height; }
  /// Horizontal position of the lowest point from the centre of mass.
  const Eigen::Vector2d& lowest_point() const { return oriented_.lowest; }
  /// The lowest point's motion at orientation q (central differences of the shape's analytic
  /// lowest point, no heights): an ellipsoid at any orientation, a wheel cambered by more than
  /// kSmoothCamber (upright its rim contact has a kink); zero for the invariant and upright-only gaps.
  GapSensitivity sensitivity(const Eigen::Quaterniond& q) const;
  static constexpr double kSmoothCamber = 1e-3;

 private:
  enum class Mode { fixed, upright, tilted };
  /// The upright gap turned by `heading` (rad about z).
  bool turn(double heading);
  /// Throws when a profile defined upright only is tilted beyond kRejectTilt.
  void check_tilt(double tilt, double t, const char* key, const std::string& why) const;
  /// The heights of a tilted shape (oriented first) into the buffer.
  template <class Shape>
  void fill(const Shape& shape);

  const ProfileSpec& profile_;
  const Grid& grid_;
  const double radius_;
  TurnedProfile upright_;  // the profile's own gap, turned about z
  std::vector<double> heights_;
  OrientedShape oriented_;
  Mode mode_ = Mode::upright;
  double heading_ = 0.0;            // of the upright gap
  Eigen::Vector4d key_ = Eigen::Vector4d::Zero();  // of the tilted gap: q (ellipsoid) or the axis (cylinder)
  bool wheel_ = false;  // a cylinder that can camber: finite, its centre of mass on its axis
  EllipsoidShape ellipsoid_shape_;
  CylinderShape cylinder_shape_;
};

}  // namespace dc::dynamics
