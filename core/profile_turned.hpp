#pragma once
// The undeformed gap (2.6) of a body turned about z (dynamic problems: the body's heading).
#include <memory>
#include <vector>

#include "grid.hpp"
#include "profile.hpp"

namespace dc {

/// profile_heights() for a body turned by `heading` (rad) about z (3-D; ignored in 2-D): the
/// profile is evaluated in the body's axes, Rz(-heading) (x, y).
std::vector<double> profile_heights(const ProfileSpec& profile, const Grid& grid, double heading);
struct TableLattice;

/// A profile turned again and again (a dynamic body's heading): a table is read into its lattice
/// once, and the heights are written into the caller's buffer (no allocation once it has the
/// grid's size). Keeps references to `profile` and `grid`.
class TurnedProfile {
 public:
  TurnedProfile(const ProfileSpec& profile, const Grid& grid);
  ~TurnedProfile();
  /// profile_heights(profile, grid, heading) into `heights`.
  void heights(double heading, std::vector<double>& heights) const;

 private:
  const ProfileSpec& profile_;
  const Grid& grid_;
  std::unique_ptr<const TableLattice> table_;
};

}  // namespace dc
