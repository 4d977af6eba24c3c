#include "height_restriction.hpp"

#include <algorithm>
#include <cmath>

namespace dc {
namespace {

/// The height midway between fine centres k and k + 1 of a line of n values v(i).
template <typename At>
double midway(const At& v, int k, int n) {
  const double a = v(k), b = v(k + 1);
  if (std::isinf(a) || std::isinf(b)) return HUGE_VAL;
  double w[4];
  int first;
  if (k == 0) {
    first = 0;
    w[0] = 5.0, w[1] = 15.0, w[2] = -5.0, w[3] = 1.0;
  } else if (k + 1 == n - 1) {
    first = n - 4;
    w[0] = 1.0, w[1] = -5.0, w[2] = 15.0, w[3] = 5.0;
  } else {
    first = k - 1;
    w[0] = -1.0, w[1] = 9.0, w[2] = 9.0, w[3] = -1.0;
  }
  double sum = 0.0;
  for (int m = 0; m < 4; ++m) {
    const double value = v(first + m);
    if (std::isinf(value)) return 0.5 * (a + b);
    sum += w[m] * value;
  }
  return sum / 16.0;
}

}  // namespace

std::optional<RestrictedHeights> restrict_heights(const Grid& fine, const std::vector<double>& h) {
  const bool three_d = fine.dimension == 3;
  if (fine.nx < 4 || fine.nx % 2 != 0) return std::nullopt;
  if (three_d && (fine.ny < 4 || fine.ny % 2 != 0)) return std::nullopt;
  RestrictedHeights out;
  const int nx = fine.nx / 2, ny = three_d ? fine.ny / 2 : 1;
  out.grid = three_d ? Grid::make(3, nx, ny, fine.x0, fine.x_max(), fine.y0, fine.y_max())
                     : Grid::make(2, nx, 1, fine.x0, fine.x_max(), 0.0, 0.0);
  // Along x on every fine row, then along y on every coarse column.
  std::vector<double> rows(static_cast<std::size_t>(nx) * fine.ny);
  for (int j = 0; j < fine.ny; ++j)
    for (int i = 0; i < nx; ++i)
      rows[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j] =
          midway([&](int k) { return h[fine.index(k, j)]; }, 2 * i, fine.nx);
  if (!three_d) {
    out.heights = std::move(rows);
    return out;
  }
  out.heights.assign(out.grid.size(), 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      out.heights[out.grid.index(i, j)] =
          midway([&](int k) { return rows[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * k]; }, 2 * j, fine.ny);
  return out;
}

double unresolved_height(const Grid& fine, const std::vector<double>& h, const std::vector<char>& in_contact) {
  // Quintic minus cubic midpoint weights over the six nearest centres, /256: zero on cubics.
  constexpr double w[6] = {3.0, -9.0, 6.0, 6.0, -9.0, 3.0};
  double largest = 0.0;
  const auto along = [&](int n_along, int n_across, auto index) {
    for (int j = 0; j < n_across; ++j)
      for (int k = 2; k + 3 < n_along; k += 2) {
        if (!in_contact[index(k, j)] && !in_contact[index(k + 1, j)]) continue;
        double sum = 0.0;
        bool finite = true;
        for (int m = 0; m < 6 && finite; ++m) {
          const double v = h[index(k - 2 + m, j)];
          finite = std::isfinite(v);
          sum += w[m] * v;
        }
        if (finite) largest = std::max(largest, std::abs(sum) / 256.0);
      }
  };
  along(fine.nx, fine.ny, [&](int i, int j) { return fine.index(i, j); });
  if (fine.dimension == 3) along(fine.ny, fine.nx, [&](int j, int i) { return fine.index(i, j); });
  return largest;
}

}  // namespace dc
