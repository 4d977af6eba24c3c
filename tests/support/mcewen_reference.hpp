#pragma once
// TEMPORARY test helper (the library's version is coming in core/subsurface_closed_forms.hpp;
// the shakedown and Dang Van tests switch to it at the merge): McEwen's closed form of the
// stresses under a Hertz line contact with a proportional tangential traction
// (E. McEwen, Phil. Mag. 40 (1949) 454-459; K. L. Johnson, Contact Mechanics, Cambridge 1985,
// section 7.2, eq. (7.19) with m and n; the normal part also in section 4.2).
//
// Plane strain, the solid z >= 0 (z into it), tension positive. On its surface z = 0 act
//   p(x) = p0 sqrt(1 - x^2/a^2)  (pressure, pushing into the solid: sigma_zz = -p),
//   q(x) = q0 sqrt(1 - x^2/a^2)  (the traction along +x on the solid: sigma_xz = -q),
// |x| < a, q0 = mu_t p0. With
//   m^2 = ( sqrt((a^2 - x^2 + z^2)^2 + 4 x^2 z^2) + (a^2 - x^2 + z^2) ) / 2,
//   n^2 = ( sqrt((a^2 - x^2 + z^2)^2 + 4 x^2 z^2) - (a^2 - x^2 + z^2) ) / 2,
// m >= 0 and n of the sign of x:
//   normal part      sigma_xx = -(p0/a) [ m (1 + (z^2 + n^2)/(m^2 + n^2)) - 2z ]
//                    sigma_zz = -(p0/a)   m (1 - (z^2 + n^2)/(m^2 + n^2))
//                    sigma_xz = -(p0/a)   n (m^2 - z^2)/(m^2 + n^2)
//   tangential part  sigma_xx =  (q0/a) [ n (2 - (z^2 - m^2)/(m^2 + n^2)) - 2x ]
//                    sigma_zz = -(q0/a)   n (m^2 - z^2)/(m^2 + n^2)
//                    sigma_xz = -(q0/a) [ m (1 + (z^2 + n^2)/(m^2 + n^2)) - 2z ]
// The signs here are those of Flamant's line-load kernels (Johnson 1985 chapter 2) superposed
// with this file's conventions (z into the solid); some sources print the normal part's shear
// with the opposite sign (another shear convention).
// test_shakedown.cpp checks these against a direct quadrature of the Flamant kernels and
// against the axis values. sigma_yy = nu (sigma_xx + sigma_zz) (plane strain).
#include <algorithm>
#include <cmath>

#include "voigt_stress.hpp"

namespace dc::test {

struct LineContactStress {
  double xx = 0.0, zz = 0.0, xz = 0.0;
};

inline LineContactStress mcewen_stress(double x, double z, double a, double p0, double q0) {
  const double b = a * a - x * x + z * z;
  const double root = std::sqrt(b * b + 4.0 * x * x * z * z);
  const double m2 = std::max(0.5 * (root + b), 0.0), n2 = std::max(0.5 * (root - b), 0.0);
  const double m = std::sqrt(m2), n = std::copysign(std::sqrt(n2), x);
  const double mn = m2 + n2;
  // On the surface at the contact's edges m = n = 0: every ratio below is multiplied by m or n.
  const double r1 = mn > 0.0 ? (z * z + n2) / mn : 0.0;
  const double r2 = mn > 0.0 ? (m2 - z * z) / mn : 0.0;
  const double r3 = mn > 0.0 ? (z * z - m2) / mn : 0.0;
  LineContactStress s;
  s.xx = -(p0 / a) * (m * (1.0 + r1) - 2.0 * z) + (q0 / a) * (n * (2.0 - r3) - 2.0 * x);
  s.zz = -(p0 / a) * m * (1.0 - r1) - (q0 / a) * n * r2;
  s.xz = -(p0 / a) * n * r2 - (q0 / a) * (m * (1.0 + r1) - 2.0 * z);
  return s;
}

/// The full plane-strain stress (Voigt), sigma_yy = nu (sigma_xx + sigma_zz).
inline Voigt mcewen_voigt(double x, double z, double a, double p0, double q0, double nu) {
  const LineContactStress s = mcewen_stress(x, z, a, p0, q0);
  return {s.xx, nu * (s.xx + s.zz), s.zz, 0.0, s.xz, 0.0};
}

}  // namespace dc::test
