#pragma once
// The undeformed gap (2.6) of a body turned about z (dynamic problems: the body's heading).
#include <vector>

#include "grid.hpp"
#include "profile.hpp"

namespace dc {

/// profile_heights() for a body turned by `heading` (rad) about z (3-D; ignored in 2-D): the
/// profile is evaluated in the body's axes, Rz(-heading) (x, y).
std::vector<double> profile_heights(const ProfileSpec& profile, const Grid& grid, double heading);
/// The same into `heights` (resized to the grid; no allocation when it already has that size).
void profile_heights(const ProfileSpec& profile, const Grid& grid, double heading, std::vector<double>& heights);

}  // namespace dc
