#pragma once
// Rotations on the unit-quaternion manifold: exponential and logarithm maps, used to advance the
// orientation (the paper's direction cosines alpha in (3.10)) without leaving the manifold.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dc::dynamics {

/// exp(phi): the unit quaternion of a rotation by |phi| about phi/|phi| (Taylor near 0).
Eigen::Quaterniond exp_map(const Eigen::Vector3d& phi);

/// log(q): the rotation vector phi with exp(phi) == +-q, |phi| <= pi (shortest rotation).
Eigen::Vector3d log_map(const Eigen::Quaterniond& q);

}  // namespace dc::dynamics
