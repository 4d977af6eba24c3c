// The subsurface field of a grid (core/subsurface_field): the FFT path against direct
// summation, Hertz's sphere and the line contact against their closed forms (Johnson, Contact
// Mechanics 3.45, 4.46, 7.19; McEwen 1949), the equilibrium of horizontal slices, and the two
// bodies of a dissimilar pair. Tolerances are stated with the grid they hold on; measured
// errors are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

#include "grid.hpp"
#include "hertz.hpp"
#include "material.hpp"
#include "subsurface_closed_forms.hpp"
#include "subsurface_field.hpp"

namespace subsurface_field_tests {
using dc::BodySide;
using dc::Elastic;
using dc::Grid;
using dc::SubsurfaceMethod;
constexpr double kPi = std::numbers::pi;

double max_abs(const double* v, std::size_t n) {
  double m = 0.0;
  for (std::size_t i = 0; i < n; ++i) m = std::max(m, std::abs(v[i]));
  return m;
}

/// The largest |FFT - direct| of `t`'s field on `grid`, relative to each component's largest
/// value (a component zero by the direct path must be zero by the FFT); per component into
/// `each` when given.
double fft_direct_difference(const dc::Grid& grid, const dc::Elastic& m, dc::BodySide side,
                             const dc::SurfaceTractions& t, const std::vector<double>& depths,
                             std::vector<double>* each = nullptr) {
  dc::SubsurfaceField field(grid, m, side);
  const dc::SubsurfaceResult fft = field.compute(t, depths, dc::SubsurfaceMethod::fft);
  const dc::SubsurfaceResult direct = field.compute(t, depths, dc::SubsurfaceMethod::direct);
  double worst = 0.0;
  for (std::size_t k = 0; k < depths.size(); ++k)
    for (int c = 0; c < dc::kFieldComponents; ++c) {
      const double* a = fft.component(k, c);
      const double* b = direct.component(k, c);
      const double scale = max_abs(b, grid.size());
      double err = 0.0;
      if (scale == 0.0) {
        err = max_abs(a, grid.size()) == 0.0 ? 0.0 : 1.0;
      } else {
        for (std::size_t e = 0; e < grid.size(); ++e) err = std::max(err, std::abs(a[e] - b[e]));
        err /= scale;
      }
      if (each) each->push_back(err);
      worst = std::max(worst, err);
    }
  return worst;
}

/// Hertz's sphere on a grid: the closed-form pressure p0 sqrt(1 - r^2/a^2) at element centres.
struct SphereCase {
  Grid grid;
  double a, p0;
  std::vector<double> p;
};
SphereCase sphere_case(int n, double half_width_over_a, const Elastic& body, const Elastic& base) {
  const dc::MaterialPair pair{body, base};
  const dc::hertz::SphereSolution h = dc::hertz::sphere(0.01, 100.0, pair.E_star());
  SphereCase s{Grid::make(3, n, n, -half_width_over_a * h.a, half_width_over_a * h.a, -half_width_over_a * h.a,
                          half_width_over_a * h.a),
               h.a, h.p0, {}};
  s.p.resize(s.grid.size());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double r2 = (s.grid.xc(i) * s.grid.xc(i) + s.grid.yc(j) * s.grid.yc(j)) / (h.a * h.a);
      s.p[s.grid.index(i, j)] = r2 < 1.0 ? h.p0 * std::sqrt(1.0 - r2) : 0.0;
    }
  return s;
}

/// The 2-D line contact: p = p0 sqrt(1 - x^2/a^2) on a grid of nx strips over [-w a, w a].
struct LineCase {
  Grid grid;
  double a, p0;
  std::vector<double> p;
};
LineCase line_case(int nx, double half_width_over_a) {
  const double a = 1e-3, p0 = 1e8;
  LineCase s{Grid::make(2, nx, 1, -half_width_over_a * a, half_width_over_a * a, 0.0, 1.0), a, p0, {}};
  s.p.resize(s.grid.size());
  for (int i = 0; i < nx; ++i) {
    const double t = s.grid.xc(i) / a;
    s.p[i] = std::abs(t) < 1.0 ? p0 * std::sqrt(1.0 - t * t) : 0.0;
  }
  return s;
}

std::vector<double> linspace(double from, double to, int n) {
  std::vector<double> v(n);
  for (int k = 0; k < n; ++k) v[k] = from + (to - from) * k / (n - 1);
  return v;
}

// ---------------------------------------------------------------------------------------------

// The measures of simple states: uniaxial sigma (von Mises sigma, Tresca sigma / 2, hydrostatic
// sigma / 3) and pure shear tau (sqrt(3) tau, tau, 0), rotated arbitrarily.
TEST(SubsurfaceField, StressMeasuresOfSimpleStates) {
  dc::FieldValues f{};
  f[dc::kSzz] = -3.0;
  dc::StressMeasures m = dc::stress_measures(f);
  EXPECT_NEAR(m.von_mises, 3.0, 1e-14);
  EXPECT_NEAR(m.tresca, 1.5, 1e-14);
  EXPECT_NEAR(m.hydrostatic, -1.0, 1e-14);
  f = {};
  f[dc::kSxz] = 2.0;  // pure shear in the x-z plane
  m = dc::stress_measures(f);
  EXPECT_NEAR(m.von_mises, 2.0 * std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(m.tresca, 2.0, 1e-14);
  EXPECT_NEAR(m.hydrostatic, 0.0, 1e-14);
  f = {};
  f[dc::kSxx] = 1.0, f[dc::kSyy] = -1.0;  // the same pure shear, 45 degrees about z
  m = dc::stress_measures(f);
  EXPECT_NEAR(m.von_mises, std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(m.tresca, 1.0, 1e-14);
}

// The closed forms' own consistency: McEwen's field carries the traction on the surface and
// gives the axis formula at x = 0; Hertz's surface radial stress is continuous at r = a.
TEST(SubsurfaceField, ClosedFormsConsistency) {
  const double a = 2.0, p0 = 3.0, q0 = 0.7;
  for (double x : {-1.5, -0.3, 0.0, 0.8, 1.9}) {
    const double shape = std::sqrt(1.0 - x * x / (a * a));
    const auto n = dc::closed_form::mcewen_normal(x, 0.0, a, p0);
    const auto q = dc::closed_form::mcewen_tangential(x, 0.0, a, q0);
    EXPECT_NEAR(n.sigma_zz, -p0 * shape, 1e-13);
    EXPECT_NEAR(n.sigma_xx, -p0 * shape, 1e-13);  // [J] 4.47: sigma_x = sigma_z on the surface
    EXPECT_NEAR(n.sigma_xz, 0.0, 1e-13);
    EXPECT_NEAR(q.sigma_xz, -q0 * shape, 1e-13);
    EXPECT_NEAR(q.sigma_xx, -2.0 * q0 * x / a, 1e-13);
    EXPECT_NEAR(q.sigma_zz, 0.0, 1e-13);
  }
  for (double z : {0.0, 0.4, 1.7, 6.0}) {
    const auto n = dc::closed_form::mcewen_normal(0.0, z, a, p0);
    const auto e = dc::closed_form::line_contact_axis(z, a, p0);
    EXPECT_NEAR(n.sigma_xx, e.sigma_xx, 1e-13);
    EXPECT_NEAR(n.sigma_zz, e.sigma_zz, 1e-13);
  }
  const double nu = 0.3;
  // Inside, the -p sqrt(1 - r^2/a^2) term approaches r = a as a square root.
  EXPECT_NEAR(dc::closed_form::hertz_sphere_surface_radial(a * (1.0 - 1e-12), a, p0, nu),
              dc::closed_form::hertz_sphere_surface_radial(a, a, p0, nu), 1e-5);
  EXPECT_NEAR(dc::closed_form::hertz_sphere_surface_radial(1e-5 * a, a, p0, nu),
              dc::closed_form::hertz_sphere_surface_radial(0.0, a, p0, nu), 1e-9);
  const auto axis0 = dc::closed_form::hertz_sphere_axis(0.0, a, p0, nu);
  EXPECT_NEAR(axis0.sigma_z, -p0, 1e-15);
  EXPECT_NEAR(axis0.sigma_r, -(1.0 + 2.0 * nu) / 2.0 * p0, 1e-15);  // the surface value at r = 0
}

// Square grid of square elements: the mirror pairs (x <-> y) are transformed once and read
// transposed, and half the corner functions are evaluated; the same sums as the direct path,
// with all three traction components (the pairs tau_x <-> tau_y active) and each alone.
TEST(SubsurfaceField, FftEqualsDirectOnSquareGrid) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Elastic m = Elastic::from_G_nu(80e9, 0.28);
  const std::vector<double> depths = {0.0, 0.02, 0.35, 2.0};
  const Grid grid = Grid::make(3, 21, 21, -1.0, 1.1, -0.8, 1.3);
  ASSERT_EQ(grid.dx, grid.dy);
  dc::SurfaceTractions all;
  for (std::vector<double>* v : {&all.p, &all.tau_x, &all.tau_y}) v->resize(grid.size());
  for (std::size_t e = 0; e < grid.size(); ++e)
    all.p[e] = 1e6 * (1.0 + u(rng)), all.tau_x[e] = 3e5 * u(rng), all.tau_y[e] = 3e5 * u(rng);
  // Each shear alone with a mean (a zero-mean shear alone leaves components that cancel to
  // 1e-3 of their terms, where the comparison measures that cancellation, not the path).
  std::vector<double> tx(grid.size()), ty(grid.size());
  for (std::size_t e = 0; e < grid.size(); ++e) tx[e] = 3e5 * (1.0 + u(rng)), ty[e] = 3e5 * (1.0 + u(rng));
  std::vector<dc::SurfaceTractions> cases(4, dc::SurfaceTractions{});
  cases[0] = all;
  cases[1].p = all.p;
  cases[2].tau_x = tx;
  cases[3].tau_y = ty;
  for (const dc::SurfaceTractions& t : cases)
    for (BodySide side : {BodySide::body, BodySide::base})
      EXPECT_LT(fft_direct_difference(grid, m, side, t, depths), 1e-12);  // as on the non-square grid below
}

// The reflection x <-> y on a square grid: K_mirror(di, dj) = K(dj, di) for every table, to the
// rounding of its corner sums (the corner functions of the mirrored half are the evaluated ones
// exchanged; the sums are taken in another order). The scale: the table's largest value at
// depth 0, where the corner functions are of the size they have at any depth.
TEST(SubsurfaceField, MirrorTablesAreTransposes) {
  const Elastic m = Elastic::from_G_nu(80e9, 0.3);
  const Grid grid = Grid::make(3, 9, 9, -0.5, 0.4, -0.45, 0.45);
  dc::SubsurfaceCoefficients coefficients(grid, m, BodySide::body);
  ASSERT_TRUE(coefficients.square_corners());
  const auto largest = [](const dc::KernelTable& t) {
    double s = 0.0;
    for (double v : t.values) s = std::max(s, std::abs(v));
    return s;
  };
  for (int c = 0; c < dc::kFieldComponents; ++c)
    for (dc::Axis load : {dc::kX, dc::kY, dc::kZ}) {
      int mc = 0;
      dc::Axis ml = dc::kZ;
      dc::SubsurfaceCoefficients::mirror(c, load, mc, ml);
      dc::KernelTable a, b;
      coefficients.set_depth(0.0);
      coefficients.fill(c, load, a);
      const double scale = largest(a);
      for (double depth : {0.0, 0.05, 0.7}) {
        coefficients.set_depth(depth);
        coefficients.fill(c, load, a);
        coefficients.fill(mc, ml, b);
        double worst = 0.0;
        for (int dj = -(grid.ny - 1); dj < grid.ny; ++dj)
          for (int di = -(grid.nx - 1); di < grid.nx; ++di)
            worst = std::max(worst, std::abs(b.at(di, dj) - a.at(dj, di)));
        EXPECT_LE(worst, 1e-15 * scale) << "component " << c << ", load " << load << ", depth " << depth;
      }
    }
}

TEST(SubsurfaceField, FftEqualsDirectOnNonSquareGrid) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Elastic m = Elastic::from_G_nu(80e9, 0.28);
  const std::vector<double> depths = {0.0, 0.013, 0.4, 2.5};
  for (int dim : {3, 2}) {
    const Grid grid = dim == 3 ? Grid::make(3, 24, 17, -1.0, 1.4, -0.3, 1.4) : Grid::make(2, 37, 1, -1.0, 1.2, 0.0, 1.0);
    dc::SurfaceTractions t;
    t.p.resize(grid.size());
    t.tau_x.resize(grid.size());
    for (double& v : t.p) v = 1e6 * (1.0 + u(rng));
    for (double& v : t.tau_x) v = 3e5 * u(rng);
    if (dim == 3) {
      t.tau_y.resize(grid.size());
      for (double& v : t.tau_y) v = 3e5 * u(rng);
    }
    for (BodySide side : {BodySide::body, BodySide::base}) {
      std::vector<double> each;
      const double worst = fft_direct_difference(grid, m, side, t, depths, &each);
      for (std::size_t k = 0; k < each.size(); ++k)
        EXPECT_LT(each[k], 1e-12) << dim << "-D depth " << depths[k / dc::kFieldComponents] << " component "
                                  << k % dc::kFieldComponents;
      std::printf("[ info ] %d-D %s: FFT - direct, largest %.2e of each component's largest value\n", dim,
                  side == BodySide::body ? "body" : "base", worst);
    }
  }
}

// Grids one element wide (a box of 1 along that axis: no transform there) and a single element.
TEST(SubsurfaceField, FftEqualsDirectOnThinGrids) {
  const Elastic m = Elastic::from_G_nu(1.0, 0.25);
  for (const Grid& grid : {Grid::make(3, 1, 6, 0.0, 0.5, 0.0, 3.0), Grid::make(3, 7, 1, 0.0, 2.1, 0.0, 0.4),
                           Grid::make(3, 1, 1, 0.0, 1.0, 0.0, 1.0), Grid::make(2, 1, 1, 0.0, 1.0, 0.0, 1.0)}) {
    dc::SurfaceTractions t;
    t.p.assign(grid.size(), 1.0);
    t.tau_x.assign(grid.size(), 0.3);
    if (grid.dimension == 3) t.tau_y.assign(grid.size(), -0.2);
    for (std::size_t e = 0; e < grid.size(); ++e) t.p[e] += 0.1 * static_cast<double>(e);
    dc::SubsurfaceField field(grid, m, BodySide::base);
    const std::vector<double> depths = {0.0, 0.3};
    const dc::SubsurfaceResult a = field.compute(t, depths), b = field.compute(t, depths, SubsurfaceMethod::direct);
    for (std::size_t k = 0; k < a.values.size(); ++k) EXPECT_NEAR(a.values[k], b.values[k], 1e-13) << k;
  }
}

// Hertz's sphere, nu = 0.3, on 65 x 65 elements over 3a x 3a (dx = 0.046 a): the axis stresses
// against Johnson 3.45 within 0.1 % of p0 below z = 0.2 a (2e-4 measured), the largest shear (Tresca) 0.31 p0 at
// z = 0.48 a, and the surface radial stress just outside r = a ((1 - 2nu) p0 a^2 / (3 r^2)).
TEST(SubsurfaceField, HertzSphere) {
  const double nu = 0.3;
  const Elastic m = Elastic::from_E_nu(210e9, nu);
  const SphereCase s = sphere_case(65, 1.5, m, m);
  const int ic = 32;  // the element on the axis
  ASSERT_NEAR(s.grid.xc(ic), 0.0, 1e-12 * s.a);
  std::vector<double> depths = linspace(0.0, 1.2 * s.a, 61);  // step 0.02 a
  for (double z : {1.5, 2.0, 3.0}) depths.push_back(z * s.a);
  dc::SubsurfaceField field(s.grid, m, BodySide::body);
  dc::SurfaceTractions t;
  t.p = s.p;
  const dc::SubsurfaceResult r = field.compute(t, depths);
  double worst_z = 0.0, worst_r = 0.0;
  for (std::size_t k = 10; k < depths.size(); ++k) {  // z >= 0.2 a
    const dc::closed_form::AxisStresses e = dc::closed_form::hertz_sphere_axis(depths[k], s.a, s.p0, nu);
    const double sz = r.at(k, dc::kSzz, ic, ic), sx = r.at(k, dc::kSxx, ic, ic), sy = r.at(k, dc::kSyy, ic, ic);
    worst_z = std::max(worst_z, std::abs(sz - e.sigma_z) / s.p0);
    worst_r = std::max(worst_r, std::max(std::abs(sx - e.sigma_r), std::abs(sy - e.sigma_r)) / s.p0);
    EXPECT_NEAR(sz / s.p0, e.sigma_z / s.p0, 1e-3) << "z/a = " << depths[k] / s.a;
    EXPECT_NEAR(sx / s.p0, e.sigma_r / s.p0, 1e-3) << "z/a = " << depths[k] / s.a;
    EXPECT_NEAR(sy / s.p0, e.sigma_r / s.p0, 1e-3) << "z/a = " << depths[k] / s.a;
    EXPECT_NEAR(r.at(k, dc::kSxz, ic, ic) / s.p0, 0.0, 1e-12);
  }
  std::printf("[ info ] Hertz sphere axis, z >= 0.2 a: |sigma_z error| <= %.2e p0, |sigma_r error| <= %.2e p0\n",
              worst_z, worst_r);
  const dc::SubsurfaceMeasures mm = dc::subsurface_measures(r);
  std::printf("[ info ] Hertz sphere: max tau_1 %.4f p0 at z = %.3f a, r = %.3f a; max von Mises %.4f p0 at z = %.3f a\n",
              mm.max_tresca.value / s.p0, mm.max_tresca.depth / s.a,
              std::hypot(mm.max_tresca.x, mm.max_tresca.y) / s.a, mm.max_von_mises.value / s.p0,
              mm.max_von_mises.depth / s.a);
  EXPECT_NEAR(mm.max_tresca.value / s.p0, 0.31, 0.005);
  EXPECT_NEAR(mm.max_tresca.depth / s.a, 0.48, 0.03);
  EXPECT_LT(std::hypot(mm.max_tresca.x, mm.max_tresca.y), 0.05 * s.a);
  // Surface, along the x axis just outside the contact: sigma_xx is the radial stress.
  for (int i = ic + 1; i < s.grid.nx; ++i) {
    const double x = s.grid.xc(i);
    if (x < s.a) continue;
    const double exact = dc::closed_form::hertz_sphere_surface_radial(x, s.a, s.p0, nu);
    const double got = r.at(0, dc::kSxx, i, ic);
    std::printf("[ info ] surface sigma_r at r = %.3f a: %.4f p0 (closed form %.4f p0)\n", x / s.a, got / s.p0,
                exact / s.p0);
    EXPECT_GT(got, 0.0);  // tension
    EXPECT_NEAR(got / exact, 1.0, 0.03);  // 1 % measured on this grid
    break;
  }
}

// The line contact (plane strain, nu = 0.3) on 801 strips over [-4a, 4a] (dx = 0.01 a): the axis
// stresses within 0.02 % of p0 below z = 0.05 a ([J] 4.46; 3e-5 measured); the extremes of tau_1, tau_xz and
// von Mises ([J] 4.2 and 6.2: 0.30 p0 at 0.78 a; +-0.25 p0 at z = 0.5 a, x = +-0.87 a; first
// yield at p0 = 1.79 Y (von Mises, z = 0.70 a) and 1.67 Y (Tresca)).
TEST(SubsurfaceField, LineContact) {
  const double nu = 0.3;
  const Elastic m = Elastic::from_E_nu(210e9, nu);
  const LineCase s = line_case(801, 4.0);
  const int ic = 400;
  ASSERT_NEAR(s.grid.xc(ic), 0.0, 1e-12 * s.a);
  const std::vector<double> depths = linspace(0.0, 1.5 * s.a, 301);  // step 0.005 a
  dc::SubsurfaceField field(s.grid, m, BodySide::body);
  dc::SurfaceTractions t;
  t.p = s.p;
  const dc::SubsurfaceResult r = field.compute(t, depths);
  double worst = 0.0;
  for (std::size_t k = 10; k < depths.size(); ++k) {
    const dc::closed_form::PlaneStresses e = dc::closed_form::line_contact_axis(depths[k], s.a, s.p0);
    const double ez = std::abs(r.at(k, dc::kSzz, ic, 0) - e.sigma_zz) / s.p0;
    const double ex = std::abs(r.at(k, dc::kSxx, ic, 0) - e.sigma_xx) / s.p0;
    const double ey = std::abs(r.at(k, dc::kSyy, ic, 0) - nu * (e.sigma_xx + e.sigma_zz)) / s.p0;
    worst = std::max({worst, ez, ex, ey});
    EXPECT_LT(std::max({ez, ex, ey}), 2e-4) << "z/a = " << depths[k] / s.a;
  }
  std::printf("[ info ] line contact axis, z >= 0.05 a: largest error %.2e p0\n", worst);
  const dc::SubsurfaceMeasures mm = dc::subsurface_measures(r);
  std::printf("[ info ] line contact: max tau_1 %.4f p0 at z = %.3f a, x = %.3f a; max von Mises %.4f p0 "
              "(p0 = %.3f Y) at z = %.3f a; Tresca p0 = %.3f Y\n",
              mm.max_tresca.value / s.p0, mm.max_tresca.depth / s.a, mm.max_tresca.x / s.a,
              mm.max_von_mises.value / s.p0, s.p0 / mm.max_von_mises.value, mm.max_von_mises.depth / s.a,
              s.p0 / (2.0 * mm.max_tresca.value));
  EXPECT_NEAR(mm.max_tresca.value / s.p0, 0.30, 0.005);
  EXPECT_NEAR(mm.max_tresca.depth / s.a, 0.78, 0.02);
  EXPECT_NEAR(mm.max_tresca.x / s.a, 0.0, 0.011);
  EXPECT_NEAR(s.p0 / mm.max_von_mises.value, 1.79, 0.01);
  EXPECT_NEAR(mm.max_von_mises.depth / s.a, 0.70, 0.02);
  EXPECT_NEAR(s.p0 / (2.0 * mm.max_tresca.value), 1.67, 0.01);
  // tau_xz: its extremes over the field, +-0.25 p0 at z = 0.5 a, x = +-0.87 a.
  double lo = 0.0, hi = 0.0;
  std::size_t klo = 0, khi = 0;
  int ilo = 0, ihi = 0;
  for (std::size_t k = 0; k < depths.size(); ++k)
    for (int i = 0; i < s.grid.nx; ++i) {
      const double v = r.at(k, dc::kSxz, i, 0);
      if (v < lo) lo = v, klo = k, ilo = i;
      if (v > hi) hi = v, khi = k, ihi = i;
    }
  std::printf("[ info ] line contact tau_xz: %.4f p0 at (x, z) = (%.3f, %.3f) a, %.4f p0 at (%.3f, %.3f) a\n",
              hi / s.p0, s.grid.xc(ihi) / s.a, depths[khi] / s.a, lo / s.p0, s.grid.xc(ilo) / s.a,
              depths[klo] / s.a);
  EXPECT_NEAR(hi / s.p0, 0.25, 0.005);
  EXPECT_NEAR(lo / s.p0, -0.25, 0.005);
  EXPECT_NEAR(depths[khi] / s.a, 0.5, 0.02);
  EXPECT_NEAR(depths[klo] / s.a, 0.5, 0.02);
  EXPECT_NEAR(std::abs(s.grid.xc(ihi)) / s.a, 0.87, 0.02);
  EXPECT_NEAR(std::abs(s.grid.xc(ilo)) / s.a, 0.87, 0.02);
  EXPECT_LT(s.grid.xc(ihi) * s.grid.xc(ilo), 0.0);
}

// Full sliding q = mu p on the line contact (801 strips over [-4a, 4a]): McEwen's field
// ([J] 7.19) at points inside, within 0.3 % of p0 (1.2e-3 measured, at the contact's edges); the largest von Mises
// stress below the surface for mu = 0.2 and on it for mu = 0.4 ([J] 7.2: at mu ~ 0.3 it reaches
// the surface).
TEST(SubsurfaceField, LineContactSlidingMcEwen) {
  const double nu = 0.3;
  const Elastic m = Elastic::from_E_nu(210e9, nu);
  const LineCase s = line_case(801, 4.0);
  dc::SubsurfaceField field(s.grid, m, BodySide::body);
  const std::vector<double> depth_over_a = {0.05, 0.2, 0.5, 0.8, 1.3};
  std::vector<double> depths;
  for (double z : depth_over_a) depths.push_back(z * s.a);
  const double mu = 0.3;
  dc::SurfaceTractions t;
  t.p = s.p;
  t.tau_x.resize(s.p.size());
  for (std::size_t e = 0; e < s.p.size(); ++e) t.tau_x[e] = mu * s.p[e];
  const dc::SubsurfaceResult r = field.compute(t, depths);
  double worst = 0.0;
  for (std::size_t k = 0; k < depths.size(); ++k)
    for (double x_over_a : {-1.5, -1.0, -0.6, 0.0, 0.3, 0.9, 1.2, 2.0}) {
      const int i = static_cast<int>(std::lround(x_over_a * s.a / s.grid.dx + 400));
      const double x = s.grid.xc(i);
      const dc::closed_form::PlaneStresses n = dc::closed_form::mcewen_normal(x, depths[k], s.a, s.p0);
      const dc::closed_form::PlaneStresses q = dc::closed_form::mcewen_tangential(x, depths[k], s.a, mu * s.p0);
      const double tol = 0.003;
      const double ex = std::abs(r.at(k, dc::kSxx, i, 0) - n.sigma_xx - q.sigma_xx) / s.p0;
      const double ez = std::abs(r.at(k, dc::kSzz, i, 0) - n.sigma_zz - q.sigma_zz) / s.p0;
      const double exz = std::abs(r.at(k, dc::kSxz, i, 0) - n.sigma_xz - q.sigma_xz) / s.p0;
      worst = std::max({worst, ex, ez, exz});
      EXPECT_LT(ex, tol) << "sigma_xx at x = " << x / s.a << " a, z = " << depth_over_a[k] << " a";
      EXPECT_LT(ez, tol) << "sigma_zz at x = " << x / s.a << " a, z = " << depth_over_a[k] << " a";
      EXPECT_LT(exz, tol) << "sigma_xz at x = " << x / s.a << " a, z = " << depth_over_a[k] << " a";
    }
  std::printf("[ info ] McEwen, mu = %.1f: largest error %.2e p0\n", mu, worst);

  // Where the von Mises maximum lies as mu grows (depths 0 to 1.2 a, step 0.01 a).
  const std::vector<double> fine = linspace(0.0, 1.2 * s.a, 121);
  for (double mu_k : {0.2, 0.25, 0.3, 0.35, 0.4}) {
    for (std::size_t e = 0; e < s.p.size(); ++e) t.tau_x[e] = mu_k * s.p[e];
    const dc::SubsurfaceMeasures mm = dc::subsurface_measures(field.compute(t, fine));
    std::printf("[ info ] mu = %.2f: max von Mises %.4f p0 at z = %.3f a, x = %.3f a\n", mu_k,
                mm.max_von_mises.value / s.p0, mm.max_von_mises.depth / s.a, mm.max_von_mises.x / s.a);
    if (mu_k == 0.2) {
      EXPECT_GT(mm.max_von_mises.depth, 0.3 * s.a);
    }
    if (mu_k == 0.4) {
      EXPECT_EQ(mm.max_von_mises.depth, 0.0);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Equilibrium of a horizontal slice. The sum of the field over the element centres times the
// element area telescopes (the coefficients are corner differences): it is exactly the integral
// of the point-load field over the grid's region as seen from each loaded element, summed over
// the elements' forces. That integral is evaluated here by quadrature of Boussinesq's and
// Cerruti's point loads (Flamant's line loads in 2-D), so the slice sums must match to
// round-off; over the infinite plane they would be -P and -Q.

/// integral over y in [y0, y1] of 1 / (x^2 + y^2 + z^2)^(5/2)
double inner_r5(double c2, double y) { return y * (2.0 * y * y + 3.0 * c2) / (3.0 * c2 * c2 * std::pow(y * y + c2, 1.5)); }

double adaptive_gauss(const std::function<double(double)>& f, double a, double b, double tol) {
  // Gauss-Legendre 10 points on panels, bisected until two levels agree.
  static const double x[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                              0.9739065285171717};
  static const double w[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                              0.0666713443086881};
  const std::function<double(double, double)> gl = [&](double lo, double hi) {
    const double m = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
    double s = 0.0;
    for (int i = 0; i < 5; ++i) s += w[i] * (f(m + h * x[i]) + f(m - h * x[i]));
    return s * h;
  };
  const std::function<double(double, double, double, int)> rec = [&](double lo, double hi, double whole, int level) {
    const double mid = 0.5 * (lo + hi), l = gl(lo, mid), r = gl(mid, hi);
    if (std::abs(l + r - whole) <= tol || level > 25) return l + r;
    return rec(lo, mid, l, level + 1) + rec(mid, hi, r, level + 1);
  };
  return rec(a, b, gl(a, b), 0);
}

/// The integral over [x0, x1] x [y0, y1] of (3/(2 pi)) {z^3, x^2 z} / rho^5 (3-D) or over
/// [x0, x1] of (2/pi) {z^3, x^2 z} / r^4 (2-D): the point (line) load's -sigma_zz, -sigma_xz.
double point_load_slice(int dim, bool shear, double x0, double x1, double y0, double y1, double z) {
  const auto f = [&](double x) {
    const double top = shear ? x * x * z : z * z * z;
    if (dim == 2) return (2.0 / kPi) * top / std::pow(x * x + z * z, 2);
    const double c2 = x * x + z * z;
    return (3.0 / (2.0 * kPi)) * top * (inner_r5(c2, y1) - inner_r5(c2, y0));
  };
  double s = 0.0;
  // Split where the integrand peaks (x = 0), panels of a few z.
  std::vector<double> cuts = {x0};
  if (x0 < 0.0 && x1 > 0.0) cuts.push_back(0.0);
  cuts.push_back(x1);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) s += adaptive_gauss(f, cuts[k], cuts[k + 1], 1e-13);
  return s;
}

void check_equilibrium(int dim) {
  const Elastic m = Elastic::from_G_nu(80e9, 0.3);
  Grid grid;
  std::vector<double> p;
  double a = 0.0;
  if (dim == 3) {
    const SphereCase s = sphere_case(48, 4.0, m, m);
    grid = s.grid, p = s.p, a = s.a;
  } else {
    const LineCase s = line_case(161, 4.0);
    grid = s.grid, p = s.p, a = s.a;
  }
  const double mu = 0.3;
  dc::SurfaceTractions t;
  t.p = p;
  t.tau_x.resize(p.size());
  for (std::size_t e = 0; e < p.size(); ++e) t.tau_x[e] = mu * p[e];
  const std::vector<double> depths = {0.1 * a, 0.5 * a, 1.0 * a, 2.0 * a};
  dc::SubsurfaceField field(grid, m, BodySide::body);
  const dc::SubsurfaceResult r = field.compute(t, depths);
  double P = 0.0;
  for (double v : p) P += v * grid.area();
  for (std::size_t k = 0; k < depths.size(); ++k) {
    double szz = 0.0, sxz = 0.0;
    for (std::size_t e = 0; e < grid.size(); ++e) {
      szz += r.component(k, dc::kSzz)[e] * grid.area();
      sxz += r.component(k, dc::kSxz)[e] * grid.area();
    }
    double expect_zz = 0.0, expect_xz = 0.0;
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const double force = p[grid.index(i, j)] * grid.area();
        if (force == 0.0) continue;
        const double x0 = grid.x0 - grid.xc(i), x1 = grid.x_max() - grid.xc(i);
        const double y0 = grid.y0 - grid.yc(j), y1 = grid.y_max() - grid.yc(j);
        expect_zz -= force * point_load_slice(dim, false, x0, x1, y0, y1, depths[k]);
        expect_xz -= mu * force * point_load_slice(dim, true, x0, x1, y0, y1, depths[k]);
      }
    std::printf("[ info ] %d-D slice z = %.1f a: sum sigma_zz dA = %.6f P (off the region's share by %.1e P), "
                "sum sigma_xz dA = %.6f Q (off by %.1e Q)\n",
                dim, depths[k] / a, szz / P, szz / P - expect_zz / P, sxz / (mu * P), (sxz - expect_xz) / (mu * P));
    EXPECT_NEAR(szz / P, expect_zz / P, 1e-12) << "z = " << depths[k] / a << " a";
    EXPECT_NEAR(sxz / (mu * P), expect_xz / (mu * P), 1e-12) << "z = " << depths[k] / a << " a";
    // The region's share of -P: what lies outside is at most the point load's share beyond the
    // distance R = 3a from the contact's edge to the grid's edge (the integrand is positive).
    const double z = depths[k], R = 3.0 * a;
    const double outside = dim == 3 ? z * z * z / std::pow(R * R + z * z, 1.5)
                                    : (2.0 / kPi) * (0.5 * kPi - std::atan(R / z) - R * z / (R * R + z * z));
    EXPECT_LT(expect_zz / P + 1.0, outside);
    EXPECT_GT(expect_zz / P + 1.0, 0.0);
  }
}

TEST(SubsurfaceField, SliceEquilibrium3D) { check_equilibrium(3); }
TEST(SubsurfaceField, SliceEquilibrium2D) { check_equilibrium(2); }

// ---------------------------------------------------------------------------------------------
// Dissimilar materials: a steel ball (nu = 0.29) on a soft base (nu = 0.45), Hertz pressure and
// a shear 0.2 p along +x on the body (65 x 65 elements over 3a x 3a). On the axis each body's
// sigma_r follows Johnson 3.45 with its own nu within 0.1 % of p0 (sigma_z the same in both); at depth 0 both carry the traction in the global
// frame: sigma_zz = -p, sigma_xz = -tau_x (the traction across the interface is continuous);
// the base's displacements are downward and along -x.
TEST(SubsurfaceField, DissimilarBodies) {
  const Elastic body = Elastic::from_E_nu(210e9, 0.29), base = Elastic::from_E_nu(5e9, 0.45);
  const SphereCase s = sphere_case(65, 1.5, body, base);
  const int ic = 32;
  dc::SurfaceTractions t;
  t.p = s.p;
  const std::vector<double> depths = {0.0, 0.3 * s.a, 0.6 * s.a, 1.0 * s.a};
  dc::SubsurfaceField upper(s.grid, body, BodySide::body), lower(s.grid, base, BodySide::base);
  const dc::SubsurfaceResult ru = upper.compute(t, depths), rl = lower.compute(t, depths);
  for (std::size_t k = 1; k < depths.size(); ++k) {
    const auto eu = dc::closed_form::hertz_sphere_axis(depths[k], s.a, s.p0, body.nu);
    const auto el = dc::closed_form::hertz_sphere_axis(depths[k], s.a, s.p0, base.nu);
    EXPECT_NEAR(ru.at(k, dc::kSxx, ic, ic) / s.p0, eu.sigma_r / s.p0, 1e-3);
    EXPECT_NEAR(rl.at(k, dc::kSxx, ic, ic) / s.p0, el.sigma_r / s.p0, 1e-3);
    EXPECT_NEAR(ru.at(k, dc::kSzz, ic, ic) / s.p0, eu.sigma_z / s.p0, 1e-3);
    EXPECT_NEAR(rl.at(k, dc::kSzz, ic, ic) / s.p0, el.sigma_z / s.p0, 1e-3);
    // The bodies differ as their nu does: far more than the tolerance.
    EXPECT_GT(std::abs(eu.sigma_r - el.sigma_r), 0.03 * s.p0);
    EXPECT_GT(std::abs(ru.at(k, dc::kSxx, ic, ic) - rl.at(k, dc::kSxx, ic, ic)), 0.03 * s.p0);
    EXPECT_GT(ru.at(k, dc::kUz, ic, ic), 0.0);  // the body moves up
    EXPECT_LT(rl.at(k, dc::kUz, ic, ic), 0.0);  // the base down
  }
  std::printf("[ info ] dissimilar, z = 0.6 a: sigma_r body %.4f p0 (nu %.2f: %.4f), base %.4f p0 (nu %.2f: %.4f)\n",
              ru.at(2, dc::kSxx, ic, ic) / s.p0, body.nu,
              dc::closed_form::hertz_sphere_axis(depths[2], s.a, s.p0, body.nu).sigma_r / s.p0,
              rl.at(2, dc::kSxx, ic, ic) / s.p0, base.nu,
              dc::closed_form::hertz_sphere_axis(depths[2], s.a, s.p0, base.nu).sigma_r / s.p0);
  // With a shear: the traction at depth 0 in the global frame, in both bodies.
  t.tau_x.resize(s.p.size());
  for (std::size_t e = 0; e < s.p.size(); ++e) t.tau_x[e] = 0.2 * s.p[e];
  const dc::SubsurfaceResult su = upper.compute(t, {0.0, 0.5 * s.a}), sl = lower.compute(t, {0.0, 0.5 * s.a});
  for (std::size_t e = 0; e < s.grid.size(); ++e) {
    for (const dc::SubsurfaceResult* r : {&su, &sl}) {
      EXPECT_NEAR(r->component(0, dc::kSzz)[e], -t.p[e], 1e-9 * s.p0);
      EXPECT_NEAR(r->component(0, dc::kSxz)[e], -t.tau_x[e], 1e-9 * s.p0);
      EXPECT_NEAR(r->component(0, dc::kSyz)[e], 0.0, 1e-9 * s.p0);
    }
  }
  EXPECT_GT(su.at(1, dc::kUx, ic, ic), 0.0);  // the body dragged along +x
  EXPECT_LT(sl.at(1, dc::kUx, ic, ic), 0.0);  // the base along -x
  // Below the centre the shear stress keeps the surface's sign in both bodies (global frame).
  EXPECT_LT(su.at(1, dc::kSxz, ic, ic), 0.0);
  EXPECT_LT(sl.at(1, dc::kSxz, ic, ic), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Timing: the FFT path on 256 x 256 elements at 32 depths (Hertz pressure; then with both shears).
TEST(SubsurfaceField, Timing256) {
  const Elastic m = Elastic::from_E_nu(210e9, 0.3);
  const SphereCase s = sphere_case(256, 1.5, m, m);
  const std::vector<double> depths = linspace(0.0, 1.5 * s.a, 32);
  const auto t0 = std::chrono::steady_clock::now();
  dc::SubsurfaceField field(s.grid, m, BodySide::body);
  const auto t1 = std::chrono::steady_clock::now();
  dc::SurfaceTractions t;
  t.p = s.p;
  const dc::SubsurfaceResult r = field.compute(t, depths);
  const auto t2 = std::chrono::steady_clock::now();
  const dc::SubsurfaceMeasures mm = dc::subsurface_measures(r);
  const auto t3 = std::chrono::steady_clock::now();
  t.tau_x.assign(s.p.size(), 0.0);
  t.tau_y.assign(s.p.size(), 0.0);
  for (std::size_t e = 0; e < s.p.size(); ++e) t.tau_x[e] = 0.1 * s.p[e], t.tau_y[e] = 0.05 * s.p[e];
  const dc::SubsurfaceResult r3 = field.compute(t, depths);
  const auto t4 = std::chrono::steady_clock::now();
  // One depth at a time into one buffer (no 150 MB result to fill): pressure only.
  t.tau_x.clear();
  t.tau_y.clear();
  std::vector<double> one(dc::kFieldComponents * s.grid.size());
  field.set_tractions(t);
  double largest_szz = 0.0;
  for (double d : depths) {
    field.compute_depth(d, one.data());
    largest_szz = std::max(largest_szz, max_abs(one.data() + dc::kSzz * s.grid.size(), s.grid.size()));
  }
  const auto t5 = std::chrono::steady_clock::now();
  const auto sec = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::printf("[ info ] 256x256, 32 depths: set-up %.3f s, pressure only %.3f s (one depth at a time into one "
              "buffer %.3f s), measures %.3f s, pressure and shears %.3f s\n",
              sec(t0, t1), sec(t1, t2), sec(t4, t5), sec(t2, t3), sec(t3, t4));
  EXPECT_NEAR(mm.max_tresca.value / s.p0, 0.31, 0.01);
  EXPECT_EQ(r3.values.size(), r.values.size());
  EXPECT_NEAR(largest_szz / s.p0, 1.0, 0.01);
}

}  // namespace subsurface_field_tests
