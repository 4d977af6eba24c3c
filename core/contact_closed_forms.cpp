#include "contact_closed_forms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dc::closed_form {
namespace {

constexpr double kPi = std::numbers::pi;

void check_ratio(double ratio, const char* who, double lo = 0.0) {
  if (!(ratio >= lo && ratio <= 1.0))
    throw std::domain_error(std::string(who) + ": force ratio must lie in [" + std::to_string(lo) +
                            ", 1], got " + std::to_string(ratio));
}

void check_positive(double v, const char* who, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::domain_error(std::string(who) + ": " + what + " must be positive and finite");
}

/// sqrt(max(0, 1 - s^2)).
double root1m(double s) { return std::sqrt(std::max(0.0, 1.0 - s * s)); }

/// Arithmetic-geometric mean of 1 and t (0 < t <= 1): K'(t) = K(sqrt(1 - t^2)) = pi/(2 AGM(1, t)),
/// accurate for small t (no 1 - t^2 cancellation).
double agm1(double t) {
  double a = 1.0, b = t;
  for (int it = 0; it < 64 && std::abs(a - b) > 4e-16 * a; ++it) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return 0.5 * (a + b);
}

/// |beta|/mu as a function of y = artanh(c/a) > 0: tanh(y) K'(tanh y) / y. Decreasing in y.
double spence_of_y(double y) {
  const double t = std::tanh(y);
  return t * (kPi / (2.0 * agm1(t))) / y;
}

/// sgn(ratio) mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - (x - centre)^2/c^2)] with the second
/// term on |x - centre| < c only, 0 outside |x| < a: the 2-D stick-slip traction of Cattaneo
/// (centre 0) and Carter (centre a - c).
double two_ellipse_traction(double x, double a, double p0, double mu, double force_ratio, double c, double centre) {
  if (std::abs(x) >= a) return 0.0;
  double q = root1m(x / a);
  if (c > 0.0 && std::abs(x - centre) < c) q -= (c / a) * root1m((x - centre) / c);
  const double sign = force_ratio < 0.0 ? -1.0 : 1.0;
  return sign * mu * p0 * q;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Cattaneo in 2-D
// ---------------------------------------------------------------------------------------------

double cattaneo_2d_stick_half_width(double a, double force_ratio) {
  check_ratio(std::abs(force_ratio), "cattaneo_2d_stick_half_width");
  return a * std::sqrt(1.0 - std::abs(force_ratio));
}

double cattaneo_2d_traction(double x, double a, double p0, double mu, double force_ratio) {
  check_ratio(std::abs(force_ratio), "cattaneo_2d_traction");
  return two_ellipse_traction(x, a, p0, mu, force_ratio, cattaneo_2d_stick_half_width(a, force_ratio), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Cattaneo-Mindlin
// ---------------------------------------------------------------------------------------------

double mindlin_stick_radius(double a, double ratio) {
  check_ratio(ratio, "mindlin_stick_radius");
  return a * std::cbrt(1.0 - ratio);
}

double mindlin_traction(double r, double a, double mu_p0, double ratio) {
  check_ratio(ratio, "mindlin_traction");
  r = std::abs(r);
  if (r >= a) return 0.0;
  const double c = mindlin_stick_radius(a, ratio);
  double q = root1m(r / a);
  if (r < c) q -= (c / a) * root1m(r / c);
  return mu_p0 * q;
}

double mindlin_shift(double mu, double P, double a, double compliance, double ratio) {
  check_ratio(ratio, "mindlin_shift");
  check_positive(a, "mindlin_shift", "contact radius");
  return 3.0 * mu * P / (16.0 * a) * compliance * (1.0 - std::pow(1.0 - ratio, 2.0 / 3.0));
}

double mindlin_unloading_shift(double mu, double P, double a, double compliance, double ratio_max,
                               double ratio) {
  check_ratio(ratio_max, "mindlin_unloading_shift");
  if (!(ratio <= ratio_max && ratio >= -ratio_max))
    throw std::domain_error("mindlin_unloading_shift: need -Q* <= Q <= Q*");
  return mindlin_shift(mu, P, a, compliance, ratio_max) -
         2.0 * mindlin_shift(mu, P, a, compliance, 0.5 * (ratio_max - ratio));
}

double mindlin_unloading_traction(double r, double a, double mu_p0, double ratio_max, double ratio) {
  check_ratio(ratio_max, "mindlin_unloading_traction");
  if (!(ratio <= ratio_max && ratio >= -ratio_max))
    throw std::domain_error("mindlin_unloading_traction: need -Q* <= Q <= Q*");
  return mindlin_traction(r, a, mu_p0, ratio_max) -
         2.0 * mindlin_traction(r, a, mu_p0, 0.5 * (ratio_max - ratio));
}

// ---------------------------------------------------------------------------------------------
// Carter
// ---------------------------------------------------------------------------------------------

double carter_stick_half_width(double a, double force_ratio) {
  check_ratio(std::abs(force_ratio), "carter_stick_half_width");
  return a * std::sqrt(1.0 - std::abs(force_ratio));
}

double carter_creepage(double a, double R, double mu, double force_ratio) {
  check_ratio(std::abs(force_ratio), "carter_creepage");
  check_positive(R, "carter_creepage", "radius");
  return mu * a / R * (1.0 - std::sqrt(1.0 - std::abs(force_ratio)));
}

double carter_force_ratio(double a, double R, double mu, double creepage) {
  check_positive(a, "carter_force_ratio", "half-width");
  check_positive(mu, "carter_force_ratio", "friction coefficient");
  const double s = std::abs(creepage) * R / (mu * a);
  if (s >= 1.0) return 1.0;
  return 1.0 - (1.0 - s) * (1.0 - s);
}

double carter_traction(double x, double a, double p0, double mu, double force_ratio) {
  check_ratio(std::abs(force_ratio), "carter_traction");
  const double ap = carter_stick_half_width(a, force_ratio);
  return two_ellipse_traction(x, a, p0, mu, force_ratio, ap, a - ap);
}

// ---------------------------------------------------------------------------------------------
// Lubkin
// ---------------------------------------------------------------------------------------------

double lubkin_stick_stiffness(double a, const MaterialPair& materials) {
  auto inv_g = [](const Elastic& m) { return m.rigid ? 0.0 : 1.0 / m.G; };
  const double sum = inv_g(materials.body) + inv_g(materials.base);
  if (!(sum > 0.0)) throw std::domain_error("lubkin_stick_stiffness: both bodies rigid");
  return 16.0 / 3.0 * a * a * a / sum;
}

double lubkin_slip_moment(double mu, double P, double a) { return 3.0 * kPi * mu * P * a / 16.0; }

// ---------------------------------------------------------------------------------------------
// Kalker
// ---------------------------------------------------------------------------------------------

KalkerCoefficients kalker_circular(double nu) {
  if (!(nu >= 0.0 && nu <= 0.5))
    throw std::domain_error("kalker_circular: Poisson's ratio outside the table [0, 0.5]");
  // Kalker (1990) / Johnson Table 8.1, a/b = 1, columns nu = 0, 0.25, 0.5.
  static constexpr std::array<double, 3> c11{3.40, 4.12, 5.20};
  static constexpr std::array<double, 3> c22{3.40, 3.67, 3.98};
  static constexpr std::array<double, 3> c23{1.33, 1.47, 1.63};
  const std::size_t i = nu < 0.25 ? 0 : 1;  // nu = 0.25 exactly -> second interval, weight 0
  const double w = (nu - 0.25 * static_cast<double>(i)) / 0.25;
  auto lerp = [&](const std::array<double, 3>& v) { return w == 0.0 ? v[i] : (1.0 - w) * v[i] + w * v[i + 1]; };
  return {lerp(c11), lerp(c22), lerp(c23)};
}

CreepForces kalker_linear_forces(double G, double c, const KalkerCoefficients& k, double xi, double eta,
                                 double phi) {
  return {-G * c * c * k.c11 * xi, -G * c * c * k.c22 * eta - G * c * c * c * k.c23 * phi};
}

// ---------------------------------------------------------------------------------------------
// Spence: the stick ratio of monotonic frictional indentation.
//
// Derivation (axisymmetric, contact radius a growing, Hertz pressure p = p0 sqrt(1 - r^2/a^2),
// p0 proportional to a; radial shear q on the body; A = sum (1-nu)/G = 2/E*):
//  * relative radial displacement due to p (point-force kernel -kappa/(4 pi) x/r^2):
//        w_p(r) = -(kappa / (2 r)) int_0^r p(s) s ds;
//  * due to an axisymmetric radial shear q (the Cerruti kernel acting on a longitudinal field
//    reduces to A/k in Fourier space), as a composition of Abel transforms:
//        g(t) = t int_t^a q(r) / sqrt(r^2 - t^2) dr,   w_q(r) = A (2/pi) (1/r) int_0^r g(t) t / sqrt(r^2 - t^2) dt
//    (checked on q = r/sqrt(c^2-r^2) -> w = A pi r/4 and q = r sqrt(c^2-r^2) by Weber-Schafheitlin);
//  * self-similarity: w(r, a) = a^2 W(r/a); a stuck point keeps its w, so W(rho) = C rho^2 on
//    the stick zone rho < lambda = c/a; on the slip zone q = mu p (directed against the slip).
// On [0, lambda] the stick condition fixes g = D t^2 + (beta/2) p0 a [t + (1 - t^2) artanh t]
// (t = r/a, beta = kappa/(2A)); on [lambda, 1] g = mu p0 a t (K(m) - E(m)), m = 1 - t^2, from
// q = mu p. q is bounded at r = c iff g is continuous at lambda (fixes D); the slip rate just
// outside has the right sign and |q| <= mu p just inside iff g' is continuous too (points pass
// from slip to stick as the zone grows, so the usual square-root term must vanish). Eliminating
// D: (g/t^2)' continuous, and with d/dt[(K - E)/t] = -K(m)/t^2,
// d/dt[(t + (1-t^2) artanh t)/t^2] = -2 artanh(t)/t^3:
//        |beta| / mu = t K'(t) / artanh(t),  t = c/a.
// Limits: t -> 1 gives beta/mu -> 0 (full stick for mu -> infinity); t -> 0 gives
// beta/mu ~ ln(4/t) (frictionless limit). Checked numerically (mpmath) against the inequalities:
// for |beta|/mu = 1.5 the root 0.7015 is feasible, while lambda -/+ 0.05 gives backward slip at
// the stick edge / |q| > mu p inside the stick zone. The 3-D solver (tests/slow_tangential_
// validation.cpp, beta = -0.02, 64^2, 24 load steps) gives c/a = 0.69-0.70 for beta/mu = 1.5
// (0.7015 here) and 0.185-0.209 for beta/mu = 3 (0.1953 here); with beta = -0.29 the coupled
// solution falls to c/a ~ 0.66 for beta/mu = 1.5 (the neglected effect of q on p).
// ---------------------------------------------------------------------------------------------

double dundurs_beta(const MaterialPair& materials) {
  const double a = materials.tangential_a();
  if (!(a > 0.0)) throw std::domain_error("dundurs_beta: both bodies rigid");
  return materials.kappa() / (2.0 * a);
}

double spence_beta_over_mu(double stick_ratio) {
  if (!(stick_ratio > 0.0 && stick_ratio < 1.0))
    throw std::domain_error("spence_beta_over_mu: stick ratio must lie in (0, 1)");
  return spence_of_y(std::atanh(stick_ratio));
}

double spence_stick_ratio(double beta_over_mu) {
  beta_over_mu = std::abs(beta_over_mu);
  if (!std::isfinite(beta_over_mu)) throw std::domain_error("spence_stick_ratio: beta/mu not finite");
  if (beta_over_mu == 0.0) return 1.0;
  // Bisection on ln y, y = artanh(c/a): y from ~4 exp(-beta/mu) (small) to ~pi/(2 beta/mu) (large).
  double lo = std::log(1e-300), hi = std::log(std::max(60.0, 4.0 * kPi / beta_over_mu));
  if (spence_of_y(std::exp(lo)) <= beta_over_mu) return std::tanh(std::exp(lo));
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (spence_of_y(std::exp(mid)) > beta_over_mu ? lo : hi) = mid;
  }
  return std::tanh(std::exp(0.5 * (lo + hi)));
}

}  // namespace dc::closed_form
