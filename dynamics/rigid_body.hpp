#pragma once
// Rigid-body state of the paper's (2.20)-(2.21): filled in by the dynamics issue.
#include <array>

namespace dc {

struct RigidBodyState {
  std::array<double, 3> position{};  ///< centre of mass R (m)
  std::array<double, 3> velocity{};  ///< V (m/s)
  std::array<double, 3> omega{};     ///< Omega (rad/s)
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  ///< unit quaternion (w, x, y, z)
};

/// Kinetic energy of a body with mass M and principal inertia I (body axes aligned).
double kinetic_energy(const RigidBodyState& state, double mass, const std::array<double, 3>& inertia);

}  // namespace dc
