// Element heights carried to the grid of twice the element size (core/height_restriction.hpp):
// the coarse heights of a profile cubic along each axis are its values at the coarse centres to
// round-off (interior and edge stencils alike), a smooth profile's to fourth order; +inf (cannot
// touch) spreads only to the coarse elements it covers; odd or short axes have no coarse grid.
// The height detail the coarse grid does not carry (unresolved_height) is zero on cubics, falls at
// fourth order on a smooth profile, and is the stencil's exact response on a waviness.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "height_restriction.hpp"

namespace dc {
namespace {

std::vector<double> sampled(const Grid& g, double (*f)(double, double)) {
  std::vector<double> h(g.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) h[g.index(i, j)] = f(g.xc(i), g.yc(j));
  return h;
}

double cubic(double x, double y) { return 0.3 + x * x - 0.7 * x * x * x + 2.0 * y * y + 0.4 * y * y * y + 0.2 * x * y; }
double smooth(double x, double y) { return std::cos(1.3 * x) * std::exp(0.4 * y); }

TEST(HeightRestriction, ACubicProfileIsExactAtTheCoarseCentres) {
  const Grid fine = Grid::make(3, 16, 12, -1.0, 1.0, -0.5, 1.0);
  const auto coarse = restrict_heights(fine, sampled(fine, cubic));
  ASSERT_TRUE(coarse);
  EXPECT_EQ(coarse->grid.nx, 8);
  EXPECT_EQ(coarse->grid.ny, 6);
  EXPECT_DOUBLE_EQ(coarse->grid.x0, fine.x0);
  EXPECT_DOUBLE_EQ(coarse->grid.y_max(), fine.y_max());
  const std::vector<double> exact = sampled(coarse->grid, cubic);
  for (std::size_t e = 0; e < exact.size(); ++e) EXPECT_NEAR(coarse->heights[e], exact[e], 1e-13) << e;
}

TEST(HeightRestriction, ASmoothProfileConvergesAtFourthOrder) {
  double error[2];
  for (int k = 0; k < 2; ++k) {
    const int n = 16 << k;
    const Grid fine = Grid::make(3, n, n, -1.0, 1.0, -1.0, 1.0);
    const auto coarse = restrict_heights(fine, sampled(fine, smooth));
    const std::vector<double> exact = sampled(coarse->grid, smooth);
    error[k] = 0.0;
    for (std::size_t e = 0; e < exact.size(); ++e) error[k] = std::max(error[k], std::abs(coarse->heights[e] - exact[e]));
  }
  EXPECT_NEAR(std::log2(error[0] / error[1]), 4.0, 0.3);
}

TEST(HeightRestriction, CannotTouchSpreadsOnlyWhereItCovers) {
  // h = x^2 at the centres 0.5, 1.5, ..., 7.5, the second element unable to touch: the coarse
  // element over it cannot touch; its neighbour's stencil meets it, so that one takes the mean of
  // its two (9.25, not x^2 = 9); the others are exact (the cubic, one-sided at the right edge).
  const Grid fine = Grid::make(2, 8, 1, 0.0, 8.0, 0.0, 0.0);
  std::vector<double> h(8);
  for (int i = 0; i < 8; ++i) h[static_cast<std::size_t>(i)] = fine.xc(i) * fine.xc(i);
  h[1] = HUGE_VAL;
  const auto coarse = restrict_heights(fine, h);
  ASSERT_TRUE(coarse);
  ASSERT_EQ(coarse->heights.size(), 4u);
  EXPECT_TRUE(std::isinf(coarse->heights[0]));
  EXPECT_NEAR(coarse->heights[1], 0.5 * (2.5 * 2.5 + 3.5 * 3.5), 1e-13);
  EXPECT_NEAR(coarse->heights[2], 25.0, 1e-13);
  EXPECT_NEAR(coarse->heights[3], 49.0, 1e-13);
}

TEST(HeightRestriction, OddOrShortAxesHaveNoCoarseGrid) {
  EXPECT_FALSE(restrict_heights(Grid::make(3, 15, 16, 0, 1, 0, 1), std::vector<double>(240, 0.0)));
  EXPECT_FALSE(restrict_heights(Grid::make(3, 16, 2, 0, 1, 0, 1), std::vector<double>(32, 0.0)));
  EXPECT_FALSE(restrict_heights(Grid::make(2, 2, 1, 0, 1, 0, 0), std::vector<double>(2, 0.0)));
}

TEST(HeightRestriction, TheDetailACoarseGridDoesNotCarryIsTheQuinticsCorrection) {
  const Grid fine = Grid::make(3, 32, 24, -1.0, 1.0, -0.5, 1.0);
  const std::vector<char> everywhere(fine.size(), 1), nowhere(fine.size(), 0);
  EXPECT_LT(unresolved_height(fine, sampled(fine, cubic), everywhere), 1e-14);
  EXPECT_EQ(unresolved_height(fine, sampled(fine, smooth), nowhere), 0.0);
  const Grid finer = Grid::make(3, 64, 48, -1.0, 1.0, -0.5, 1.0);
  const double ratio = unresolved_height(fine, sampled(fine, smooth), everywhere) /
                       unresolved_height(finer, sampled(finer, smooth), std::vector<char>(finer.size(), 1));
  EXPECT_NEAR(ratio, 16.0, 16.0 * 0.2);  // O(h^4)
  // A waviness of six elements along x, cos(pi x / (3 dx)) (midpoints at its crests): the
  // response 2 [3 cos(5 pi / 6) - 9 cos(pi / 2) + 6 cos(pi / 6)] / 256 = 3 sqrt(3) / 256.
  const Grid line = Grid::make(3, 48, 8, 0.0, 48.0, 0.0, 8.0);  // dx = 1
  std::vector<double> wave(line.size());
  for (int j = 0; j < line.ny; ++j)
    for (int i = 0; i < line.nx; ++i) wave[line.index(i, j)] = std::cos(M_PI * (line.xc(i) - 1.0) / 3.0);
  EXPECT_NEAR(unresolved_height(line, wave, std::vector<char>(line.size(), 1)), 3.0 * std::sqrt(3.0) / 256.0, 1e-14);
}

}  // namespace
}  // namespace dc
