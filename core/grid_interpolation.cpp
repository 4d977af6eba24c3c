#include "grid_interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dc {
namespace {

/// The lower neighbour's index and the weight of the upper one at coordinate u (in element
/// units from the first centre); false outside the grid.
bool bracket(double u, int n, int& i, double& w) {
  if (u < -0.5 || u > n - 0.5) return false;
  const double c = std::clamp(u, 0.0, static_cast<double>(n - 1));
  i = std::min(static_cast<int>(std::floor(c)), std::max(n - 2, 0));
  w = n > 1 ? c - i : 0.0;
  return true;
}

}  // namespace

std::vector<double> interpolate_to_grid(const Grid& from, const std::vector<double>& values, const Grid& to) {
  if (values.size() != from.size()) throw std::invalid_argument("interpolate_to_grid: one value per element");
  std::vector<double> out(to.size(), 0.0);
  const bool three_d = from.dimension == 3 && to.dimension == 3;
  for (int j = 0; j < to.ny; ++j)
    for (int i = 0; i < to.nx; ++i) {
      int ix = 0, iy = 0;
      double wx = 0.0, wy = 0.0;
      if (!bracket((to.xc(i) - from.x0) / from.dx - 0.5, from.nx, ix, wx)) continue;
      if (three_d && !bracket((to.yc(j) - from.y0) / from.dy - 0.5, from.ny, iy, wy)) continue;
      const int ix1 = std::min(ix + 1, from.nx - 1), iy1 = three_d ? std::min(iy + 1, from.ny - 1) : 0;
      auto at = [&](int a, int b) { return values[from.index(a, b)]; };
      out[to.index(i, j)] = (1 - wy) * ((1 - wx) * at(ix, iy) + wx * at(ix1, iy)) +
                            wy * ((1 - wx) * at(ix, iy1) + wx * at(ix1, iy1));
    }
  return out;
}

}  // namespace dc
