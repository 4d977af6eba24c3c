#include "subsurface_closed_forms.hpp"

#include <cmath>

namespace dc::closed_form {

AxisStresses hertz_sphere_axis(double z, double a, double p0, double nu) {
  const double t = z / a, s = 1.0 / (1.0 + t * t);
  AxisStresses out;
  out.sigma_z = -p0 * s;
  // (z/a) atan(a/z) -> 1 - ... as z -> inf; 0 at z = 0.
  const double z_atan = t == 0.0 ? 0.0 : t * std::atan(1.0 / t);
  out.sigma_r = -p0 * ((1.0 + nu) * (1.0 - z_atan) - 0.5 * s);
  return out;
}

double hertz_sphere_surface_radial(double r, double a, double p0, double nu) {
  const double rho = std::abs(r) / a;
  if (rho >= 1.0) return (1.0 - 2.0 * nu) * p0 / (3.0 * rho * rho);
  if (rho == 0.0) return -0.5 * (1.0 + 2.0 * nu) * p0;
  // (1 - root^3) / rho^2 = (1 + root + root^2) / (1 + root), free of cancellation near r = 0.
  const double root = std::sqrt((1.0 - rho) * (1.0 + rho));
  return p0 * ((1.0 - 2.0 * nu) / 3.0 * (1.0 + root + root * root) / (1.0 + root) - root);
}

namespace {
/// McEwen's m and n ([J] 7.20): m^2, n^2 = ((A^2 + 4 x^2 z^2)^(1/2) +- A) / 2 with
/// A = a^2 - x^2 + z^2; m has the sign of z, n that of x. The smaller square from m^2 n^2 = x^2 z^2.
void mcewen_mn(double x, double z, double a, double& m, double& n) {
  const double A = a * a - x * x + z * z, root = std::sqrt(A * A + 4.0 * x * x * z * z);
  double m2, n2;
  if (A >= 0.0) {
    m2 = 0.5 * (root + A);
    n2 = m2 > 0.0 ? x * x * z * z / m2 : 0.0;
  } else {
    n2 = 0.5 * (root - A);
    m2 = n2 > 0.0 ? x * x * z * z / n2 : 0.0;
  }
  m = std::copysign(std::sqrt(m2), z);
  n = std::copysign(std::sqrt(n2), x);
  if (z == 0.0) m = std::abs(m);
}
}  // namespace

PlaneStresses mcewen_normal(double x, double z, double a, double p0) {
  double m, n;
  mcewen_mn(x, z, a, m, n);
  const double s = m * m + n * n, k = p0 / a;
  PlaneStresses out;
  if (s == 0.0) return out;  // the contact's edge on the surface: all terms vanish
  out.sigma_xx = -k * (m * (1.0 + (z * z + n * n) / s) - 2.0 * z);
  out.sigma_zz = -k * m * (1.0 - (z * z + n * n) / s);
  out.sigma_xz = -k * n * (m * m - z * z) / s;
  return out;
}

PlaneStresses mcewen_tangential(double x, double z, double a, double q0) {
  double m, n;
  mcewen_mn(x, z, a, m, n);
  const double s = m * m + n * n, k = q0 / a;
  PlaneStresses out;
  if (s == 0.0) {
    out.sigma_xx = -2.0 * k * x;
    return out;
  }
  out.sigma_xx = k * (n * (2.0 - (z * z - m * m) / s) - 2.0 * x);
  out.sigma_zz = -k * n * (m * m - z * z) / s;
  out.sigma_xz = -k * (m * (1.0 + (z * z + n * n) / s) - 2.0 * z);
  return out;
}

PlaneStresses line_contact_axis(double z, double a, double p0) {
  const double root = std::sqrt(a * a + z * z);
  PlaneStresses out;
  out.sigma_zz = -p0 * a / root;
  out.sigma_xx = -p0 * ((a * a + 2.0 * z * z) / (a * root) - 2.0 * z / a);
  return out;
}

}  // namespace dc::closed_form
