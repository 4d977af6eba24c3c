#pragma once
// The quasi-steady surface temperature of a half-space heated on its surface by a source that
// moves over it, and its influence coefficients per grid element.
//
// Frame: the grid is fixed to the contact; the half-space's surface material moves through it at
// -V along x, i.e. the heat source moves at speed V (signed) along +x relative to the material
// (rolling along +x: material enters at the leading edge x > 0 and leaves at x < 0). Steady in
// the contact's frame, the heat equation kappa lap T = dT/dt becomes
// kappa lap T + V dT/dx = 0 (Carslaw & Jaeger, Conduction of Heat in Solids, 2nd ed. 1959, 10.7;
// Jaeger 1942, Proc. R. Soc. NSW 76, 203-224). With k = V / (2 kappa) and X = x - x',
// R = sqrt(X^2 + Y^2) the offset of the field point from the source:
//   point source Q (W) on the surface:  T = Q exp(-(|k| R + k X)) / (2 pi K R)             (1)
//   line source q' (W/m) along y (2-D): T = q' exp(-k X) K0(|k X|) / (pi K)                (2)
// ((2) is (1) integrated over Y: int exp(-|k| R)/R dY = 2 K0(|k X|)). The exponent vanishes
// behind the source (X < 0 when V > 0: the hot trail) and is -2|k||X| ahead of it. V = 0 in (1)
// is the stationary source Q / (2 pi K R); (2) at V = 0 has no steady state (the temperature of
// a line source grows like log t without bound), so a 2-D grid needs V != 0.
//
// Per element (uniform flux q on the element, W/m^2): the coefficient T at an element's centre
// per unit q on element (i - di, j - dj), a KernelTable of influence.hpp.
// 3-D: the corner functions C(A, B) = int_0^A int_0^B (1) dY dX (unit Q density) combined over the
// element's four corners (as the elastic tables). In polar coordinates about the field point the
// radial integral of (1) is closed: int_0^Rm exp(-c R) dR = Rm E(c Rm), E(z) = (1 - e^-z)/z,
// c = |k| + k cos(theta); split along the diagonal into the triangle on the X side (Rm = |A| /
// cos phi) and the one on the Y side (Rm = |B| / sin phi), and with phi = atan(sinh w),
// phi = acot(sinh w) respectively,
//   C(A, B) = sgn(A) sgn(B) / (2 pi K) [ |A| int_0^asinh(|B|/|A|) E(|k||A| (cosh w + s)) dw
//                                      + |B| int_0^asinh(|A|/|B|) E(|k||B| e^(s w)) dw ],
// s = sgn(k A): both integrands smooth and bounded (the 1/R singularity is integrated exactly),
// evaluated by adaptive Gauss-Kronrod to 1e-13 relative. V = 0 (E = 1): the closed form
// |A| asinh(|B|/|A|) + |B| asinh(|A|/|B|) (Love's 1/R over a rectangle).
// 2-D: (2) over a strip has the antiderivative
//   M(u) = int_0^u e^-t K0(|t|) dt = 1 + u e^-u (K0(u) - K1(u))   (u >= 0),
//                                   1 - |u| e^|u| (K0(|u|) + K1(|u|))   (u < 0)
// (differentiate: (u e^-u (K0 - K1))' = e^-u K0 with K0' = -K1, K1' = -K0 - K1/u), so a strip
// [X1, X2] gives (M(k X2) - M(k X1)) / (pi K k): exact. M(+inf) = 1; M(u) ~ -sqrt(2 pi |u|) as
// u -> -inf.
#include <string>

#include "grid.hpp"
#include "influence.hpp"

namespace dc {

/// One body's thermal constants: conductivity K (W/(m K)) and diffusivity kappa (m^2/s).
struct ThermalProperties {
  double conductivity = 0.0;
  double diffusivity = 0.0;
  /// Validated (both > 0 and finite); errors name `key`.conductivity / `key`.diffusivity.
  static ThermalProperties make(double conductivity, double diffusivity, const std::string& key);
};

/// One surface of the contact: its thermal constants and the speed of the heat source relative
/// to it, along +x (m/s, signed: the surface moves through the contact at -speed).
struct ThermalSurface {
  ThermalProperties properties;
  double speed = 0.0;
  /// Jaeger's Peclet number V L / (2 kappa) for a length L (half-width, radius).
  double peclet(double length) const { return std::abs(speed) * length / (2.0 * properties.diffusivity); }
};

/// e^x K_nu(x) for x > 0 and nu = 0 or 1 (std::cyl_bessel_k below 30, the asymptotic series
/// of Abramowitz & Stegun 9.7.2 above, where e^x overflows long before the product).
double scaled_bessel_k(int nu, double x);

/// M(u) above: the integral of e^-t K0(|t|) from 0 to u.
double moving_line_source_integral(double u);

/// (1) per unit Q and (2) per unit q' at offset (X, Y) (2-D: Y unused); K conductivity,
/// k = V / (2 kappa). For tests and closed forms.
double moving_point_source(double conductivity, double k, double X, double Y);
double moving_line_source(double conductivity, double k, double X);

/// The corner function C(A, B) above (3-D, per unit flux density).
double moving_source_corner(double conductivity, double k, double A, double B);

/// The influence table of `surface` on `grid`: at(di, dj) = the temperature at the centre of
/// element (i, j) per unit uniform flux (W/m^2) on element (i - di, j - dj). Even in dj; even in
/// di only at speed 0. 2-D: InputError `key`.speed when the speed is 0. `key` names the surface.
KernelTable heat_influence_table(const Grid& grid, const ThermalSurface& surface, const std::string& key);

}  // namespace dc
