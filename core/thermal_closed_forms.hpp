#pragma once
// Closed forms of the flash temperature of one half-space under a moving heat source
// (moving_heat_source.hpp's frame: the source moves at V along +x over the surface; k = V/(2 kappa);
// Jaeger's Peclet number Pe = V L / (2 kappa) with L the half-width or radius). Temperatures
// are dimensionless: T K / (q L) for a uniform flux q, T K / (q0 L) for a Hertzian flux of peak q0.
//
// Uniform band |x| <= b (2-D, line contact), the exact quasi-steady temperature (Jaeger 1942,
// Proc. R. Soc. NSW 76, 203-224: the moving line source (2) integrated over the band; the
// integral is closed with M(u) of moving_heat_source.hpp):
//   theta(xi) = [M(Pe (xi + 1)) - M(Pe (xi - 1))] / (pi Pe),   xi = x / b.                  (B1)
// Its mean over the band by quadrature of (B1), its maximum by a golden-section search.
// Low Pe (K0(z) = -ln(z/2) - gamma + O(z^2 ln z), e^-u = 1 - u + ..., the odd term vanishing at
// the centre and in the mean):
//   theta(0) -> (2/pi) (1 + ln 2 - gamma - ln Pe),   mean -> (2/pi) (3/2 - gamma - ln Pe)    (B2)
// (int_-1^1 ln|xi'| dxi' = -2, (1/2) int int ln|xi - xi'| = 2 ln 2 - 3 over the band).
// High Pe, each point of the surface heated as a 1-D semi-infinite solid for its time
// (b - x)/V under the source (Jaeger 1942; Carslaw & Jaeger 2.9 (5)):
//   theta(xi) -> 2 sqrt((1 - xi) / (2 pi Pe)),  max 2 / sqrt(pi Pe) at xi = -1,
//   mean 4 / (3 sqrt(pi Pe))  (Jaeger's 1.596 and 1.064 in units q b / (K sqrt(V b / kappa))). (B3)
//
// Uniform square |x|, |y| <= a (3-D), stationary (Pe = 0), from Love's 1/R over a rectangle:
//   centre (4/pi) asinh(1) = 1.1222,  mean (1/pi) [4 asinh(1) - (4/3)(sqrt 2 - 1)] = 0.94640 (S1)
// (the mean is the unit square's int int int int dA dA'/|r - r'| = 4 asinh(1) + (4/3)(1 - sqrt 2);
// Tian & Kennedy 1994, J. Tribol. 116, 167-174, quote 1.122 and 0.946).
// Uniform circle r <= a, stationary: centre 1 (int 1/R over the disc = 2 pi a), mean 8/(3 pi). (C1)
// Low Pe, any uniform source of area S (the kernel's first-order term -k, the odd -k X / R
// dropping out of the centre of a symmetric source and of every mean):
//   theta(Pe) = theta(0) - Pe S / (2 pi L^2) + O(Pe^2):  square -(2/pi) Pe, circle -Pe/2.   (L1)
// High Pe (the 1-D limit as (B3) along each chord of length 2c(y), c = sqrt(a^2 - y^2) for the
// circle, c = a for the square): max 2 / sqrt(pi Pe) at the trailing edge of the widest chord;
// mean over the square 4 / (3 sqrt(pi Pe)); over the circle
//   (8 / (3 pi sqrt(pi))) B(1/2, 7/4) / sqrt(Pe) = 0.68855 / sqrt(Pe)                         (C2)
// (int (2c)^(3/2) dy = 2^(3/2) a^(5/2) B(1/2, 7/4); Archard 1958, Wear 2, 438-455, writes the
// mean as 0.31 Q/(a K) sqrt(kappa/(V a)) with Q = pi a^2 q: 0.68855 sqrt(2)/pi = 0.30997).
// These limits drop conduction along the surface: their relative error is O(Pe^-1/2) for the
// square's and the circle's means (the lateral edges) and about 1/Pe on the centre line (the
// band's maximum: 3.6e-3 at Pe = 100, 4.8e-4 at Pe = 1000).
//
// Hertzian flux q = q0 sqrt(1 - x^2/b^2) on the band (Blok 1937, Proc. Gen. Discussion on
// Lubrication 2, 222-235; Blok's flash temperature of a Hertzian line contact), high Pe:
//   theta(xi) = I(xi) / sqrt(2 pi Pe),   I(xi) = int_xi^1 sqrt(1 - s^2) / sqrt(s - xi) ds,      (H1)
// evaluated with s = xi + t^2 (a smooth integrand); its maximum, found here, is 0.87301 q0 b /
// (K sqrt(Pe)) at xi = -0.65223: with the mean flux qm = pi q0 / 4 that is 1.1115 qm b /
// (K sqrt(Pe)), Blok's 1.11. The exact finite-Pe temperature of the Hertzian flux:
//   theta(xi) = (1/pi) int_-1^1 sqrt(1 - s^2) e^(-Pe (xi - s)) K0(Pe |xi - s|) ds,          (H2)
// by adaptive quadrature split at the logarithmic singularity s = xi.
// Hertzian flux q0 sqrt(1 - r^2/a^2) on the circle, high Pe: each chord y is (H1) with its half
// length c = sqrt(a^2 - y^2) and peak q0 c / a, so the maximum is (H1)'s on the central chord,
// 0.87301 q0 a / (K sqrt(Pe)), and the mean over the disc is
//   B(1/2, 9/4) J / (pi sqrt(2 pi)) / sqrt(Pe) = 0.47836 / sqrt(Pe),  J = int_-1^1 I = 32 sqrt(2)/15 (H3)
// (int c^(5/2) dy = a^(7/2) B(1/2, 9/4); int_-1^1 I(xi) dxi = 2 int_-1^1 sqrt(1 - s^2) sqrt(1 + s) ds).
// In Archard's form with the heat Q = (2/3) pi a^2 q0: 0.323 Q / (a K) sqrt(kappa / (V a)).
//
// Transient, a flux q switched on at t = 0 over a stationary source (Carslaw & Jaeger 1959,
// 2.9 (5) and 10.5 (7)), with tau = sqrt(kappa t) / L:
//   1-D (a uniform flux over the whole surface, or any point of a high-Pe source heated for
//   the time t): theta = 2 tau / sqrt(pi)                                                   (T1)
//   the centre of a uniform circle of radius a:
//   theta = 2 tau [1/sqrt(pi) - ierfc(1/(2 tau))],  ierfc(x) = e^(-x^2)/sqrt(pi) - x erfc(x),  (T2)
//   rising as (T1) while tau << 1 and to (C1)'s 1 as tau -> infinity (ierfc(x) = 1/sqrt(pi) - x
//   + O(x^2)).

namespace dc::thermal {

/// Uniform band: (B1) and its mean and maximum over |xi| <= 1 (Pe > 0).
double band_temperature(double xi, double peclet);
double band_mean(double peclet);
double band_max(double peclet);
/// (B2) low Pe: the centre and the mean.
double band_centre_low_peclet(double peclet);
double band_mean_low_peclet(double peclet);
/// (B3) high Pe: the maximum (trailing edge) and the mean; the same for a square (1-D limit).
double one_dimensional_max(double peclet);
double one_dimensional_mean(double peclet);

/// (S1), (C1): stationary square (half-side a) and circle (radius a).
double square_centre_stationary();
double square_mean_stationary();
double circle_centre_stationary();
double circle_mean_stationary();
/// (T1) and (T2) at tau = sqrt(kappa t) / L (units q L / K).
double one_dimensional_transient(double tau);
double circle_centre_transient(double tau);
/// (L1): the first-order slope d theta / d Pe at Pe = 0 of the centre and the mean.
double square_low_peclet_slope();
double circle_low_peclet_slope();
/// (C2): the circle's mean at high Pe.
double circle_mean_high_peclet(double peclet);

/// (H1): Blok's high-Pe profile of the Hertzian flux, I(xi) / sqrt(2 pi Pe), in units q0 b / K.
double hertz_line_high_peclet(double xi, double peclet);
/// The maximum of I(xi) / sqrt(2 pi) over xi (0.87301) and where it is (-0.65223).
struct BlokMaximum {
  double coefficient = 0.0;  ///< theta_max sqrt(Pe), units q0 b / K
  double xi = 0.0;
};
BlokMaximum blok_line_maximum();
/// (H3): the mean over the disc of the Hertzian flux at high Pe, units q0 a / K.
double hertz_circle_mean_high_peclet(double peclet);
/// (H2): the exact temperature of the Hertzian flux at finite Pe, units q0 b / K.
double hertz_line_temperature(double xi, double peclet);

}  // namespace dc::thermal
