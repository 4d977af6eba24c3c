#include "moving_heat_source.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "adaptive_quadrature.hpp"
#include "errors.hpp"
#include "interrupt.hpp"
#include "number_text.hpp"

namespace dc {
namespace {
constexpr double kHeatPi = std::numbers::pi;

/// E(z) = (1 - e^-z) / z for z >= 0, E(0) = 1.
double heat_exp_ratio(double z) { return z < 1e-10 ? 1.0 - 0.5 * z : -std::expm1(-z) / z; }

/// The corner integral without 1/(2 pi K): the region between the field point and (A, B).
double heat_corner_integral(double k, double A, double B) {
  if (A == 0.0 || B == 0.0) return 0.0;
  const double sign = (A > 0.0) == (B > 0.0) ? 1.0 : -1.0;
  const double a = std::abs(A), b = std::abs(B);
  if (k == 0.0) return sign * (a * std::asinh(b / a) + b * std::asinh(a / b));
  const double kk = std::abs(k);
  const bool ahead = (k > 0.0) == (A > 0.0);  // s = sgn(k A) = +1: the field point ahead of the source
  // Triangle on the X side: z = |k| a (cosh w + s); cosh w - 1 = 2 sinh^2(w / 2) without cancellation.
  const auto x_side = [kk, a, ahead](double w) {
    const double h = std::sinh(0.5 * w);
    return heat_exp_ratio(kk * a * (ahead ? 2.0 + 2.0 * h * h : 2.0 * h * h));
  };
  // Triangle on the Y side: z = |k| b e^(s w).
  const auto y_side = [kk, b, ahead](double w) { return heat_exp_ratio(kk * b * std::exp(ahead ? w : -w)); };
  const QuadratureTolerance tolerance{1e-13, 0.0, 400};
  return sign * (a * integrate_adaptive(x_side, 0.0, std::asinh(b / a), tolerance) +
                 b * integrate_adaptive(y_side, 0.0, std::asinh(a / b), tolerance));
}

/// e^x K_nu(x) by its asymptotic series (A&S 9.7.2), x >= 30: the terms fall below 1e-17
/// relative well before they start to grow (the smallest is about e^-2x).
double heat_bessel_asymptotic(int nu, double x) {
  const double mu = 4.0 * nu * nu;
  double term = 1.0, sum = 1.0;
  for (int k = 1; k < 60; ++k) {
    const double odd = 2.0 * k - 1.0;
    const double next = term * (mu - odd * odd) / (k * 8.0 * x);
    if (std::abs(next) > std::abs(term)) break;
    term = next;
    sum += term;
    if (std::abs(term) < 1e-17 * std::abs(sum)) break;
  }
  return std::sqrt(kHeatPi / (2.0 * x)) * sum;
}

/// The 2-D strip table (speed != 0).
void heat_strip_table(const Grid& grid, double K, double k, KernelTable& table) {
  const double scale = 1.0 / (kHeatPi * K * k);
  for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di)
    table.at(di, 0) = scale * (moving_line_source_integral(k * (di + 0.5) * grid.dx) -
                               moving_line_source_integral(k * (di - 0.5) * grid.dx));
}

/// The 3-D table from the corner functions on the lattice A_m = (m - nx + 1/2) dx (m < 2 nx),
/// B_l = (l + 1/2) dy (l < ny); C is odd in B, so the table is even in dj.
void heat_rectangle_table(const Grid& grid, double K, double k, KernelTable& table) {
  const int nx = grid.nx, ny = grid.ny, na = 2 * nx;
  std::vector<double> corner(static_cast<std::size_t>(na) * ny);
  for (int l = 0; l < ny; ++l) {
    throw_if_interrupted();
    for (int m = 0; m < na; ++m)
      corner[m + static_cast<std::size_t>(na) * l] =
          heat_corner_integral(k, (m - nx + 0.5) * grid.dx, (l + 0.5) * grid.dy);
  }
  const double scale = 1.0 / (2.0 * kHeatPi * K);
  const auto c = [&](int m, int l) {  // l = -1: B = -dy/2
    return l < 0 ? -corner[m] : corner[m + static_cast<std::size_t>(na) * l];
  };
  for (int dj = 0; dj < ny; ++dj)
    for (int di = -(nx - 1); di <= nx - 1; ++di) {
      const int lo = di + nx - 1, hi = di + nx;
      const double v = scale * ((c(hi, dj) - c(lo, dj)) - (c(hi, dj - 1) - c(lo, dj - 1)));
      table.at(di, dj) = v;
      table.at(di, -dj) = v;
    }
}
}  // namespace

ThermalProperties ThermalProperties::make(double conductivity, double diffusivity, const std::string& key) {
  if (!std::isfinite(conductivity) || conductivity <= 0.0)
    throw InputError(key + ".conductivity", "the thermal conductivity must be positive and finite, got " +
                                                six_digits(conductivity) + " W/(m K)");
  if (!std::isfinite(diffusivity) || diffusivity <= 0.0)
    throw InputError(key + ".diffusivity", "the thermal diffusivity must be positive and finite, got " +
                                               six_digits(diffusivity) + " m^2/s");
  return {conductivity, diffusivity};
}

double scaled_bessel_k(int nu, double x) {
  if (x < 30.0) return std::exp(x) * std::cyl_bessel_k(static_cast<double>(nu), x);
  return heat_bessel_asymptotic(nu, x);
}

double moving_line_source_integral(double u) {
  if (u == 0.0) return 0.0;
  if (u > 0.0) {
    // e^-u K(u) = e^-2u (e^u K(u)); the bracket tends to 0 like -1/(2u) times K0's scale.
    return 1.0 + u * std::exp(-2.0 * u) * (scaled_bessel_k(0, u) - scaled_bessel_k(1, u));
  }
  const double t = -u;
  return 1.0 - t * (scaled_bessel_k(0, t) + scaled_bessel_k(1, t));
}

double moving_point_source(double conductivity, double k, double X, double Y) {
  const double R = std::hypot(X, Y);
  return std::exp(-(std::abs(k) * R + k * X)) / (2.0 * kHeatPi * conductivity * R);
}

double moving_line_source(double conductivity, double k, double X) {
  const double t = std::abs(k * X);
  // e^-kX K0(|kX|) = e^(-kX - |kX|) (e^|kX| K0(|kX|)).
  return std::exp(-k * X - t) * scaled_bessel_k(0, t) / (kHeatPi * conductivity);
}

double moving_source_corner(double conductivity, double k, double A, double B) {
  return heat_corner_integral(k, A, B) / (2.0 * kHeatPi * conductivity);
}

KernelTable heat_influence_table(const Grid& grid, const ThermalSurface& surface, const std::string& key) {
  const ThermalProperties p = ThermalProperties::make(surface.properties.conductivity,
                                                      surface.properties.diffusivity, key);
  if (!std::isfinite(surface.speed))
    throw InputError(key + ".speed", "the speed must be finite, got " + six_digits(surface.speed));
  const double k = surface.speed / (2.0 * p.diffusivity);
  if (grid.dimension == 2 && k == 0.0)
    throw InputError(key + ".speed",
                     "a line contact (2-D) needs a moving heat source: a stationary line source has no "
                     "steady temperature");
  KernelTable table;
  table.nx = grid.nx;
  table.ny = grid.ny;
  table.values.assign(static_cast<std::size_t>(2 * grid.nx - 1) * (2 * grid.ny - 1), 0.0);
  if (grid.dimension == 2)
    heat_strip_table(grid, p.conductivity, k, table);
  else
    heat_rectangle_table(grid, p.conductivity, k, table);
  return table;
}

}  // namespace dc
