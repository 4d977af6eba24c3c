#include "hertz.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace dc::hertz {
namespace {
constexpr double kPi = std::numbers::pi;

/// (K(m) - E(m)) / m, accurate also as m -> 0 (series pi/4 (1 + 3m/8 + ...)).
double k_minus_e_over_m(double m) {
  if (m < 1e-6) return kPi / 4.0 * (1.0 + 3.0 * m / 8.0);
  return (ellipk(m) - ellipe(m)) / m;
}

/// Curvature ratio B/A of an ellipse with axes a >= b, m = 1 - b^2/a^2 (Johnson 4.2).
double curvature_ratio(double m) {
  if (m < 1e-6) return 1.0 + 0.5 * m;  // both numerator and denominator ~ pi m / 4
  const double K = ellipk(m), E = ellipe(m);
  return (E / (1.0 - m) - K) / (K - E);
}
}  // namespace

double ellipk(double m) {
  if (!(m >= 0.0 && m < 1.0)) throw std::domain_error("ellipk: parameter outside [0, 1)");
  double a = 1.0, b = std::sqrt(1.0 - m);
  for (int it = 0; it < 64 && std::abs(a - b) > 4e-16 * a; ++it) {  // AGM: quadratic convergence
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return kPi / (2.0 * a);
}

double ellipe(double m) {
  if (!(m >= 0.0 && m <= 1.0)) throw std::domain_error("ellipe: parameter outside [0, 1]");
  if (m == 1.0) return 1.0;
  // E = K (1 - sum 2^(n-1) c_n^2), c_0^2 = m, c_(n+1) = (a_n - b_n)/2 (AGM).
  double a = 1.0, b = std::sqrt(1.0 - m), sum = 0.5 * m, pow2 = 0.5;
  for (int it = 0; it < 64 && std::abs(a - b) > 4e-16 * a; ++it) {
    const double cn = 0.5 * (a - b);
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
    pow2 *= 2.0;
    sum += pow2 * cn * cn;
  }
  return kPi / (2.0 * a) * (1.0 - sum);
}

SphereSolution sphere(double R, double P, double E_star) {
  const double a = std::cbrt(3.0 * P * R / (4.0 * E_star));
  return {a, a * a / R, 3.0 * P / (2.0 * kPi * a * a)};
}

ImpactSolution sphere_impact(double R, double m, double v, double E_star) {
  const double delta = std::pow(15.0 * m * v * v / (16.0 * E_star * std::sqrt(R)), 0.4);
  // Contact time 2 (delta / v) int_0^1 dx / sqrt(1 - x^(5/2)) = (4/5) B(2/5, 1/2) delta / v.
  const double factor = 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);  // 2.9432752
  return {delta, 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(delta, 1.5), factor * delta / std::abs(v)};
}

EllipticSolution elliptic(double A, double B, double P, double E_star) {
  if (!(A > 0.0 && B > 0.0)) throw std::domain_error("hertz::elliptic: curvatures must be positive");
  const bool swapped = A > B;  // the major semi-axis lies along the smaller curvature
  if (swapped) std::swap(A, B);
  const double ratio = B / A;
  double lo = 0.0, hi = 1.0 - 1e-15;
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double mid = 0.5 * (lo + hi);
    (curvature_ratio(mid) < ratio ? lo : hi) = mid;
  }
  const double m = 0.5 * (lo + hi);
  const double a = std::cbrt(3.0 * P * k_minus_e_over_m(m) / (2.0 * kPi * E_star * A));
  const double b = a * std::sqrt(1.0 - m);
  const double p0 = 3.0 * P / (2.0 * kPi * a * b);
  const double approach = p0 * b * ellipk(m) / E_star;
  if (swapped) return {b, a, approach, p0};
  return {a, b, approach, p0};
}

CylinderSolution cylinder2d(double R, double P, double E_star) {
  const double a = std::sqrt(4.0 * P * R / (kPi * E_star));
  return {a, 2.0 * P / (kPi * a)};
}

double flat_punch_force(double a, double approach, double E_star) { return 2.0 * a * E_star * approach; }

double flat_punch_pressure(double a, double P, double r) {
  if (r >= a) return 0.0;
  return P / (2.0 * kPi * a * std::sqrt(a * a - r * r));
}

}  // namespace dc::hertz
