#include "influence.hpp"
#include "interrupt.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace dc {
namespace {
constexpr double kPi = std::numbers::pi;

// ---- 3-D: antiderivatives F(x, y) with d2F/dxdy = kernel, for uniform traction on a
// rectangle (Love 1929; Johnson, Contact Mechanics, 3.5 and 3.7). Written to be finite and
// free of cancellation at every corner, including r = 0 and the negative axes.

/// y * ln(x + r), with x + r = y^2 / (r - x) for x < 0 (no cancellation); 0 when y = 0.
double y_log_x_plus_r(double x, double y) {
  if (y == 0.0) return 0.0;
  const double r = std::hypot(x, y);
  const double s = x >= 0.0 ? x + r : y * y / (r - x);
  return y * std::log(s);
}
double integral_inv_r(double x, double y) { return y_log_x_plus_r(y, x) + y_log_x_plus_r(x, y); }
double integral_xx_r3(double x, double y) { return y_log_x_plus_r(x, y); }
double integral_yy_r3(double x, double y) { return y_log_x_plus_r(y, x); }
double integral_xy_r3(double x, double y) { return -std::hypot(x, y); }
/// Integral of x / r^2: y ln r + x atan(y / x) (the corner sum removes a term linear in y).
double integral_x_r2(double x, double y) {
  const double r = std::hypot(x, y);
  const double a = (y == 0.0 || r == 0.0) ? 0.0 : y * std::log(r);
  const double b = (x == 0.0) ? 0.0 : x * std::atan(y / x);
  return a + b;
}
double integral_y_r2(double x, double y) { return integral_x_r2(y, x); }


// ---- 2-D plane strain: antiderivatives along x of the line-load kernels.
double integral_log(double x, double L) { return x == 0.0 ? 0.0 : x * std::log(std::abs(x) / L) - x; }
double integral_sign(double x) { return std::abs(x); }

int pair_code(Axis out, Axis in) { return 3 * static_cast<int>(out) + static_cast<int>(in); }

/// Antiderivative F(x, y) of the (out, in) kernel per unit traction (3-D): the element value
/// is the corner sum of F over the element's extent relative to the field point.
std::function<double(double, double)> antiderivative_3d(const MaterialPair& m, Axis out, Axis in) {
  const double a = m.tangential_a(), b = m.tangential_b(), kappa = m.kappa();
  const double normal = 1.0 / (kPi * m.E_star()), shear = 1.0 / (2.0 * kPi), cross = kappa / (4.0 * kPi);
  switch (pair_code(out, in)) {
    case 3 * kZ + kZ:  // B31: Boussinesq / Love
      return [=](double x, double y) { return normal * integral_inv_r(x, y); };
    case 3 * kX + kX:  // B22: Cerruti
      return [=](double x, double y) { return shear * (a * integral_inv_r(x, y) + b * integral_xx_r3(x, y)); };
    case 3 * kY + kY:
      return [=](double x, double y) { return shear * (a * integral_inv_r(x, y) + b * integral_yy_r3(x, y)); };
    case 3 * kX + kY:
    case 3 * kY + kX:
      return [=](double x, double y) { return shear * b * integral_xy_r3(x, y); };
    case 3 * kX + kZ:  // kappa B21: points move toward a normal load
      return [=](double x, double y) { return -cross * integral_x_r2(x, y); };
    case 3 * kY + kZ:
      return [=](double x, double y) { return -cross * integral_y_r2(x, y); };
    case 3 * kZ + kX:  // kappa B32 (Betti: the transpose of B21)
      return [=](double x, double y) { return cross * integral_x_r2(x, y); };
    case 3 * kZ + kY:
      return [=](double x, double y) { return cross * integral_y_r2(x, y); };
  }
  throw std::logic_error("influence: bad component pair");
}

/// Antiderivative along x of the (out, in) line-load kernel (2-D plane strain, per unit length).
std::function<double(double)> antiderivative_2d(const MaterialPair& m, Axis out, Axis in, double L) {
  const double log_coeff = -2.0 / (kPi * m.E_star()), cross = 0.25 * m.kappa();
  switch (pair_code(out, in)) {
    case 3 * kZ + kZ:
    case 3 * kX + kX:
      return [=](double x) { return log_coeff * integral_log(x, L); };
    case 3 * kX + kZ:  // points move toward a normal line load
      return [=](double x) { return -cross * integral_sign(x); };
    case 3 * kZ + kX:
      return [=](double x) { return cross * integral_sign(x); };
  }
  throw std::invalid_argument("influence: 2-D problems have components x and z only");
}
}  // namespace

KernelTable influence_table(const Grid& grid, const MaterialPair& materials, Axis out, Axis in,
                            const InfluenceOptions& options) {
  KernelTable t;
  t.nx = grid.nx;
  t.ny = grid.ny;
  t.values.assign(static_cast<std::size_t>(2 * grid.nx - 1) * static_cast<std::size_t>(2 * grid.ny - 1), 0.0);
  // Corner abscissae (k - 0.5) dx, k = -(n-1)..n: each antiderivative is evaluated once per
  // corner and shared by the four elements meeting there.
  const int cx = 2 * grid.nx, cy = grid.dimension == 2 ? 1 : 2 * grid.ny;
  if (grid.dimension == 2) {
    const double L = options.reference_length > 0.0 ? options.reference_length : grid.nx * grid.dx;
    const auto F = antiderivative_2d(materials, out, in, L);
    std::vector<double> corner(static_cast<std::size_t>(cx));
    for (int k = 0; k < cx; ++k) corner[k] = F((k - grid.nx + 0.5) * grid.dx);
    for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di)
      t.at(di, 0) = corner[di + grid.nx] - corner[di + grid.nx - 1];
    return t;
  }
  const auto F = antiderivative_3d(materials, out, in);
  std::vector<double> corner(static_cast<std::size_t>(cx) * static_cast<std::size_t>(cy));
  for (int l = 0; l < cy; ++l) {
    throw_if_interrupted();  // large grids take seconds here
    for (int k = 0; k < cx; ++k)
      corner[k + static_cast<std::size_t>(cx) * l] =
          F((k - grid.nx + 0.5) * grid.dx, (l - grid.ny + 0.5) * grid.dy);
  }
  auto at = [&](int k, int l) { return corner[k + static_cast<std::size_t>(cx) * l]; };
  for (int dj = -(grid.ny - 1); dj <= grid.ny - 1; ++dj) {
    const int l = dj + grid.ny;
    for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di) {
      const int k = di + grid.nx;
      t.at(di, dj) = at(k, l) - at(k - 1, l) - at(k, l - 1) + at(k - 1, l - 1);
    }
  }
  return t;
}

double point_load_kernel(int dimension, const MaterialPair& m, Axis out, Axis in, double x, double y,
                         double reference_length) {
  const double kappa = m.kappa();
  if (dimension == 2) {
    const double s = x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
    switch (pair_code(out, in)) {
      case 3 * kZ + kZ:
      case 3 * kX + kX: return -2.0 / (kPi * m.E_star()) * std::log(std::abs(x) / reference_length);
      case 3 * kX + kZ: return -0.25 * kappa * s;
      case 3 * kZ + kX: return 0.25 * kappa * s;
    }
    throw std::invalid_argument("point_load_kernel: 2-D has components x and z only");
  }
  const double r = std::hypot(x, y), r2 = r * r, r3 = r2 * r;
  const double a = m.tangential_a(), b = m.tangential_b();
  switch (pair_code(out, in)) {
    case 3 * kZ + kZ: return 1.0 / (kPi * m.E_star() * r);
    case 3 * kX + kX: return (a / r + b * x * x / r3) / (2.0 * kPi);
    case 3 * kY + kY: return (a / r + b * y * y / r3) / (2.0 * kPi);
    case 3 * kX + kY:
    case 3 * kY + kX: return b * x * y / r3 / (2.0 * kPi);
    case 3 * kX + kZ: return -kappa * x / r2 / (4.0 * kPi);
    case 3 * kY + kZ: return -kappa * y / r2 / (4.0 * kPi);
    case 3 * kZ + kX: return kappa * x / r2 / (4.0 * kPi);
    case 3 * kZ + kY: return kappa * y / r2 / (4.0 * kPi);
  }
  throw std::logic_error("point_load_kernel: bad component pair");
}

}  // namespace dc
