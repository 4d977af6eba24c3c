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
//  [H]  G. M. Hamilton, Explicit equations for the stresses beneath a sliding spherical contact,
//       Proc. IMechE 197C (1983) 53-59.
//  [HG] G. M. Hamilton, L. E. Goodman, The stress field created by a circular sliding contact,
//       J. Appl. Mech. 33 (1966) 371-376.
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

/// The six stresses of a 3-D point (Voigt order of voigt_stress.hpp: xx, yy, zz, yz, xz, xy).
struct SpatialStresses {
  double sigma_xx = 0.0, sigma_yy = 0.0, sigma_zz = 0.0, sigma_yz = 0.0, sigma_xz = 0.0, sigma_xy = 0.0;
};

/// Hertz's sphere with a sliding shear ([H], [HG]): all six stresses at (x, y, z), z >= 0, under
/// the pressure p0 sqrt(1 - r^2/a^2) (hertz_sphere_normal_field) and under the shear
/// q0 sqrt(1 - r^2/a^2) along +x (hertz_sphere_shear_field); full sliding q = mu p is their sum
/// with q0 = mu p0 (hamilton_sliding_sphere).
///
/// The field of the distribution is that of point loads at the complex depths z + i t, 0 <= t <= a
/// ([HG]): for a harmonic point-load kernel f(x, y, z) (Boussinesq's and Cerruti's stresses are
/// derivatives of Omega = z ln(R + z) - R, R = sqrt(r^2 + z^2), as in subsurface_influence.hpp)
///   integral over the disc of sqrt(a^2 - rho^2) f = pi Re integral_0^a (a^2 - t^2) f(x, y, z + i t) dt
/// (both sides harmonic, equal on z = 0: the Abel transform of Hertz's surface potential). With
/// Theta the third antiderivative of f in z, integration by parts gives the closed form
///   pi Re integral_0^a (a^2 - t^2) d^3 Theta / dz^3 dt = 2 pi [Im Theta(z1) - a Re Theta'(z1)],
/// z1 = z + i a, the terms at t = 0 being real. The antiderivatives of Omega in z (G_k, k >= 1) are
///   G_1 = (z^2/2 - r^2/4) L - 3 z R / 4,   G_2 = (z^3/6 - r^2 z/4) L - 11 z^2 R / 36 + r^2 R / 9,
///   G_3 = (z^4/24 - r^2 z^2/8 + r^4/64) L - 25 z^3 R / 288 + 55 r^2 z R / 576,   L = ln(R + z),
/// (G_0 = Omega, G_-1 = L, G_-2 = 1/R) evaluated at z1, where sqrt(r^2 + z1^2) = M + i N of [H]
/// (M, N = sqrt((S +- A)/2), A = r^2 + z^2 - a^2, S = sqrt(A^2 + 4 a^2 z^2)); their x and y
/// derivatives are derivatives in r^2, exact by Taylor arithmetic (no 1/r terms: the axis is a
/// regular point). [H] writes the same field in real form; its normal-load part is checked
/// against it (tests/test_subsurface_field.cpp). z = 0 is the limit from inside, except on the
/// contact's edge r = a itself.
SpatialStresses hertz_sphere_normal_field(double x, double y, double z, double a, double p0, double nu);
SpatialStresses hertz_sphere_shear_field(double x, double y, double z, double a, double q0, double nu);
SpatialStresses hamilton_sliding_sphere(double x, double y, double z, double a, double p0, double mu, double nu);

}  // namespace dc::closed_form
