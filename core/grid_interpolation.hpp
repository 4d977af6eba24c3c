#pragma once
// A field of element values (one per element, at the centres) carried to another grid:
// bilinear between the centres, the nearest centre's value up to the grid's edge, zero beyond it.
// Used to warm-start a solve on a refined grid from the coarser grid's answer.
#include <vector>

#include "grid.hpp"

namespace dc {

/// `values` (one per element of `from`) at the element centres of `to`.
std::vector<double> interpolate_to_grid(const Grid& from, const std::vector<double>& values, const Grid& to);

}  // namespace dc
