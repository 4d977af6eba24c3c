// The closed-form field of one element (core/subsurface_influence) against an adaptive
// quadrature of the point-load (Boussinesq, Cerruti: Johnson, Contact Mechanics, 3.2-3.3) and
// line-load (Flamant: [J] 2.15, 2.19) solutions, against the surface influence tables at
// depth 0, and the 2-D strip against a long 3-D rectangle (plane strain).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "influence.hpp"
#include "material.hpp"
#include "subsurface_influence.hpp"

namespace subsurface_influence_tests {
using dc::Elastic;
using dc::FieldValues;
constexpr double kPi = std::numbers::pi;

/// Forward-mode dual number with a 3-gradient: the point-load stresses from the displacements.
struct Dual {
  double v = 0.0;
  double g[3] = {0.0, 0.0, 0.0};
};
Dual cst(double c) { return Dual{c, {0, 0, 0}}; }
Dual var(double v, int i) {
  Dual d{v, {0, 0, 0}};
  d.g[i] = 1.0;
  return d;
}
Dual operator+(Dual a, const Dual& b) {
  a.v += b.v;
  for (int i = 0; i < 3; ++i) a.g[i] += b.g[i];
  return a;
}
Dual operator-(Dual a, const Dual& b) {
  a.v -= b.v;
  for (int i = 0; i < 3; ++i) a.g[i] -= b.g[i];
  return a;
}
Dual operator*(const Dual& a, const Dual& b) {
  Dual r{a.v * b.v, {}};
  for (int i = 0; i < 3; ++i) r.g[i] = a.g[i] * b.v + a.v * b.g[i];
  return r;
}
Dual operator/(const Dual& a, const Dual& b) {
  Dual r{a.v / b.v, {}};
  for (int i = 0; i < 3; ++i) r.g[i] = (a.g[i] * b.v - a.v * b.g[i]) / (b.v * b.v);
  return r;
}
Dual operator*(double c, Dual a) {
  a.v *= c;
  for (double& g : a.g) g *= c;
  return a;
}
Dual sqrt(const Dual& a) {
  Dual r{std::sqrt(a.v), {}};
  for (int i = 0; i < 3; ++i) r.g[i] = a.g[i] / (2.0 * r.v);
  return r;
}
Dual log(const Dual& a) {
  Dual r{std::log(a.v), {}};
  for (int i = 0; i < 3; ++i) r.g[i] = a.g[i] / a.v;
  return r;
}
Dual atan(const Dual& a) {
  Dual r{std::atan(a.v), {}};
  for (int i = 0; i < 3; ++i) r.g[i] = a.g[i] / (1.0 + a.v * a.v);
  return r;
}

/// Hooke: the nine field values from displacements with gradients (3-D; 2-D plane strain has
/// no y-dependence and u_y = 0, so the same formula holds).
FieldValues field_from(const Dual u[3], double G, double nu) {
  const double lambda = 2.0 * G * nu / (1.0 - 2.0 * nu);
  const double tr = u[0].g[0] + u[1].g[1] + u[2].g[2];
  FieldValues f{};
  f[dc::kUx] = u[0].v;
  f[dc::kUy] = u[1].v;
  f[dc::kUz] = u[2].v;
  f[dc::kSxx] = lambda * tr + 2.0 * G * u[0].g[0];
  f[dc::kSyy] = lambda * tr + 2.0 * G * u[1].g[1];
  f[dc::kSzz] = lambda * tr + 2.0 * G * u[2].g[2];
  f[dc::kSxy] = G * (u[0].g[1] + u[1].g[0]);
  f[dc::kSxz] = G * (u[0].g[2] + u[2].g[0]);
  f[dc::kSyz] = G * (u[1].g[2] + u[2].g[1]);
  return f;
}

/// Unit point load at the origin of the half-space (depth z > 0): load 2 = normal (Boussinesq,
/// [J] 3.19), 0 = Q_x, 1 = Q_y (Cerruti, [J] 3.33), all in the half-space frame.
FieldValues point_load(int load, double G, double nu, double x, double y, double z) {
  Dual X = var(x, 0), Y = var(y, 1), Z = var(z, 2);
  if (load == 1) std::swap(X, Y);
  const Dual rho = sqrt(X * X + Y * Y + Z * Z), rz = rho + Z, r3 = rho * rho * rho;
  const double c = 1.0 / (4.0 * kPi * G), m = 1.0 - 2.0 * nu;
  Dual u[3];
  if (load == 2) {
    u[0] = c * (X * Z / r3 - m * X / (rho * rz));
    u[1] = c * (Y * Z / r3 - m * Y / (rho * rz));
    u[2] = c * (Z * Z / r3 + 2.0 * (1.0 - nu) * (cst(1.0) / rho));
  } else {
    u[0] = c * (cst(1.0) / rho + X * X / r3 + m * (cst(1.0) / rz - X * X / (rho * rz * rz)));
    u[1] = c * (X * Y / r3 - m * X * Y / (rho * rz * rz));
    u[2] = c * (X * Z / r3 + m * X / (rho * rz));
    if (load == 1) std::swap(u[0], u[1]);
  }
  return field_from(u, G, nu);  // the duals keep their own axes: no exchange back
}

/// Unit line load (plane strain) at x = 0: load 2 normal, 0 tangential (Flamant, [J] 2.15-2.19;
/// the displacements with logarithms vanishing at distance L).
FieldValues line_load(int load, double G, double nu, double x, double z, double L) {
  const Dual X = var(x, 0), Z = var(z, 2);
  const Dual r2 = X * X + Z * Z;
  const double c = 1.0 / (2.0 * kPi * G);
  Dual u[3];
  if (load == 2) {
    u[0] = -c * ((1.0 - 2.0 * nu) * atan(X / Z) - X * Z / r2);
    u[2] = -c * ((1.0 - nu) * log(r2 / cst(L * L)) - Z * Z / r2);
  } else {
    u[0] = -c * ((1.0 - nu) * log(r2 / cst(L * L)) + Z * Z / r2);
    u[2] = c * ((1.0 - 2.0 * nu) * atan(X / Z) + X * Z / r2);
  }
  return field_from(u, G, nu);
}

/// Adaptive Gauss-Kronrod (7-15) on [a, b] of a vector-valued integrand.
using Integrand = std::function<FieldValues(double)>;
void add_scaled(FieldValues& s, const FieldValues& v, double w) {
  for (int c = 0; c < dc::kFieldComponents; ++c) s[c] += w * v[c];
}
FieldValues gauss_kronrod(const Integrand& f, double a, double b, double abs_tol, int level = 0) {
  static const double xk[8] = {0.991455371120812639, 0.949107912342758525, 0.864864423359769073,
                               0.741531185599394440, 0.586087235467691130, 0.405845151377397167,
                               0.207784955007898468, 0.0};
  static const double wk[8] = {0.022935322010529225, 0.063092092629978553, 0.104790010322250184,
                               0.140653259715525919, 0.169004726639267903, 0.190350578064785410,
                               0.204432940075298892, 0.209482141084727828};
  static const double wg[4] = {0.129484966168869693, 0.279705391489276668, 0.381830050505118945,
                               0.417959183673469388};
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  FieldValues kron{}, gauss{};
  for (int i = 0; i < 8; ++i) {
    const FieldValues f1 = f(mid + half * xk[i]);
    if (i == 7) {
      add_scaled(kron, f1, wk[i]);
      add_scaled(gauss, f1, wg[3]);
      break;
    }
    const FieldValues f2 = f(mid - half * xk[i]);
    add_scaled(kron, f1, wk[i]);
    add_scaled(kron, f2, wk[i]);
    if (i % 2 == 1) {
      add_scaled(gauss, f1, wg[i / 2]);
      add_scaled(gauss, f2, wg[i / 2]);
    }
  }
  double err = 0.0;
  for (int c = 0; c < dc::kFieldComponents; ++c) err = std::max(err, std::abs(kron[c] - gauss[c]) * half);
  if (err <= abs_tol || level > 30) {
    for (double& v : kron) v *= half;
    return kron;
  }
  FieldValues left = gauss_kronrod(f, a, mid, 0.5 * abs_tol, level + 1);
  add_scaled(left, gauss_kronrod(f, mid, b, 0.5 * abs_tol, level + 1), 1.0);
  return left;
}
/// The interval split at the point where the integrand peaks (when inside).
FieldValues integrate(const Integrand& f, double a, double b, double peak, double abs_tol) {
  if (peak <= a || peak >= b) return gauss_kronrod(f, a, b, abs_tol);
  FieldValues s = gauss_kronrod(f, a, peak, 0.5 * abs_tol);
  add_scaled(s, gauss_kronrod(f, peak, b, 0.5 * abs_tol), 1.0);
  return s;
}

double largest(const FieldValues& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

struct Probe {
  double x, y, d;
};
const Probe kProbes[] = {{0.0, 0.0, 0.3},   {0.13, -0.07, 0.05}, {0.5, 0.25, 0.2},  {-0.5, 0.1, 0.02},
                         {1.3, -0.9, 0.4},  {-0.2, 0.45, 1.7},   {3.0, 2.0, 0.1},   {0.35, -0.5, 0.6}};

TEST(SubsurfaceInfluence, RectangleMatchesPointLoadQuadrature) {
  const Elastic m = Elastic::from_G_nu(2.0, 0.27);
  const double dx = 1.0, dy = 0.6;
  double worst = 0.0;
  for (const Probe& q : kProbes) {
    const dc::UnitFields exact = dc::rectangle_unit_fields(m, dx, dy, q.x, q.y, q.d);
    const FieldValues* fields[3] = {&exact.shear_x, &exact.shear_y, &exact.pressure};
    for (int load = 0; load < 3; ++load) {
      const double scale = largest(*fields[load]);
      const Integrand inner_x = [&](double xi) {
        const Integrand along_y = [&](double eta) { return point_load(load, m.G, m.nu, q.x - xi, q.y - eta, q.d); };
        return integrate(along_y, -0.5 * dy, 0.5 * dy, q.y, 1e-11 * scale);
      };
      const FieldValues numeric = integrate(inner_x, -0.5 * dx, 0.5 * dx, q.x, 1e-10 * scale);
      for (int c = 0; c < dc::kFieldComponents; ++c) {
        const double err = std::abs(numeric[c] - (*fields[load])[c]) / scale;
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-8) << "load " << load << " component " << c << " at (" << q.x << ", " << q.y << ", "
                             << q.d << "): quadrature " << numeric[c] << ", closed form " << (*fields[load])[c];
      }
    }
  }
  std::printf("[ info ] rectangle vs point-load quadrature: largest error %.2e of the largest component\n", worst);
}

TEST(SubsurfaceInfluence, StripMatchesLineLoadQuadrature) {
  const Elastic m = Elastic::from_G_nu(0.7, 0.31);
  const double dx = 0.8, L = 11.0;
  double worst = 0.0;
  for (const Probe& q : kProbes) {
    const dc::UnitFields exact = dc::strip_unit_fields(m, dx, q.x, q.d, L);
    const FieldValues* fields[3] = {&exact.shear_x, nullptr, &exact.pressure};
    for (int load : {0, 2}) {
      const double scale = largest(*fields[load]);
      const Integrand f = [&](double xi) { return line_load(load, m.G, m.nu, q.x - xi, q.d, L); };
      FieldValues numeric = integrate(f, -0.5 * dx, 0.5 * dx, q.x, 1e-14 * scale);
      numeric[dc::kSyy] = m.nu * (numeric[dc::kSxx] + numeric[dc::kSzz]);  // plane strain
      for (int c = 0; c < dc::kFieldComponents; ++c) {
        const double err = std::abs(numeric[c] - (*fields[load])[c]) / scale;
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-8) << "load " << load << " component " << c << " at (" << q.x << ", " << q.d
                             << "): quadrature " << numeric[c] << ", closed form " << (*fields[load])[c];
      }
    }
  }
  std::printf("[ info ] strip vs line-load quadrature: largest error %.2e of the largest component\n", worst);
}

// Flamant's line loads are the y-integral of Boussinesq's and Cerruti's point loads: the strip's
// stresses equal those of a rectangle of length 2e6 dx at y = 0 (the ends' share falls as
// dx / length: 1.3e-7 of the unit traction here).
TEST(SubsurfaceInfluence, StripIsTheLongRectangle) {
  const Elastic m = Elastic::from_G_nu(1.0, 0.3);
  const double dx = 1.0, length = 2e6;
  for (const Probe& q : kProbes) {
    const dc::UnitFields strip = dc::strip_unit_fields(m, dx, q.x, q.d, 10.0);
    const dc::UnitFields rect = dc::rectangle_unit_fields(m, dx, length, q.x, 0.0, q.d);
    for (int c : {dc::kSxx, dc::kSyy, dc::kSzz, dc::kSxz}) {
      EXPECT_NEAR(rect.pressure[c], strip.pressure[c], 3e-7) << c << " at " << q.x << ", " << q.d;
      EXPECT_NEAR(rect.shear_x[c], strip.shear_x[c], 3e-7) << c << " at " << q.x << ", " << q.d;
    }
    for (int c : {dc::kSxy, dc::kSyz}) {
      EXPECT_NEAR(rect.pressure[c], 0.0, 3e-7);
      EXPECT_NEAR(rect.shear_x[c], 0.0, 3e-7);
    }
  }
}

// Depth 0: the two bodies' displacements give the relative surface displacement of
// influence.hpp's tables (Love, Cerruti and the kappa cross terms), 3-D and 2-D.
TEST(SubsurfaceInfluence, SurfaceDisplacementsAreTheInfluenceTables) {
  const Elastic body = Elastic::from_G_nu(1.3, 0.22), base = Elastic::from_G_nu(0.8, 0.35);
  const dc::MaterialPair pair{body, base};
  for (int dim : {3, 2}) {
    const dc::Grid grid = dim == 3 ? dc::Grid::make(3, 5, 4, -1.0, 1.5, -0.4, 0.8)
                                   : dc::Grid::make(2, 7, 1, -1.0, 2.5, 0.0, 1.0);
    const double L = grid.nx * grid.dx;
    const dc::Axis axes[3] = {dc::kX, dc::kY, dc::kZ};
    const int out_component[3] = {dc::kUx, dc::kUy, dc::kUz};
    for (dc::Axis out : axes)
      for (dc::Axis in : axes) {
        if (dim == 2 && (out == dc::kY || in == dc::kY)) continue;
        const dc::KernelTable t = dc::influence_table(grid, pair, out, in);
        double scale = 0.0;
        for (double v : t.values) scale = std::max(scale, std::abs(v));
        for (int dj = -(grid.ny - 1); dj <= grid.ny - 1; ++dj)
          for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di) {
            const double x = di * grid.dx, y = dj * grid.dy;
            const double t_in[3] = {in == dc::kX ? 1.0 : 0.0, in == dc::kY ? 1.0 : 0.0, in == dc::kZ ? 1.0 : 0.0};
            const FieldValues up = dim == 3 ? dc::rectangle_field(body, dc::BodySide::body, grid.dx, grid.dy, t_in[0],
                                                                  t_in[1], t_in[2], x, y, 0.0)
                                            : dc::strip_field(body, dc::BodySide::body, grid.dx, t_in[0], t_in[2], x,
                                                              0.0, L);
            const FieldValues down = dim == 3 ? dc::rectangle_field(base, dc::BodySide::base, grid.dx, grid.dy,
                                                                    t_in[0], t_in[1], t_in[2], x, y, 0.0)
                                              : dc::strip_field(base, dc::BodySide::base, grid.dx, t_in[0], t_in[2],
                                                                x, 0.0, L);
            const double w = up[out_component[out]] - down[out_component[out]];
            EXPECT_NEAR(w, t.at(di, dj), 1e-12 * scale)
                << dim << "-D w_" << out << " due to t_" << in << " at offset " << di << ", " << dj;
          }
      }
  }
}

// Depth 0 inside the loaded element: the stresses carry the traction (sigma_dd = -p,
// sigma_xd = -q_x, sigma_yd = -q_y); outside it they vanish; limits stay finite on the edges.
TEST(SubsurfaceInfluence, SurfaceTractionsAndEdgesAreFinite) {
  const Elastic m = Elastic::from_G_nu(1.0, 0.3);
  const dc::UnitFields inside = dc::rectangle_unit_fields(m, 1.0, 2.0, 0.1, -0.3, 0.0);
  EXPECT_NEAR(inside.pressure[dc::kSzz], -1.0, 1e-15);
  EXPECT_NEAR(inside.pressure[dc::kSxz], 0.0, 1e-15);
  EXPECT_NEAR(inside.shear_x[dc::kSxz], -1.0, 1e-15);
  EXPECT_NEAR(inside.shear_x[dc::kSzz], 0.0, 1e-15);
  EXPECT_NEAR(inside.shear_y[dc::kSyz], -1.0, 1e-15);
  const dc::UnitFields outside = dc::rectangle_unit_fields(m, 1.0, 2.0, 0.7, -0.3, 0.0);
  for (const FieldValues* f : {&outside.pressure, &outside.shear_x, &outside.shear_y})
    for (int c : {dc::kSzz, dc::kSxz, dc::kSyz}) EXPECT_NEAR((*f)[c], 0.0, 1e-15);
  // d = 0 agrees with a tiny depth away from the edges.
  const dc::UnitFields near = dc::rectangle_unit_fields(m, 1.0, 2.0, 0.1, -0.3, 1e-9);
  for (int c = 0; c < dc::kFieldComponents; ++c) {
    EXPECT_NEAR(near.pressure[c], inside.pressure[c], 1e-7);
    EXPECT_NEAR(near.shear_x[c], inside.shear_x[c], 1e-7);
    EXPECT_NEAR(near.shear_y[c], inside.shear_y[c], 1e-7);
  }
  // Edges, corners and the centre, at depth 0 and just below: finite, no NaN.
  for (double x : {-0.5, 0.0, 0.5, 1.5})
    for (double y : {-1.0, 0.0, 1.0})
      for (double d : {0.0, 1e-300, 1e-12}) {
        const dc::UnitFields f = dc::rectangle_unit_fields(m, 1.0, 2.0, x, y, d);
        const dc::UnitFields s = dc::strip_unit_fields(m, 1.0, x, d, 4.0);
        for (int c = 0; c < dc::kFieldComponents; ++c)
          for (double v : {f.pressure[c], f.shear_x[c], f.shear_y[c], s.pressure[c], s.shear_x[c]})
            EXPECT_TRUE(std::isfinite(v)) << x << ", " << y << ", " << d << " component " << c;
      }
}

}  // namespace subsurface_influence_tests

namespace subsurface_influence_tests {
// The tables of a grid (one quadrant evaluated, the rest by parity) against the closed form of
// one element at every offset, in both bodies, 3-D and 2-D.
TEST(SubsurfaceInfluence, TablesAreTheSingleElementField) {
  const Elastic m = Elastic::from_G_nu(1.7, 0.33);
  for (int dim : {3, 2}) {
    const dc::Grid grid = dim == 3 ? dc::Grid::make(3, 6, 5, -1.0, 2.0, -0.5, 1.5)
                                   : dc::Grid::make(2, 9, 1, -1.0, 2.0, 0.0, 1.0);
    const double L = grid.nx * grid.dx;
    for (dc::BodySide side : {dc::BodySide::body, dc::BodySide::base}) {
      dc::SubsurfaceCoefficients coefficients(grid, m, side);
      for (double depth : {0.0, 0.07, 0.9}) {
        coefficients.set_depth(depth);
        for (dc::Axis load : {dc::kX, dc::kY, dc::kZ}) {
          if (dim == 2 && load == dc::kY) continue;
          const double t[3] = {load == dc::kX ? 1.0 : 0.0, load == dc::kY ? 1.0 : 0.0, load == dc::kZ ? 1.0 : 0.0};
          for (int c = 0; c < dc::kFieldComponents; ++c) {
            dc::KernelTable table;
            coefficients.fill(c, load, table);
            for (int dj = -(grid.ny - 1); dj <= grid.ny - 1; ++dj)
              for (int di = -(grid.nx - 1); di <= grid.nx - 1; ++di) {
                const FieldValues f =
                    dim == 3 ? dc::rectangle_field(m, side, grid.dx, grid.dy, t[0], t[1], t[2], di * grid.dx,
                                                   dj * grid.dy, depth)
                             : dc::strip_field(m, side, grid.dx, t[0], t[2], di * grid.dx, depth, L);
                EXPECT_NEAR(table.at(di, dj), f[c], 1e-13 * (1.0 + std::abs(f[c])))
                    << dim << "-D component " << c << " load " << load << " offset " << di << ", " << dj
                    << " depth " << depth;
              }
          }
        }
      }
    }
  }
}
}  // namespace subsurface_influence_tests
