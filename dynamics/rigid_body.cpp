#include "rigid_body.hpp"

namespace dc {

double kinetic_energy(const RigidBodyState& s, double mass, const std::array<double, 3>& inertia) {
  double e = 0.0;
  for (int k = 0; k < 3; ++k)
    e += 0.5 * mass * s.velocity[k] * s.velocity[k] + 0.5 * inertia[k] * s.omega[k] * s.omega[k];
  return e;
}

}  // namespace dc
