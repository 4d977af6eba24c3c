#include "thermal_closed_forms.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "adaptive_quadrature.hpp"
#include "moving_heat_source.hpp"

namespace dc::thermal {
namespace {
constexpr double kThermalPi = std::numbers::pi;
constexpr double kEulerGamma = std::numbers::egamma;

/// The maximum of a unimodal f on [lo, hi] by golden-section search to 1e-10 of the interval.
template <class F>
double thermal_golden_max(const F& f, double lo, double hi, double& where) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi, c = b - r * (b - a), d = a + r * (b - a);
  double fc = f(c), fd = f(d);
  while (b - a > 1e-10 * (hi - lo)) {
    if (fc > fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - r * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + r * (b - a);
      fd = f(d);
    }
  }
  where = 0.5 * (a + b);
  double best = f(where);
  // The ends (a maximum on the boundary).
  const double f_lo = f(lo), f_hi = f(hi);
  if (f_lo > best) {
    best = f_lo;
    where = lo;
  }
  if (f_hi > best) {
    best = f_hi;
    where = hi;
  }
  return best;
}
}  // namespace

double band_temperature(double xi, double peclet) {
  return (moving_line_source_integral(peclet * (xi + 1.0)) - moving_line_source_integral(peclet * (xi - 1.0))) /
         (kThermalPi * peclet);
}

double band_mean(double peclet) {
  const auto f = [peclet](double xi) { return band_temperature(xi, peclet); };
  return 0.5 * integrate_adaptive(f, -1.0, 1.0, {1e-12, 0.0, 400});
}

double band_max(double peclet) {
  double where = 0.0;
  return thermal_golden_max([peclet](double xi) { return band_temperature(xi, peclet); }, -1.0, 1.0, where);
}

double band_centre_low_peclet(double peclet) {
  return (2.0 / kThermalPi) * (1.0 + std::log(2.0) - kEulerGamma - std::log(peclet));
}

double band_mean_low_peclet(double peclet) { return (2.0 / kThermalPi) * (1.5 - kEulerGamma - std::log(peclet)); }

double one_dimensional_max(double peclet) { return 2.0 / std::sqrt(kThermalPi * peclet); }

double one_dimensional_mean(double peclet) { return 4.0 / (3.0 * std::sqrt(kThermalPi * peclet)); }

double square_centre_stationary() { return (4.0 / kThermalPi) * std::asinh(1.0); }

double square_mean_stationary() {
  return (4.0 * std::asinh(1.0) - (4.0 / 3.0) * (std::numbers::sqrt2 - 1.0)) / kThermalPi;
}

double circle_centre_stationary() { return 1.0; }

double circle_mean_stationary() { return 8.0 / (3.0 * kThermalPi); }

double one_dimensional_transient(double tau) { return 2.0 * tau / std::sqrt(kThermalPi); }

double circle_centre_transient(double tau) {
  const double x = 0.5 / tau;
  const double ierfc = std::exp(-x * x) / std::sqrt(kThermalPi) - x * std::erfc(x);
  return 2.0 * tau * (1.0 / std::sqrt(kThermalPi) - ierfc);
}

double square_low_peclet_slope() { return -2.0 / kThermalPi; }

double circle_low_peclet_slope() { return -0.5; }

double circle_mean_high_peclet(double peclet) {
  // B(1/2, 7/4) = Gamma(1/2) Gamma(7/4) / Gamma(9/4).
  const double beta = std::sqrt(kThermalPi) * std::tgamma(1.75) / std::tgamma(2.25);
  return 8.0 / (3.0 * kThermalPi * std::sqrt(kThermalPi)) * beta / std::sqrt(peclet);
}

double hertz_line_high_peclet(double xi, double peclet) {
  if (xi >= 1.0) return 0.0;
  // s = xi + t^2: I = 2 int_0^sqrt(1 - xi) sqrt(1 - s^2) dt; below xi = -1 the flux starts at
  // s = -1 (t0 = sqrt(-1 - xi)).
  const double t0 = xi < -1.0 ? std::sqrt(-1.0 - xi) : 0.0;
  const auto f = [xi](double t) {
    const double s = xi + t * t;
    return 2.0 * std::sqrt(std::max(0.0, (1.0 - s) * (1.0 + s)));
  };
  return integrate_adaptive(f, t0, std::sqrt(1.0 - xi), {1e-13, 0.0, 400}) / std::sqrt(2.0 * kThermalPi * peclet);
}

BlokMaximum blok_line_maximum() {
  BlokMaximum m;
  m.coefficient = thermal_golden_max([](double xi) { return hertz_line_high_peclet(xi, 1.0); }, -1.0, 1.0, m.xi);
  return m;
}

double hertz_circle_mean_high_peclet(double peclet) {
  const double beta = std::sqrt(kThermalPi) * std::tgamma(2.25) / std::tgamma(2.75);  // B(1/2, 9/4)
  const double J = 32.0 * std::numbers::sqrt2 / 15.0;
  return beta * J / (kThermalPi * std::sqrt(2.0 * kThermalPi)) / std::sqrt(peclet);
}

double hertz_line_temperature(double xi, double peclet) {
  const auto f = [xi, peclet](double s) {
    const double d = xi - s;
    if (d == 0.0) return 0.0;  // the integrable logarithm's point itself (never a node of the rule)
    return std::sqrt(std::max(0.0, (1.0 - s) * (1.0 + s))) * moving_line_source(1.0, peclet, d) * kThermalPi;
  };
  const QuadratureTolerance tol{1e-12, 0.0, 600};
  double sum = 0.0;
  const double split = std::clamp(xi, -1.0, 1.0);
  sum += integrate_adaptive(f, -1.0, split, tol);
  sum += integrate_adaptive(f, split, 1.0, tol);
  return sum / kThermalPi;
}

}  // namespace dc::thermal
