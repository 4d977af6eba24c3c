#include "rigid_body.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "errors.hpp"

namespace dc::dynamics {

RigidBody::RigidBody(double mass, const Eigen::Matrix3d& inertia_body, const std::string& key)
    : mass_(mass), inertia_(inertia_body) {
  if (!(std::isfinite(mass) && mass > 0.0))
    throw InputError(key + ".mass", "must be a positive finite number");
  const std::string ikey = key + ".inertia";
  if (!inertia_body.allFinite()) throw InputError(ikey, "must be finite");
  const double size = inertia_body.cwiseAbs().maxCoeff();
  if ((inertia_body - inertia_body.transpose()).cwiseAbs().maxCoeff() > 1e-12 * size)
    throw InputError(ikey, "must be symmetric");
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia_body);
  const Eigen::Vector3d moments = eig.eigenvalues();  // ascending
  if (!(moments(0) > 1e-14 * size))
    throw InputError(ikey, "must be positive definite (principal moments > 0)");
  // The largest moment may equal the sum of the two others (a lamina), not exceed it.
  if (moments(2) > (moments(0) + moments(1)) * (1.0 + 1e-12))
    throw InputError(ikey, "principal moments violate the triangle inequality I1 + I2 >= I3");
  inverse_inertia_ = inertia_body.inverse();
  gyration_radius_ = std::sqrt(inertia_body.trace() / (2.0 * mass));
}

RigidBody RigidBody::principal(double mass, double i1, double i2, double i3,
                               const std::string& key) {
  return RigidBody(mass, Eigen::Vector3d(i1, i2, i3).asDiagonal().toDenseMatrix(), key);
}

Eigen::Matrix3d RigidBody::inertia_world(const Eigen::Quaterniond& q) const {
  const Eigen::Matrix3d Q = q.toRotationMatrix();
  return Q * inertia_ * Q.transpose();
}

Eigen::Vector3d angular_momentum(const RigidBody& body, const RigidBodyState& state) {
  return body.inertia_world(state.orientation) * state.omega;
}

double kinetic_energy(const RigidBody& body, const RigidBodyState& state) {
  return 0.5 * body.mass() * state.velocity.squaredNorm() +
         0.5 * state.omega.dot(angular_momentum(body, state));
}

}  // namespace dc::dynamics
