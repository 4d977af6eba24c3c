// The flash temperature of a grid (core/moving_heat_source, core/flash_temperature): the
// element coefficients against a direct quadrature of the moving point source, their speed -> 0
// limit and mirror symmetry, the grid's uniform band, square and circle against Jaeger's closed
// forms at low and high Peclet number, Blok's Hertzian flux, FFT against dense summation, and the
// partition of the heat between the two bodies. Tolerances are stated with the grid they hold
// on; measured errors are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "adaptive_quadrature.hpp"
#include "errors.hpp"
#include "flash_temperature.hpp"
#include "moving_heat_source.hpp"
#include "thermal_closed_forms.hpp"

namespace flash_temperature_tests {
using dc::BodySide;
using dc::FlashTemperature;
using dc::Grid;
using dc::HeatPartition;
using dc::ThermalSurface;
constexpr double kPi = std::numbers::pi;

/// A surface of conductivity K = 1 and diffusivity 1 at Peclet number `pe` for the length L.
ThermalSurface surface_at(double pe, double length) {
  return ThermalSurface{dc::ThermalProperties::make(1.0, 1.0, "surface"), 2.0 * pe / length};
}

double heated_mean(const std::vector<double>& T, const std::vector<double>& q) {
  double s = 0.0;
  int n = 0;
  for (std::size_t e = 0; e < T.size(); ++e)
    if (q[e] > 0.0) {
      s += T[e];
      ++n;
    }
  return s / n;
}

TEST(FlashTemperature, CoefficientsMatchPointSourceQuadrature) {
  // Away from the element: a nested adaptive quadrature of (1) over it. The element itself and
  // its neighbour: the same split into the four rectangles with the field point at a corner,
  // each nested quadrature with the 1/R singularity at its end (integrable, resolved adaptively).
  const Grid grid = Grid::make(3, 7, 5, 0.0, 7e-3, 0.0, 4e-3);
  const double k = 0.7 / grid.dx;  // 0.7 per element
  const ThermalSurface s{dc::ThermalProperties::make(2.0, 1e-5, "s"), 2.0 * 1e-5 * k};
  const dc::KernelTable table = dc::heat_influence_table(grid, s, "s");
  const auto rectangle = [&](double x1, double x2, double y1, double y2) {
    const auto inner = [&](double X) {
      return dc::integrate_adaptive(
          [&](double Y) { return X == 0.0 && Y == 0.0 ? 0.0 : dc::moving_point_source(2.0, k, X, Y); }, y1, y2,
          {1e-12, 0.0, 2000});
    };
    return dc::integrate_adaptive(inner, x1, x2, {1e-11, 0.0, 2000});
  };
  double worst = 0.0;
  for (const auto& [di, dj] : std::vector<std::pair<int, int>>{{0, 0}, {1, 0}, {-1, 1}, {3, 2}, {-4, 1}, {-6, 4}, {6, -3}}) {
    // X = x - x' over the source element: [(di - 1/2) dx, (di + 1/2) dx].
    const double x1 = (di - 0.5) * grid.dx, x2 = (di + 0.5) * grid.dx;
    const double y1 = (dj - 0.5) * grid.dy, y2 = (dj + 0.5) * grid.dy;
    double exact = 0.0;
    const double xs[3] = {x1, std::clamp(0.0, x1, x2), x2}, ys[3] = {y1, std::clamp(0.0, y1, y2), y2};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) exact += rectangle(xs[a], xs[a + 1], ys[b], ys[b + 1]);
    const double rel = std::abs(table.at(di, dj) - exact) / exact;
    worst = std::max(worst, rel);
    EXPECT_LT(rel, 1e-9) << "offset " << di << ", " << dj;
  }
  std::printf("element coefficients against quadrature: worst relative %.2e\n", worst);
}

TEST(FlashTemperature, CoefficientsSlowLimitAndMirror) {
  const Grid grid = Grid::make(3, 9, 6, -1.0, 1.0, -0.5, 0.5);
  const dc::KernelTable still = dc::heat_influence_table(grid, surface_at(0.0, 1.0), "s");
  // At k dx = 5e-11 the quadrature path meets Love's closed form (the first-order change is
  // -k dx dy / (2 pi K): relative 1e-10 at most).
  const dc::KernelTable slow = dc::heat_influence_table(grid, surface_at(1e-10 * 0.5 / grid.dx, 1.0), "s");
  const dc::KernelTable fast = dc::heat_influence_table(grid, surface_at(3.0, 1.0), "s");
  const dc::KernelTable back = dc::heat_influence_table(grid, ThermalSurface{{1.0, 1.0}, -6.0}, "s");
  for (int dj = -(grid.ny - 1); dj < grid.ny; ++dj)
    for (int di = -(grid.nx - 1); di < grid.nx; ++di) {
      EXPECT_NEAR(slow.at(di, dj), still.at(di, dj), 1e-9 * still.at(di, dj));
      EXPECT_NEAR(still.at(di, dj), still.at(-di, dj), 1e-15 * still.at(di, dj));
      EXPECT_NEAR(fast.at(di, dj), fast.at(di, -dj), 1e-15 * fast.at(di, dj));
      EXPECT_NEAR(back.at(di, dj), fast.at(-di, dj), 1e-12 * fast.at(-di, dj));  // the source moving -x
      if (di > 0) {
        EXPECT_LT(fast.at(di, dj), fast.at(-di, dj));  // ahead of the source is cooler
      }
    }
}

TEST(FlashTemperature, BandMatchesJaegerAtLowAndHighPeclet) {
  // 2-D, uniform q = 1 on |x| <= b = 1, 400 strips on the band (edges on strip edges) and 100
  // on either side. Piecewise constant, the band is exact on the grid: the centres carry (B1) to
  // round-off. The grid's maximum and mean (midpoint values) then meet (B2), (B3) to the closed
  // form's remainder plus the sampling: the centre sits dx/2 from x = 0 (low Pe, curvature
  // (2/pi) / (1 - x^2): 2e-6) and from the trailing edge (high Pe, sqrt profile: dx / (8 b) of
  // the maximum, 1.3e-3 relative at dx = b/200), the mean is a midpoint rule of a sqrt (the
  // leading edge: O(dx^1.5), 1e-4 relative).
  const Grid grid = Grid::make(2, 600, 1, -1.5, 1.5, 0.0, 1.0);
  std::vector<double> q(grid.size(), 0.0);
  for (int i = 0; i < grid.nx; ++i)
    if (std::abs(grid.xc(i)) < 1.0) q[i] = 1.0;
  for (double pe : {0.01, 0.1, 10.0, 100.0}) {
    const FlashTemperature ft(grid, surface_at(pe, 1.0), surface_at(pe, 1.0));
    const std::vector<double> T = ft.surface_temperature(BodySide::base, q);
    double worst = 0.0;
    for (int i = 0; i < grid.nx; ++i)
      worst = std::max(worst, std::abs(T[i] - dc::thermal::band_temperature(grid.xc(i), pe)));
    const double max = *std::max_element(T.begin(), T.end()), mean = heated_mean(T, q);
    EXPECT_LT(worst, 1e-12 * max) << "Pe " << pe;
    if (pe < 1.0) {
      const double bound = pe * pe * std::log(pe) * std::log(pe) + 1e-5;
      std::printf("band Pe %g: grid max %.6f mean %.6f, Jaeger low-Pe %.6f %.6f (bound %.1e)\n", pe, max, mean,
                  dc::thermal::band_centre_low_peclet(pe), dc::thermal::band_mean_low_peclet(pe), bound);
      EXPECT_NEAR(max, dc::thermal::band_centre_low_peclet(pe), bound);
      EXPECT_NEAR(mean, dc::thermal::band_mean_low_peclet(pe), bound);
    } else {
      const double max_1d = dc::thermal::one_dimensional_max(pe), mean_1d = dc::thermal::one_dimensional_mean(pe);
      std::printf("band Pe %g: grid max %.6f (1-D %.6f, %.2e) mean %.6f (1-D %.6f, %.2e)\n", pe, max, max_1d,
                  max / max_1d - 1.0, mean, mean_1d, mean / mean_1d - 1.0);
      EXPECT_NEAR(max / max_1d, 1.0, 1.0 / pe + grid.dx / 8.0);
      EXPECT_NEAR(mean / mean_1d, 1.0, 1.0 / pe + 1e-3);
    }
  }
}

/// The uniform square |x|, |y| <= a = 1 as the whole grid (n odd: an element at the centre).
struct SquareCase {
  Grid grid = Grid::make(3, 41, 41, -1.0, 1.0, -1.0, 1.0);
  std::vector<double> q = std::vector<double>(41 * 41, 1.0);
};

TEST(FlashTemperature, SquareMatchesJaegerAtLowAndHighPeclet) {
  const SquareCase sq;
  const std::size_t centre = sq.grid.index(20, 20);
  // Stationary: exact at the centre (the elements tile the square); the mean of the centre
  // values is a midpoint rule of a field whose slope is logarithmic at the edges: O(dx^2 ln dx).
  const FlashTemperature still(sq.grid, surface_at(0.0, 1.0), surface_at(0.0, 1.0));
  const std::vector<double> T0 = still.surface_temperature(BodySide::base, sq.q);
  const double mean0 = heated_mean(T0, sq.q);
  std::printf("square Pe 0: centre %.10f (%.10f), mean %.6f (%.6f)\n", T0[centre],
              dc::thermal::square_centre_stationary(), mean0, dc::thermal::square_mean_stationary());
  EXPECT_NEAR(T0[centre], dc::thermal::square_centre_stationary(), 1e-12);
  const double h = sq.grid.dx / 2.0;  // dx / (2 a)
  EXPECT_NEAR(mean0, dc::thermal::square_mean_stationary(), h * h * std::abs(std::log(h)));
  // Low Pe: (L1)'s slope -2/pi, the remainder O(Pe^2): the centre within Pe^2 of the line.
  for (double pe : {0.01, 0.05}) {
    const FlashTemperature slow(sq.grid, surface_at(pe, 1.0), surface_at(pe, 1.0));
    const std::vector<double> T = slow.surface_temperature(BodySide::base, sq.q);
    const double line = dc::thermal::square_centre_stationary() + dc::thermal::square_low_peclet_slope() * pe;
    std::printf("square Pe %g: centre %.8f, first order %.8f\n", pe, T[centre], line);
    EXPECT_NEAR(T[centre], line, pe * pe);
    EXPECT_NEAR(heated_mean(T, sq.q) - mean0, dc::thermal::square_low_peclet_slope() * pe, pe * pe);
  }
  // High Pe: the centre line's trailing element against the 1-D profile at its centre
  // 2 sqrt((1 - xi) / (2 pi Pe)) (O(1/Pe) relative), the mean against (B3) (the lateral edges,
  // O(Pe^-1/2)).
  for (double pe : {20.0, 100.0}) {
    const FlashTemperature fast(sq.grid, surface_at(pe, 1.0), surface_at(pe, 1.0));
    const std::vector<double> T = fast.surface_temperature(BodySide::base, sq.q);
    const double xi = sq.grid.xc(0);
    const double trail = T[sq.grid.index(0, 20)], trail_1d = 2.0 * std::sqrt((1.0 - xi) / (2.0 * kPi * pe));
    const double mean = heated_mean(T, sq.q), mean_1d = dc::thermal::one_dimensional_mean(pe);
    std::printf("square Pe %g: trailing %.6f (1-D %.6f, %.2e), mean %.6f (1-D %.6f, %.2e)\n", pe, trail, trail_1d,
                trail / trail_1d - 1.0, mean, mean_1d, mean / mean_1d - 1.0);
    EXPECT_NEAR(trail / trail_1d, 1.0, 1.0 / pe);
    EXPECT_NEAR(mean / mean_1d, 1.0, 1.0 / std::sqrt(pe));
  }
}

/// The uniform circle r <= a = 1 on an n x n grid over [-a, a]^2, each element's flux its share
/// of area inside the circle (16 x 16 samples).
struct CircleCase {
  Grid grid;
  std::vector<double> q;
  explicit CircleCase(int n) : grid(Grid::make(3, n, n, -1.0, 1.0, -1.0, 1.0)), q(grid.size(), 0.0) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int inside = 0;
        for (int b = 0; b < 16; ++b)
          for (int a = 0; a < 16; ++a) {
            const double x = grid.x0 + (i + (a + 0.5) / 16.0) * grid.dx, y = grid.y0 + (j + (b + 0.5) / 16.0) * grid.dy;
            inside += x * x + y * y < 1.0;
          }
        q[grid.index(i, j)] = inside / 256.0;
      }
  }
};

TEST(FlashTemperature, CircleMatchesJaegerAtLowAndHighPeclet) {
  // 61 x 61 over the circle's square. The centre sees the boundary's rasterised area at a
  // distance a: error ~ the area's 1/256 sampling of the edge elements over 2 pi a^2 (2e-4).
  const CircleCase c(61);
  const std::size_t centre = c.grid.index(30, 30);
  const FlashTemperature still(c.grid, surface_at(0.0, 1.0), surface_at(0.0, 1.0));
  const std::vector<double> T0 = still.surface_temperature(BodySide::base, c.q);
  std::printf("circle Pe 0: centre %.6f (1), max %.6f\n", T0[centre], *std::max_element(T0.begin(), T0.end()));
  EXPECT_NEAR(T0[centre], dc::thermal::circle_centre_stationary(), 1e-3);
  EXPECT_EQ(*std::max_element(T0.begin(), T0.end()), T0[centre]);
  // The mean over the disc, weighted by each element's area inside it.
  const auto disc_mean = [&](const std::vector<double>& T) {
    double s = 0.0, w = 0.0;
    for (std::size_t e = 0; e < T.size(); ++e) {
      s += c.q[e] * T[e];
      w += c.q[e];
    }
    return s / w;
  };
  std::printf("circle Pe 0: mean %.6f (%.6f)\n", disc_mean(T0), dc::thermal::circle_mean_stationary());
  EXPECT_NEAR(disc_mean(T0), dc::thermal::circle_mean_stationary(), 2e-3);
  // Low Pe: (L1)'s slope -1/2.
  const double pe = 0.02;
  const FlashTemperature slow(c.grid, surface_at(pe, 1.0), surface_at(pe, 1.0));
  const std::vector<double> Ts = slow.surface_temperature(BodySide::base, c.q);
  std::printf("circle Pe %g: centre change %.6e (first order %.6e)\n", pe, Ts[centre] - T0[centre],
              dc::thermal::circle_low_peclet_slope() * pe);
  EXPECT_NEAR(Ts[centre] - T0[centre], dc::thermal::circle_low_peclet_slope() * pe, pe * pe);
  // High Pe: the maximum (the central chord's trailing edge) within O(1/Pe) plus the sampling of
  // the sqrt profile by the trailing element (dx / (8 a)); the mean (C2) within O(Pe^-1/2).
  for (double fast_pe : {25.0, 100.0}) {
    const FlashTemperature fast(c.grid, surface_at(fast_pe, 1.0), surface_at(fast_pe, 1.0));
    const std::vector<double> T = fast.surface_temperature(BodySide::base, c.q);
    const double max = *std::max_element(T.begin(), T.end()), max_1d = dc::thermal::one_dimensional_max(fast_pe);
    const double mean = disc_mean(T), mean_1d = dc::thermal::circle_mean_high_peclet(fast_pe);
    std::printf("circle Pe %g: max %.6f (1-D %.6f, %.2e), mean %.6f (1-D %.6f, %.2e)\n", fast_pe, max, max_1d,
                max / max_1d - 1.0, mean, mean_1d, mean / mean_1d - 1.0);
    EXPECT_NEAR(max / max_1d, 1.0, 1.0 / fast_pe + c.grid.dx / 8.0);
    EXPECT_NEAR(mean / mean_1d, 1.0, 1.0 / std::sqrt(fast_pe));
  }
}

TEST(FlashTemperature, BlokHertzianLineContact) {
  // 2-D, q = q0 sqrt(1 - x^2/b^2) at the strip centres, 800 strips over |x| <= b (b = 1).
  const Grid grid = Grid::make(2, 800, 1, -1.0, 1.0, 0.0, 1.0);
  std::vector<double> q(grid.size());
  for (int i = 0; i < grid.nx; ++i) q[i] = std::sqrt(1.0 - grid.xc(i) * grid.xc(i));
  const dc::thermal::BlokMaximum blok = dc::thermal::blok_line_maximum();
  // At Pe = 1 against the exact (H2) (the flux's midpoint sampling: O(dx^2) but O(dx^1.5) at the
  // edges, where the sqrt is steepest; 1e-4 relative at dx = b/400).
  {
    const FlashTemperature ft(grid, surface_at(1.0, 1.0), surface_at(1.0, 1.0));
    const std::vector<double> T = ft.surface_temperature(BodySide::base, q);
    double worst = 0.0, tmax = 0.0;
    for (int i = 0; i < grid.nx; i += 40) {
      worst = std::max(worst, std::abs(T[i] - dc::thermal::hertz_line_temperature(grid.xc(i), 1.0)));
      tmax = std::max(tmax, T[i]);
    }
    std::printf("Hertzian flux Pe 1: grid against (H2) %.2e of the maximum\n", worst / tmax);
    EXPECT_LT(worst, 1e-4 * tmax);
  }
  // At high Pe the grid's maximum meets Blok's 0.87301 q0 b / (K sqrt(Pe)) at O(1/Pe), and
  // where (x = -0.652 b) to the strip.
  for (double pe : {100.0, 1000.0}) {
    const FlashTemperature ft(grid, surface_at(pe, 1.0), surface_at(pe, 1.0));
    const std::vector<double> T = ft.surface_temperature(BodySide::base, q);
    const auto at = std::max_element(T.begin(), T.end());
    const double limit = blok.coefficient / std::sqrt(pe);
    const double x = grid.xc(static_cast<int>(at - T.begin()));
    std::printf("Hertzian flux Pe %g: grid max %.6f at x = %.4f (Blok %.6f at %.4f, %.2e)\n", pe, *at, x, limit,
                blok.xi, *at / limit - 1.0);
    EXPECT_NEAR(*at / limit, 1.0, 1.0 / pe + 1e-4);
    EXPECT_NEAR(x, blok.xi, 0.02);
  }
}

TEST(FlashTemperature, BlokHertzianCircle) {
  // 3-D, q = q0 sqrt(1 - r^2/a^2) at the element centres of a 61 x 61 grid over the circle's
  // square, Pe = 100: the maximum on the central chord against (H1)'s 0.87301 (O(1/Pe), the peak
  // inside the contact: no edge sampling), the mean over the heated elements against (H3)
  // (the lateral edges: O(Pe^-1/2); the rasterised rim: O(dx / a) of the mean).
  const Grid grid = Grid::make(3, 61, 61, -1.0, 1.0, -1.0, 1.0);
  std::vector<double> q(grid.size(), 0.0);
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double r2 = grid.xc(i) * grid.xc(i) + grid.yc(j) * grid.yc(j);
      if (r2 < 1.0) q[grid.index(i, j)] = std::sqrt(1.0 - r2);
    }
  const double pe = 100.0;
  const FlashTemperature ft(grid, surface_at(pe, 1.0), surface_at(pe, 1.0));
  const std::vector<double> T = ft.surface_temperature(BodySide::base, q);
  const double max = *std::max_element(T.begin(), T.end()), mean = heated_mean(T, q);
  const double max_1d = dc::thermal::blok_line_maximum().coefficient / std::sqrt(pe);
  const double mean_1d = dc::thermal::hertz_circle_mean_high_peclet(pe);
  std::printf("Hertzian circle Pe %g: max %.6f (Blok %.6f, %.2e), mean %.6f (1-D %.6f, %.2e)\n", pe, max, max_1d,
              max / max_1d - 1.0, mean, mean_1d, mean / mean_1d - 1.0);
  EXPECT_NEAR(max / max_1d, 1.0, 1.0 / pe);
  EXPECT_NEAR(mean / mean_1d, 1.0, 1.0 / std::sqrt(pe) + grid.dx);
}

TEST(FlashTemperature, FftEqualsDenseAndIsLinear) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Grid& grid : {Grid::make(3, 24, 17, -1.0, 1.0, -0.7, 0.7), Grid::make(2, 300, 1, -1.0, 1.0, 0.0, 1.0)}) {
    const ThermalSurface base = surface_at(2.5, 1.0), body = ThermalSurface{{3.0, 2.0}, -0.7};
    const FlashTemperature dense(grid, base, body, dc::OperatorKind::dense);
    const FlashTemperature fft(grid, base, body, dc::OperatorKind::fft);
    ASSERT_EQ(dense.kind(), "dense");
    ASSERT_EQ(fft.kind(), "fft");
    std::vector<double> q1(grid.size()), q2(grid.size()), mix(grid.size());
    for (std::size_t e = 0; e < grid.size(); ++e) {
      q1[e] = u(rng);
      q2[e] = u(rng);
      mix[e] = 2.0 * q1[e] + 0.5 * q2[e];
    }
    for (BodySide side : {BodySide::base, BodySide::body}) {
      const std::vector<double> a = dense.surface_temperature(side, q1), b = fft.surface_temperature(side, q1);
      // An independent direct sum of the table.
      std::vector<double> direct(grid.size(), 0.0);
      const dc::KernelTable& t = dense.table(side);
      for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i)
          for (int jj = 0; jj < grid.ny; ++jj)
            for (int ii = 0; ii < grid.nx; ++ii) direct[grid.index(i, j)] += t.at(i - ii, j - jj) * q1[grid.index(ii, jj)];
      const double scale = *std::max_element(direct.begin(), direct.end());
      const std::vector<double> m1 = fft.surface_temperature(side, q2), mm = fft.surface_temperature(side, mix);
      for (std::size_t e = 0; e < grid.size(); ++e) {
        EXPECT_NEAR(a[e], direct[e], 1e-13 * scale);
        EXPECT_NEAR(b[e], direct[e], 1e-12 * scale);
        EXPECT_NEAR(mm[e], 2.0 * b[e] + 0.5 * m1[e], 1e-12 * scale);
      }
    }
  }
}

TEST(FlashTemperature, PartitionEqualisesTheTemperatures) {
  // A steel base under a bronze-like body, rolling with 10 % slip, Hertzian flux on a 31 x 25
  // grid.
  const Grid grid = Grid::make(3, 31, 25, -1.2e-3, 1.2e-3, -1e-3, 1e-3);
  std::vector<double> q(grid.size(), 0.0);
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double r2 = (grid.xc(i) * grid.xc(i) + grid.yc(j) * grid.yc(j)) / 1e-6;
      if (r2 < 1.0) q[grid.index(i, j)] = 1e8 * std::sqrt(1.0 - r2);
    }
  const ThermalSurface base{dc::ThermalProperties::make(45.0, 1.2e-5, "base"), 2.0};
  const ThermalSurface body{dc::ThermalProperties::make(60.0, 1.8e-5, "body"), 2.2};
  const FlashTemperature ft(grid, base, body);
  const auto mean_rule = ft.compute(q, {HeatPartition::Rule::equal_mean});
  EXPECT_NEAR(mean_rule.base_mean, mean_rule.body_mean, 1e-12 * mean_rule.base_mean);
  EXPECT_GT(mean_rule.base_fraction, 0.0);
  EXPECT_LT(mean_rule.base_fraction, 1.0);
  const auto max_rule = ft.compute(q, {HeatPartition::Rule::equal_max});
  EXPECT_NEAR(max_rule.base_max, max_rule.body_max, 1e-12 * max_rule.base_max);
  const auto fixed = ft.compute(q, {HeatPartition::Rule::fixed, 0.3});
  EXPECT_DOUBLE_EQ(fixed.base_fraction, 0.3);
  const std::vector<double> base_all = ft.surface_temperature(BodySide::base, q);
  const double hottest = *std::max_element(base_all.begin(), base_all.end());
  for (std::size_t e = 0; e < grid.size(); ++e) EXPECT_NEAR(fixed.base[e], 0.3 * base_all[e], 1e-14 * hottest);
  const auto pointwise = ft.compute(q, {HeatPartition::Rule::pointwise});
  double worst = 0.0;
  for (std::size_t e = 0; e < grid.size(); ++e)
    if (q[e] > 0.0) worst = std::max(worst, std::abs(pointwise.base[e] - pointwise.body[e]));
  std::printf("partition: equal mean f = %.4f, equal max f = %.4f, pointwise f = %.4f (|T_base - T_body| %.1e of %.3g K)\n",
              mean_rule.base_fraction, max_rule.base_fraction, pointwise.base_fraction, worst, pointwise.base_max);
  EXPECT_LT(worst, 1e-9 * pointwise.base_max);
  // The matrix-free path (GMRES on the operators, 1e-12 residual) meets the dense solve.
  HeatPartition krylov{HeatPartition::Rule::pointwise};
  krylov.dense_limit = 0;
  const auto iterative = ft.compute(q, krylov);
  for (std::size_t e = 0; e < grid.size(); ++e)
    EXPECT_NEAR(iterative.base[e], pointwise.base[e], 1e-8 * pointwise.base_max);
  // The heat is conserved: the fractions of the flux sum to the pointwise total.
  double into_base = 0.0;
  for (std::size_t e = 0; e < grid.size(); ++e) into_base += pointwise.base_flux_fraction[e] * q[e] * grid.area();
  EXPECT_NEAR(into_base / pointwise.total_heat, pointwise.base_fraction, 1e-12);
  // Identical surfaces share half and half, pointwise too.
  const FlashTemperature same(grid, base, base);
  const auto half = same.compute(q, {HeatPartition::Rule::pointwise});
  for (std::size_t e = 0; e < grid.size(); ++e) {
    if (q[e] > 0.0) {
      EXPECT_NEAR(half.base_flux_fraction[e], 0.5, 1e-10);
    }
  }
  EXPECT_NEAR(same.compute(q).base_fraction, 0.5, 1e-14);
}

TEST(FlashTemperature, PointwisePartitionOnALargeGrid) {
  // 72 x 72 (FFT operators), a uniform circle of about 4000 heated elements: beyond the dense
  // limit, GMRES. Equal temperatures on every heated element to the residual's 1e-12 (of |b| in
  // the 2-norm; 1e-10 of the maximum pointwise allows its spread over ~4000 elements).
  const Grid grid = Grid::make(3, 72, 72, -1.0, 1.0, -1.0, 1.0);
  std::vector<double> q(grid.size(), 0.0);
  std::size_t heated = 0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      if (grid.xc(i) * grid.xc(i) + grid.yc(j) * grid.yc(j) < 1.0) {
        q[grid.index(i, j)] = 1.0;
        ++heated;
      }
  ASSERT_GT(heated, HeatPartition{}.dense_limit);
  const FlashTemperature ft(grid, surface_at(5.0, 1.0), ThermalSurface{{2.0, 0.5}, 0.0});
  ASSERT_EQ(ft.kind(), "fft");
  const auto r = ft.compute(q, {HeatPartition::Rule::pointwise});
  double worst = 0.0;
  for (std::size_t e = 0; e < grid.size(); ++e)
    if (q[e] > 0.0) worst = std::max(worst, std::abs(r.base[e] - r.body[e]));
  std::printf("pointwise partition, %zu heated elements: f = %.4f, |T_base - T_body| %.1e of %.3g\n", heated,
              r.base_fraction, worst, r.base_max);
  EXPECT_LT(worst, 1e-10 * r.base_max);
}

TEST(FlashTemperature, PartitionAtHighPecletFollowsBlok) {
  // Both surfaces at high Pe: T_s ~ f_s / (K_s sqrt(V_s / kappa_s)) (B3), so equal means give
  // Blok's share f_base = e_base / (e_base + e_body), e = K sqrt(V / kappa), to the O(1/Pe) of
  // the 1-D limit. 2-D band of 400 strips, Pe 250 and 1000.
  const Grid grid = Grid::make(2, 400, 1, -1.0, 1.0, 0.0, 1.0);
  const std::vector<double> q(grid.size(), 1.0);
  const ThermalSurface base{{45.0, 1.2e-5}, 2.0 * 250.0 * 1.2e-5}, body{{15.0, 4e-6}, 2.0 * 1000.0 * 4e-6};
  const FlashTemperature ft(grid, base, body);
  const double eb = 45.0 * std::sqrt(base.speed / 1.2e-5), ed = 15.0 * std::sqrt(body.speed / 4e-6);
  const double f = ft.compute(q).base_fraction;
  std::printf("high-Pe partition: %.6f (Blok %.6f)\n", f, eb / (eb + ed));
  EXPECT_NEAR(f, eb / (eb + ed), 1.0 / 250.0);
}

TEST(FlashTemperature, BadInputNamesTheKey) {
  const Grid line = Grid::make(2, 10, 1, -1.0, 1.0, 0.0, 1.0);
  const Grid plane = Grid::make(3, 6, 6, -1.0, 1.0, -1.0, 1.0);
  const auto key_of = [](const auto& make) {
    try {
      make();
    } catch (const dc::InputError& e) {
      return e.key();
    }
    return std::string("none");
  };
  EXPECT_EQ(key_of([&] { FlashTemperature(plane, ThermalSurface{{0.0, 1.0}, 1.0}, surface_at(1.0, 1.0)); }),
            "base.conductivity");
  EXPECT_EQ(key_of([&] { FlashTemperature(plane, surface_at(1.0, 1.0), ThermalSurface{{1.0, -2.0}, 1.0}); }),
            "body.diffusivity");
  EXPECT_EQ(key_of([&] { FlashTemperature(line, surface_at(1.0, 1.0), surface_at(0.0, 1.0)); }), "body.speed");
  EXPECT_EQ(key_of([&] { FlashTemperature(plane, ThermalSurface{{1.0, 1.0}, std::nan("")}, surface_at(1.0, 1.0)); }),
            "base.speed");
  EXPECT_EQ(key_of([&] {
              FlashTemperature(line, surface_at(1.0, 1.0), surface_at(0.0, 1.0), dc::OperatorKind::automatic,
                               "materials.base", "materials.body");
            }),
            "materials.body.speed");
  const FlashTemperature ft(plane, surface_at(1.0, 1.0), surface_at(0.0, 1.0));
  std::vector<double> q(plane.size(), 1.0);
  EXPECT_EQ(key_of([&] { ft.compute(q, {HeatPartition::Rule::fixed, 1.5}); }), "partition");
  q[3] = -1.0;
  EXPECT_THROW(ft.compute(q), std::invalid_argument);
  EXPECT_THROW(ft.compute(std::vector<double>(5, 1.0)), std::invalid_argument);
  // No heat: zero temperatures.
  const auto none = ft.compute(std::vector<double>(plane.size(), 0.0));
  EXPECT_EQ(none.base_max, 0.0);
  EXPECT_EQ(none.body_max, 0.0);
}

}  // namespace flash_temperature_tests
