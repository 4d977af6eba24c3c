#pragma once
// Fatigue over a run in time (CASES.md "fatigue"): Dang Van's criterion (core/dang_van.hpp) on
// the stress history of a body's material points over the run's states (subsurface_series.hpp):
// a dynamic run's snapshots (the base), or the steps of a shift or torsion loading history
// (either body; the grid does not move, so each point is an element centre: fretting under a
// cyclic load, one cycle given as the steps). In a dynamic run the contact grid follows the body (its origin under the
// centre of mass), so a point fixed in the base at (X, Y, depth) sees at a snapshot the field at
// (X - x_body, Y - y_body): interpolated bilinearly between the element centres, zero off the
// grid (the grid encloses the contact: a point off it is unloaded). The points are the element
// centres of the grid's positions over the run (the base's track, spacing dx, dy). A point's
// path holds every snapshot, so memory grows as points x depths x snapshots: beyond
// kMaxPathEntries the index is not computed (a note says so: raise output.snapshot_every or
// give fewer depths).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "subsurface_series.hpp"
#include "voigt_stress.hpp"

namespace dc::runs {

class FatigueOverRun {
 public:
  /// Voigt entries kept at most (6 doubles each: 2e6 are 96 MB).
  static constexpr std::size_t kMaxPathEntries = 2'000'000;

  /// The points of `body` ("base" or "body", with its spec) over the track of `states` (their
  /// grid offsets) at `depths`.
  FatigueOverRun(std::string body, const FatigueSpec& spec, const Grid& grid, const std::vector<double>& depths,
                 const std::vector<SubsurfaceState>& states);
  /// Appends the body's field of `run` at state `s` to every point's path.
  void add(const SubsurfaceState& s, const SubsurfaceRun& run);
  /// summary.json's "fatigue" entry of the body: {dang_van_max, at [X, Y, depth] (world), alpha,
  /// beta, orthogonal_shear_range, at_orthogonal_range, snapshots, points, frame} or a "note".
  nlohmann::json to_json() const;
  const std::string& body() const { return body_; }

 private:
  std::string body_;
  FatigueSpec spec_;
  Grid grid_;
  std::vector<double> depths_;
  std::vector<double> xs_, ys_;  ///< the points' world coordinates along x and y
  std::vector<std::vector<Voigt>> paths_;  ///< per (depth, y, x) point
  std::string note_;
};

}  // namespace dc::runs
