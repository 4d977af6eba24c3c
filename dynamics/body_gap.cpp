#include "body_gap.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "errors.hpp"

namespace dc::dynamics {
namespace {

/// The heading (rad about z) of a horizontal body axis turned to `axis`.
double heading_of(const Eigen::Vector3d& axis) { return std::atan2(axis.y(), axis.x()); }

/// Angle (rad) of `v` from the horizontal plane.
double elevation(const Eigen::Vector3d& v) { return std::atan2(std::abs(v.z()), std::hypot(v.x(), v.y())); }

std::string upright_only(ProfileType type) {
  return std::string("the gap of a '") + to_string(type) +
         "' profile is defined for an upright body (turned about z) only; give a body that tilts as an "
         "'ellipsoid' (a quadratic a x^2 + b y^2 is one with radius_x = 1/(2a), radius_y = 1/(2b)), a "
         "'sphere' or a 'cylinder' with a length";
}

}  // namespace

BodyGap::BodyGap(const ProfileSpec& profile, const Grid& grid, double centre_height)
    : profile_(profile),
      grid_(grid),
      radius_(centre_height),
      upright_(profile, grid),
      heights_(profile_heights(profile, grid)),
      ellipsoid_shape_(std::sqrt(profile.radius_x * centre_height), std::sqrt(profile.radius_y * centre_height),
                       centre_height),
      cylinder_shape_(profile.radius, profile.length) {
  oriented_.centre_height = centre_height;
  if (grid.dimension == 2 || profile.type == ProfileType::sphere) mode_ = Mode::fixed;
  // A wheel: finite, its centre of mass on its axis.
  wheel_ = profile.type == ProfileType::cylinder && profile.length > 0.0 &&
           std::abs(profile.radius - centre_height) <= 1e-12 * profile.radius;
}

bool BodyGap::turn(double heading) {
  if (mode_ == Mode::upright && std::abs(heading - heading_) <= kSameTurn) return false;
  mode_ = Mode::upright;
  heading_ = heading;
  oriented_ = {radius_, Eigen::Vector2d::Zero()};
  upright_.heights(heading, heights_);
  return true;
}

void BodyGap::check_tilt(double tilt, double t, const char* key, const std::string& why) const {
  if (tilt <= kRejectTilt) return;
  char when[160];
  std::snprintf(when, sizeof when, "at t = %.6g s the body is tilted by %.3g rad (more than %.0e rad): ", t, tilt,
                kRejectTilt);
  throw InputError(key, when + why);
}

template <class Shape>
void BodyGap::fill(const Shape& shape) {
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) heights_[grid_.index(i, j)] = shape.height(grid_.xc(i), grid_.yc(j));
}

bool BodyGap::update(const Eigen::Quaterniond& q, double t) {
  if (mode_ == Mode::fixed) return false;
  const Eigen::Vector3d ez = q * Eigen::Vector3d::UnitZ();
  const double tilt = std::atan2(std::hypot(ez.x(), ez.y()), ez.z());
  switch (profile_.type) {
    case ProfileType::ellipsoid: {
      if (tilt <= kUprightTilt) return turn(heading_of(q * Eigen::Vector3d::UnitX()));
      if (mode_ == Mode::tilted && q.coeffs() == key_) return false;  // any turn changes the gap
      mode_ = Mode::tilted;
      key_ = q.coeffs();
      oriented_ = ellipsoid_shape_.orient(q.toRotationMatrix());
      fill(ellipsoid_shape_);
      return true;
    }
    case ProfileType::cylinder: {
      // Only the axis matters: rolling about it changes nothing.
      const Eigen::Vector3d u = q * Eigen::Vector3d::UnitY();
      const double camber = elevation(u), heading = std::atan2(-u.x(), u.y());
      if (camber <= kUprightTilt) return turn(heading);
      if (!wheel_) {
        if (profile_.length > 0.0)
          check_tilt(camber, t, "body.radius",
                     "a cambered cylinder's gap needs its centre of mass on its axis (body.radius = profile.radius)");
        else
          check_tilt(camber, t, "profile.length",
                     "a cylinder without a length cannot camber (tilt about a horizontal axis across its own): give "
                     "its length");
        return turn(heading);
      }
      const Eigen::Vector4d key(u.x(), u.y(), u.z(), 0.0);
      if (mode_ == Mode::tilted && (key - key_).lpNorm<Eigen::Infinity>() <= kSameTurn) return false;
      mode_ = Mode::tilted;
      key_ = key;
      oriented_ = cylinder_shape_.orient(u);
      fill(cylinder_shape_);
      return true;
    }
    case ProfileType::flat_punch:
      check_tilt(tilt, t, "profile.type", upright_only(profile_.type));
      return false;  // the same at any heading
    case ProfileType::quadratic:
    case ProfileType::table:
      check_tilt(tilt, t, "profile.type", upright_only(profile_.type));
      return turn(heading_of(q * Eigen::Vector3d::UnitX()));
    case ProfileType::sphere:
      break;
  }
  return false;
}

GapSensitivity BodyGap::sensitivity(const Eigen::Quaterniond& q) const {
  GapSensitivity d;
  const bool ellipsoid = profile_.type == ProfileType::ellipsoid && grid_.dimension == 3;
  if (!ellipsoid && !wheel_) return d;
  if (wheel_ && elevation(q * Eigen::Vector3d::UnitY()) <= kSmoothCamber) return d;
  EllipsoidShape ellipsoid_shape = ellipsoid_shape_;
  CylinderShape cylinder_shape = cylinder_shape_;
  auto at = [&](const Eigen::Vector3d& theta) {
    const Eigen::Quaterniond turned =
        theta.norm() > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(theta.norm(), theta.normalized())) * q : q;
    return ellipsoid ? ellipsoid_shape.orient(turned.toRotationMatrix())
                     : cylinder_shape.orient(turned * Eigen::Vector3d::UnitY());
  };
  constexpr double step = 1e-6;  // rad: round-off ~1e-16 / 1e-6 of the lowest point's lever
  for (int l = 0; l < 3; ++l) {
    const Eigen::Vector3d e = step * Eigen::Vector3d::Unit(l);
    const OrientedShape plus = at(e), minus = at(-e);
    d.centre_height(l) = (plus.centre_height - minus.centre_height) / (2.0 * step);
    d.lowest.col(l) = (plus.lowest - minus.lowest) / (2.0 * step);
  }
  return d;
}

}  // namespace dc::dynamics
