// The row the worn profiles are drawn along (apps/output/wear_writer.hpp wear_row): through the
// wear's centroid across the grid. A scar symmetric about y = 0 keeps the row nearest y = 0 (the
// upper of the two on an even grid, as without wear) whatever the round-off of its centroid; a
// track worn off y = 0 is drawn through the track; no wear, the row nearest y = 0; 2-D, row 0.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "wear_writer.hpp"

namespace dc {
namespace {

TEST(WearRow, FollowsTheWornTrackAndKeepsTheCentreLineOfASymmetricScar) {
  const Grid g = Grid::make(3, 20, 16, -1.0, 1.0, -0.8, 0.8);  // dy = 0.1, y = 0 between rows 7 and 8
  std::vector<double> none(g.size(), 0.0), ring(g.size(), 0.0), track(g.size(), 0.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double r = std::hypot(g.xc(i), g.yc(j));
      if (r > 0.3 && r < 0.6) ring[g.index(i, j)] = 1e-6 * (0.1 + 0.3 * g.xc(i) * g.xc(i));  // even in y
      if (j == 12 || j == 13) track[g.index(i, j)] = (j == 12 ? 2e-6 : 1e-6);
    }
  EXPECT_EQ(output::wear_row(g, none, {}), 8);
  EXPECT_EQ(output::wear_row(g, ring, {}), 8);
  EXPECT_EQ(output::wear_row(g, {}, ring), 8);
  EXPECT_EQ(output::wear_row(g, track, {}), 12);  // centroid 1/3 of a row above row 12's centre
  EXPECT_EQ(output::wear_row(g, track, track), 12);
  EXPECT_EQ(output::wear_row(Grid::make(2, 20, 1, -1.0, 1.0, 0.0, 0.0), std::vector<double>(20, 1.0), {}), 0);
}

}  // namespace
}  // namespace dc
