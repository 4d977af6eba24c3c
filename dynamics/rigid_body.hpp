#pragma once
// The rigid body of (2.20)-(2.21): its inertia data (RigidBody) and its kinematic state.
//
// Conventions (docs/dynamics.md):
//  - orientation q is a unit quaternion mapping BODY axes to WORLD axes:
//    x_world = R + q * x_body (q * v = q v q^-1); the rotation matrix of q is the paper's
//    direction cosines alpha;
//  - V and Omega are stored in the WORLD frame; the body-frame angular velocity of (2.21) is
//    q^-1 * Omega. The world inertia is I_world = Q I_body Q^T (Q the matrix of q);
//  - SI units.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

namespace dc::dynamics {

/// Mass m (kg) and inertia tensor about the centre of mass in body axes (kg m^2).
class RigidBody {
 public:
  /// Validates: m > 0 and finite ("<key>.mass"); inertia symmetric, positive definite and its
  /// principal moments obeying the triangle inequality I_i + I_j >= I_k ("<key>.inertia").
  /// Throws dc::InputError naming the key.
  RigidBody(double mass, const Eigen::Matrix3d& inertia_body, const std::string& key = "body");

  /// Principal moments on the body axes: inertia = diag(i1, i2, i3).
  static RigidBody principal(double mass, double i1, double i2, double i3,
                             const std::string& key = "body");

  double mass() const { return mass_; }
  const Eigen::Matrix3d& inertia_body() const { return inertia_; }
  const Eigen::Matrix3d& inverse_inertia_body() const { return inverse_inertia_; }
  /// Radius of gyration sqrt(trace(I) / (2 m)): the length that turns Omega into a speed.
  double gyration_radius() const { return gyration_radius_; }

  /// I_world = Q I_body Q^T for the orientation q (body -> world).
  Eigen::Matrix3d inertia_world(const Eigen::Quaterniond& q) const;

 private:
  double mass_;
  Eigen::Matrix3d inertia_;
  Eigen::Matrix3d inverse_inertia_;
  double gyration_radius_;
};

/// State at time t: centre of mass R, orientation q (body -> world), V and Omega (world frame).
struct RigidBodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();            ///< R (m)
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< q, unit, body -> world
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            ///< V (m/s), world
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();               ///< Omega (rad/s), world
  double time = 0.0;                                             ///< t (s)

  /// Omega in body axes, q^-1 * Omega: the angular velocity of the paper's (2.21).
  Eigen::Vector3d omega_body() const { return orientation.conjugate() * omega; }
};

/// Angular momentum about the centre of mass, world frame: I_world Omega.
Eigen::Vector3d angular_momentum(const RigidBody& body, const RigidBodyState& state);

/// Kinetic energy m|V|^2/2 + Omega . I_world Omega / 2.
double kinetic_energy(const RigidBody& body, const RigidBodyState& state);

}  // namespace dc::dynamics
