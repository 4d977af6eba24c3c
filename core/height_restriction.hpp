#pragma once
// Element heights (the undeformed gap at the element centres) carried to the grid of twice the
// element size over the same bounds, for an error estimate of a problem given by its heights
// alone (no profile to sample again: Python's NormalProblem). A coarse centre lies midway between
// two fine centres along each axis; there the height is the cubic through the four nearest
// (-1, 9, 9, -1)/16, one-sided (5, 15, -5, 1)/16 at the grid's edge: exact for a profile cubic
// along each axis (a sphere, an ellipsoid, a cylinder), fourth order for a smooth one. Where a
// neighbour is +inf (the body cannot touch) the two nearest are averaged; where one of those is
// +inf the coarse element cannot touch either.
#include <optional>
#include <vector>

#include "grid.hpp"

namespace dc {

struct RestrictedHeights {
  Grid grid;                   ///< nx / 2 (3-D: and ny / 2) elements over the same bounds
  std::vector<double> heights; ///< at its element centres (m)
};

/// None when an axis has an odd number of elements or fewer than 4 (3-D: either axis).
std::optional<RestrictedHeights> restrict_heights(const Grid& fine, const std::vector<double>& heights);

/// The height detail the grid of twice the element size does not carry where the body touches:
/// at every coarse midpoint beside a fine element with `in_contact` set, the quintic through the
/// six nearest fine centres (3, -25, 150, 150, -25, 3)/256 minus the cubic restrict_heights uses,
/// along x on the rows and along y on the columns; the largest magnitude (m). Zero for a profile
/// of degree 3 along each axis, O(h^4) of the fourth derivative for a smooth one, of the order
/// of the amplitude for waviness a few elements long (which the coarse grids alias). Midpoints
/// whose six centres are not all finite and on the grid are skipped.
double unresolved_height(const Grid& fine, const std::vector<double>& heights, const std::vector<char>& in_contact);

}  // namespace dc
