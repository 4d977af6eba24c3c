#pragma once
// Closed-form stress fields inside a half-space under Hertzian loads, the references of the
// subsurface field (subsurface_field.hpp). Half-space frame: depth z >= 0 into the solid,
// tension positive; the surface traction (pressure p > 0 into the solid, shear q along +x) is
// the force per area on the solid.
//
// Sources:
//  [J]  K. L. Johnson, Contact Mechanics, Cambridge University Press (1985).
//  [M]  E. McEwen, Phil. Mag. 40 (1949) 454-459; [J] section 7.2, (7.19) with m, n of (7.20)
//       (the tangential part is (7.19)'s, with its sign for a shear along +x).
namespace dc::closed_form {

/// Stresses on the axis r = 0 of Hertz's sphere at depth z ([J] 3.45, from Huber 1904):
/// sigma_z = -p0 / (1 + z^2/a^2),
/// sigma_r = sigma_theta = -p0 [(1 + nu)(1 - (z/a) atan(a/z)) - 1 / (2 (1 + z^2/a^2))].
struct AxisStresses {
  double sigma_r = 0.0, sigma_z = 0.0;
};
AxisStresses hertz_sphere_axis(double z, double a, double p0, double nu);

/// Radial stress on the surface of Hertz's sphere ([J] 3.41): inside (r < a)
/// p0 [(1 - 2nu)/3 (a^2/r^2)(1 - (1 - r^2/a^2)^(3/2)) - sqrt(1 - r^2/a^2)]; outside
/// (1 - 2nu) p0 a^2 / (3 r^2) (tension; sigma_theta = -sigma_r there). r = 0: -(1 + 2nu) p0 / 2.
double hertz_sphere_surface_radial(double r, double a, double p0, double nu);

/// Plane stresses (sigma_xx, sigma_zz, sigma_xz) at (x, z) in plane strain.
struct PlaneStresses {
  double sigma_xx = 0.0, sigma_zz = 0.0, sigma_xz = 0.0;
};

/// Line (cylinder) contact, pressure p0 sqrt(1 - x^2/a^2) ([M]; [J] 7.19, the p0 terms).
PlaneStresses mcewen_normal(double x, double z, double a, double p0);
/// The same contact's shear traction q0 sqrt(1 - x^2/a^2) along +x ([M]; [J] 7.19, the q0
/// terms): full sliding is q0 = mu p0 (the sum of both parts).
PlaneStresses mcewen_tangential(double x, double z, double a, double q0);

/// On the axis x = 0 of the line contact ([J] 4.46 and 7.19 at x = 0):
/// sigma_z = -p0 a / sqrt(a^2 + z^2), sigma_x = -p0 [(a^2 + 2 z^2) / (a sqrt(a^2 + z^2)) - 2 z / a].
PlaneStresses line_contact_axis(double z, double a, double p0);

}  // namespace dc::closed_form
