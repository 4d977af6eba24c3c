#pragma once
// The error estimate of a normal solve given by element heights alone (Python's NormalProblem,
// docs/accuracy.md "Problems given by their heights"): the same load solved again on grids of 2
// and 4 times the element size over the same bounds, their heights the given ones carried to the
// coarse centres (core/height_restriction.hpp: exact for a profile cubic along each axis), and
// the results estimated as a case's are (accuracy_estimate.hpp): summary.json's accuracy block.
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "material.hpp"
#include "normal_problem.hpp"
#include "operator_kind.hpp"

namespace dc::runs {

/// The coarse problems of one fine grid, set up on the first estimate and kept for the next
/// (a problem solved many times: each estimate's coarse solves start from the last ones).
class HeightsAccuracy {
 public:
  HeightsAccuracy(const Grid& grid, const MaterialPair& materials, OperatorKind kind);
  ~HeightsAccuracy();
  HeightsAccuracy(const HeightsAccuracy&) = delete;
  HeightsAccuracy& operator=(const HeightsAccuracy&) = delete;

  /// The accuracy block of `fine` (solved on the grid with `heights`, `load`, `solver` in
  /// `fine_seconds`). Unavailable (the block says why) in 2-D (its estimate needs shifted grids),
  /// when the solve did not converge, an axis has an odd number of elements, or the coarser grid
  /// would have fewer than 6 elements across the contact. Its cost_fraction counts the coarse
  /// problems' set-up when they are made.
  nlohmann::json estimate(const std::vector<double>& heights, const NormalSpec& load, const SolverOptions& solver,
                          const NormalSolution& fine, double fine_seconds);

 private:
  struct Level;
  Grid grid_;
  MaterialPair materials_;
  OperatorKind kind_;
  std::vector<std::unique_ptr<Level>> levels_;  // 2h, 4h as made
};

}  // namespace dc::runs
