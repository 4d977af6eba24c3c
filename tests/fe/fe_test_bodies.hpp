#pragma once
// Bodies shared by the finite-contact tests.
#include "fe_body_spec.hpp"
#include "elastic_stiffness.hpp"

namespace dc::fe::testing {

/// A flat-ended cylinder of radius and height a, `stiffness` times E (Poisson's ratio nu):
/// with 1000 x the half-space's modulus, a rigid flat punch.
inline FeBodySpec stiff_flat_cylinder(double a, double E, double nu, double stiffness = 1000.0) {
  FeBodySpec s;
  s.shape = FeShape::cylinder;
  s.radius = a;
  s.height = a;
  s.elements = {6, 6, 3};
  s.contact_size = a / 6.0;
  s.material = {isotropic_stiffness(stiffness * E, nu, "test"), 7800.0};
  return s;
}

}  // namespace dc::fe::testing
