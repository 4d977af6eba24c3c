// Element values carried to another grid (core/grid_interpolation.hpp): a linear field is
// reproduced between the centres, the edge keeps the nearest centre's value, outside is zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "grid.hpp"
#include "grid_interpolation.hpp"

namespace {

TEST(GridInterpolation, ReproducesALinearFieldOnARefinedGrid3d) {
  const dc::Grid coarse = dc::Grid::make(3, 8, 6, -1.0, 1.0, -0.5, 1.0);
  const dc::Grid fine = dc::Grid::make(3, 16, 12, -1.0, 1.0, -0.5, 1.0);
  auto f = [](double x, double y) { return 2.0 + 3.0 * x - 1.5 * y; };
  std::vector<double> v(coarse.size());
  for (int j = 0; j < coarse.ny; ++j)
    for (int i = 0; i < coarse.nx; ++i) v[coarse.index(i, j)] = f(coarse.xc(i), coarse.yc(j));
  const auto out = dc::interpolate_to_grid(coarse, v, fine);
  for (int j = 0; j < fine.ny; ++j)
    for (int i = 0; i < fine.nx; ++i) {
      const double x = fine.xc(i), y = fine.yc(j);
      // Between the first and last centres: exact; in the half element beyond: the nearest centre's.
      const double xi = std::clamp(x, coarse.xc(0), coarse.xc(coarse.nx - 1));
      const double yi = std::clamp(y, coarse.yc(0), coarse.yc(coarse.ny - 1));
      EXPECT_NEAR(out[fine.index(i, j)], f(xi, yi), 1e-12) << i << ", " << j;
    }
}

TEST(GridInterpolation, IsZeroOutsideTheSourceGrid2d) {
  const dc::Grid from = dc::Grid::make(2, 4, 1, 0.0, 1.0, 0.0, 0.0);
  const dc::Grid to = dc::Grid::make(2, 6, 1, -1.0, 2.0, 0.0, 0.0);  // elements of 0.5 centred at -0.75 ... 1.75
  const auto out = dc::interpolate_to_grid(from, {1.0, 2.0, 3.0, 4.0}, to);
  EXPECT_EQ(out[0], 0.0);
  EXPECT_EQ(out[1], 0.0);   // centre -0.25: beyond the half element
  EXPECT_NEAR(out[2], 1.0 + (0.25 - 0.125) / 0.25, 1e-12);
  EXPECT_NEAR(out[3], 3.0 + (0.75 - 0.625) / 0.25, 1e-12);
  EXPECT_EQ(out[5], 0.0);
  EXPECT_THROW(dc::interpolate_to_grid(from, {1.0}, to), std::invalid_argument);
}

}  // namespace
