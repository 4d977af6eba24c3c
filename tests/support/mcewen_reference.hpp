#pragma once
// McEwen's stresses under a Hertz line contact with a proportional tangential traction, in the
// form the shakedown and Dang Van tests sample them: the library's closed forms
// (core/subsurface_closed_forms.hpp, Johnson 7.19) summed over the pressure p0 sqrt(1 - x^2/a^2)
// and the shear q0 sqrt(1 - x^2/a^2) along +x. Plane strain, z >= 0 into the solid, tension
// positive; sigma_yy = nu (sigma_xx + sigma_zz).
#include "subsurface_closed_forms.hpp"
#include "voigt_stress.hpp"

namespace dc::test {

struct LineContactStress {
  double xx = 0.0, zz = 0.0, xz = 0.0;
};

inline LineContactStress mcewen_stress(double x, double z, double a, double p0, double q0) {
  const closed_form::PlaneStresses n = closed_form::mcewen_normal(x, z, a, p0);
  const closed_form::PlaneStresses t = closed_form::mcewen_tangential(x, z, a, q0);
  return {n.sigma_xx + t.sigma_xx, n.sigma_zz + t.sigma_zz, n.sigma_xz + t.sigma_xz};
}

/// The full plane-strain stress (Voigt).
inline Voigt mcewen_voigt(double x, double z, double a, double p0, double q0, double nu) {
  const LineContactStress s = mcewen_stress(x, z, a, p0, q0);
  return {s.xx, nu * (s.xx + s.zz), s.zz, 0.0, s.xz, 0.0};
}

}  // namespace dc::test
