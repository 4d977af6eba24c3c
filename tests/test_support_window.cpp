// The tangential program posed on a window of the grid that holds f(p) > 0: the window's
// compliance is the grid's restricted to it (translation invariance), and a loading history
// solved on windows reaches the states of the whole grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "fft_planning.hpp"
#include "support_window.hpp"
#include "tangential_support.hpp"

namespace dc {
namespace {

/// A window's side: the widest whose FFT box (fft_fast_size(2 n - 1)) is the support's own, or
/// the grid's side.
int widest_side_of_box(int extent, int n) {
  const int box = fft_fast_size(2 * std::max(extent, std::min(8, n)) - 1);
  return std::min(n, (box + 1) / 2);
}

TEST(SupportWindow, HoldsTheSupportInTheWidestRectangleOfItsFftBox) {
  const Grid g = Grid::make(3, 60, 50, 0.0, 6.0, 0.0, 5.0);
  std::vector<double> f(g.size(), 0.0);
  EXPECT_EQ(support_window(g, f).nx, 0) << "no support, no window";
  // Support: elements 7..19 along x, 45..49 along y (at the grid's edge).
  for (int j = 45; j < 50; ++j)
    for (int i = 7; i < 20; ++i) f[g.index(i, j)] = 1.0;
  const SupportWindow w = support_window(g, f);
  ASSERT_GT(w.nx, 0);
  EXPECT_EQ(w.nx, widest_side_of_box(13, 60));
  EXPECT_EQ(w.ny, widest_side_of_box(5, 50));
  EXPECT_EQ(fft_fast_size(2 * w.nx - 1), fft_fast_size(2 * 13 - 1)) << "the support's transform, no longer";
  EXPECT_LE(w.i0, 7);
  EXPECT_GE(w.i0 + w.nx, 20);
  EXPECT_LE(w.j0, 45);
  EXPECT_EQ(w.j0 + w.ny, 50) << "the window stays inside the grid";
  EXPECT_GE(w.i0, 0);
  std::size_t held = 0;
  for (std::size_t l = 0; l < w.size(); ++l) held += f[w.global(g, l)] > 0.0;
  EXPECT_EQ(held, 13u * 5u) << "every element of the support is in the window";
  const Grid wg = w.grid_of(g);
  EXPECT_DOUBLE_EQ(wg.xc(0), g.xc(w.i0));
  EXPECT_DOUBLE_EQ(wg.yc(0), g.yc(w.j0));
  // A support spread over most of the grid: no window.
  f[g.index(59, 0)] = 1.0;
  EXPECT_EQ(support_window(g, f).nx, 0);
}

TEST(SupportWindow, AGrowingSupportMeetsFewWindowSizesAndTheCacheStaysBounded) {
  // A support growing element by element along x of a 400^2 grid: the windows' sides take few
  // values (a history builds few operators), each at least the support and at most 30 % wider
  // than it beyond the smallest sides.
  const Grid g = Grid::make(3, 400, 400, -1.0, 1.0, -1.0, 1.0);
  std::vector<double> f(g.size(), 0.0);
  std::vector<int> sides;
  for (int extent = 1; extent <= 300; ++extent) {
    f[g.index(50 + extent - 1, 200)] = 1.0;
    const SupportWindow w = support_window(g, f);
    ASSERT_GT(w.nx, 0) << extent;
    EXPECT_GE(w.nx, extent);
    if (extent >= 16) {
      EXPECT_LE(w.nx, 1.3 * extent) << extent;
    }
    EXPECT_EQ(w.ny, 8) << "the smallest side";
    if (sides.empty() || sides.back() != w.nx) sides.push_back(w.nx);
  }
  EXPECT_LE(sides.size(), 20u);
  EXPECT_TRUE(std::is_sorted(sides.begin(), sides.end()));
  // The kept operators never hold more than three grids' elements: on a 40^2 grid (1600),
  // five window sizes of 5504 elements in all.
  const Grid small = Grid::make(3, 40, 40, -1.0, 1.0, -1.0, 1.0);
  const MaterialPair m{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)};
  WindowedCompliance windows(small, m, OperatorKind::fft);
  std::size_t most = 0;
  for (const auto& [nx, ny] : {std::pair{40, 32}, {32, 40}, {40, 24}, {24, 40}, {32, 32}}) {
    windows.operators(SupportWindow{0, 0, nx, ny});
    most = std::max(most, windows.elements_kept());
  }
  EXPECT_LE(most, 3 * small.size());
  EXPECT_GE(windows.elements_kept(), 1024u) << "the last window is kept";
}

/// The window's operator against the grid's, for a field supported in the window.
void expect_restriction(const Grid& g, const MaterialPair& m, const SupportWindow& w) {
  const HalfSpace hs(g, m);
  const auto full = hs.tangential(OperatorKind::fft);
  WindowedCompliance windows(g, m, OperatorKind::fft);
  const LinearOperator& part = windows.tangential(w);
  const int comps = g.dimension == 2 ? 1 : 2;
  const std::size_t N = g.size(), Nw = w.size();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> xw(comps * Nw), x(comps * N, 0.0), yw, y;
  for (std::size_t l = 0; l < Nw; ++l)
    for (int c = 0; c < comps; ++c) x[c * N + w.global(g, l)] = xw[c * Nw + l] = u(rng);
  part.apply(xw, yw);
  full->apply(x, y);
  double scale = 0.0, err = 0.0;
  for (std::size_t l = 0; l < Nw; ++l)
    for (int c = 0; c < comps; ++c) {
      scale = std::max(scale, std::abs(y[c * N + w.global(g, l)]));
      err = std::max(err, std::abs(yw[c * Nw + l] - y[c * N + w.global(g, l)]));
    }
  EXPECT_LE(err, 1e-12 * scale) << "dimension " << g.dimension;
}

TEST(SupportWindow, WindowCompliesAsTheGridRestrictedToIt) {
  const MaterialPair m{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(7e10, 0.2)};
  expect_restriction(Grid::make(3, 40, 34, -2.0, 2.0, -1.0, 2.4), m, SupportWindow{5, 9, 16, 8});
  // 2-D: the logarithmic kernels keep the whole grid's reference length.
  expect_restriction(Grid::make(2, 70, 1, -3.5, 3.5, 0.0, 1.0), m, SupportWindow{30, 0, 24, 1});
}

TEST(SupportWindow, HistoryOnWindowsReachesTheStatesOfTheWholeGrid) {
  // A rigid sphere pressed into an elastic body (kappa != 0) on a grid three times the final
  // contact's width, loaded in three steps, then a tangential force (x and y) held by the rows:
  // the programs on windows (smaller than the grid until the last steps) and on the grid agree.
  const MaterialPair m{Elastic::make_rigid(), Elastic::from_E_nu(7e10, 0.1)};
  ASSERT_NE(m.kappa(), 0.0);
  const double P = 100.0, mu = 0.3;
  const test::SphereSetup su = test::sphere_setup(48, 3.0, m, 0.01, P);
  TangentialProblem windowed(su.grid, m, su.heights, FrictionLaw::coulomb(mu));
  TangentialProblem whole(su.grid, m, su.heights, FrictionLaw::coulomb(mu));
  whole.set_windowing(false);
  const SolverOptions solver = test::native_tangential_solver();
  TangentialLoad load;
  load.modes = {test::resultant(0.0), test::resultant(0.0), test::amplitude(0.0)};
  for (int k = 1; k <= 3; ++k) {
    load.normal = {Control::force, P * k / 3.0};
    const TangentialSolution a = windowed.step(load, solver), b = whole.step(load, solver);
    test::expect_certified(a);
    test::expect_certified(b);
    test::expect_same_state(a, b, "indentation step " + std::to_string(k));
  }
  load.modes = {test::resultant(0.4 * mu * P), test::resultant(-0.2 * mu * P), test::resultant(0.0)};
  const TangentialSolution a = windowed.step(load, solver), b = whole.step(load, solver);
  test::expect_certified(a);
  EXPECT_GT(a.n_slip, 0) << "a partial slip state";
  test::expect_same_state(a, b, "tangential force");
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(a.amplitudes[k], b.amplitudes[k], 1e-5 * std::abs(b.amplitudes[k])) << "shift " << k;
}

}  // namespace
}  // namespace dc
