#pragma once
// The wrapped kernel of a translation-invariant compliance on a periodic mx x my box, from its
// response to a unit load at the grid centre: box offsets in (-m/2, m/2]; those beyond the grid
// take the value of the nearest offset the grid holds (a preconditioner needs the shape, not
// every digit). Shared by the FFT preconditioners (normal_preconditioner, tangential_preconditioner).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "grid.hpp"

namespace dc {

/// `response` holds the field of one output component at `offset` (N values per component);
/// the load sat at element (grid.nx / 2, grid.ny / 2). Returns mx * my values, x fastest.
inline std::vector<double> periodic_kernel_box(const std::vector<double>& response, std::size_t offset,
                                               const Grid& grid, int mx, int my) {
  const int ic = grid.nx / 2, jc = grid.ny / 2;
  std::vector<double> box(static_cast<std::size_t>(mx) * my);
  for (int bj = 0; bj < my; ++bj)
    for (int bi = 0; bi < mx; ++bi) {
      const int di = bi <= mx / 2 ? bi : bi - mx, dj = bj <= my / 2 ? bj : bj - my;
      const int i = std::clamp(ic + di, 0, grid.nx - 1), j = std::clamp(jc + dj, 0, grid.ny - 1);
      box[bi + static_cast<std::size_t>(mx) * bj] = response[offset + grid.index(i, j)];
    }
  return box;
}

}  // namespace dc
