#pragma once
// The external resultant on the body as a function of the end-of-step kinematics: the right-hand
// sides F_{K+1} + int f_s and T_{K+1} + int r x f_s of (3.9)-(3.10). The contact part will
// depend on the approach and the rigid slip v at t_{K+1}, hence a callback of StepKinematics.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>

namespace dc::dynamics {

/// Trial kinematics at the end of a step, t_{K+1} (same frames as RigidBodyState).
struct StepKinematics {
  Eigen::Vector3d position;        ///< R_{K+1} (m), world
  Eigen::Quaterniond orientation;  ///< q_{K+1}, body -> world
  Eigen::Vector3d velocity;        ///< V_{K+1} (m/s), world
  Eigen::Vector3d omega;           ///< Omega_{K+1} (rad/s), world
  double time;                     ///< t_{K+1} (s)
};

/// Resultant force (N) and moment about the centre of mass (N m), both in the world frame.
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
};

/// Called several times per step (once per Newton residual and finite-difference column): it
/// must be a pure function of its argument. Keep captures small: std::function holds a callable
/// of up to a few pointers without allocating.
using WrenchFunction = std::function<Wrench(const StepKinematics&)>;

/// The sensitivity of the wrench (rows F, M) to the end-of-step position R, velocity V, angular
/// velocity Omega and orientation q (columns x, y, z; world frame; the orientation's columns per
/// unit rotation vector theta of q -> exp(theta) q).
struct WrenchJacobian {
  Eigen::Matrix<double, 6, 3> position = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 6, 3> velocity = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 6, 3> omega = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 6, 3> orientation = Eigen::Matrix<double, 6, 3>::Zero();
  bool valid = true;  ///< false: not available (Newton falls back to finite differences)
  /// Its costly part kept from an earlier evaluation (asked with fresh = false): a chord Jacobian,
  /// whose step Newton checks (NewtonOptions::chord_contraction).
  bool kept = false;
};

/// Called right after the WrenchFunction at the same kinematics (it may reuse that evaluation).
/// `fresh`: the sensitivity at these kinematics; else one kept from an earlier evaluation may do.
using WrenchJacobianFunction = std::function<WrenchJacobian(const StepKinematics&, bool fresh)>;

}  // namespace dc::dynamics
