#pragma once
// The "accuracy" block (CASES.md): the discretisation error estimate every static answer carries,
// and the accuracy a user may ask for instead of a grid (docs/accuracy.md).
#include <optional>
#include <string>
#include <vector>

namespace dc {

struct AccuracySpec {
  /// accuracy.estimate: solve again on grids of 2 and 4 times the element size and report the
  /// estimated error of each result. Default on for the static problems (normal, tangential:
  /// it costs about 1/4 + 1/16 of the solve in 3-D; the 2-D solves are cheap whatever their share);
  /// off for dynamic runs (each coarse grid runs the whole run again: docs/accuracy.md).
  bool estimate = true;
  /// accuracy.target: the largest relative error of each named quantity; the grid is refined
  /// (from a grid sized by the closed-form contact, grid.nx/ny optional) until it is met or a
  /// budget stops it.
  std::optional<double> target;
  /// accuracy.quantities: the results the target applies to (names of summary.json keys, e.g.
  /// "max_pressure", "tangential_force", "Fx"; a dynamic run's peaks, e.g. "max_normal_force",
  /// "contact_time"); default: max_pressure (dynamic: max_normal_force).
  std::vector<std::string> quantities;
  /// accuracy.max_elements: the finest grid allowed (2048 x 2048: a 3-D contact area converges at
  /// first order, and its 1e-3 took 1536 x 1536, 18 s and 0.85 GB on a Hertz sphere); the memory
  /// the machine has available stops the refinement first where it is smaller (max_memory).
  long long max_elements = 4194304;
  double max_seconds = 600.0;        ///< accuracy.max_seconds: the refinement's wall-clock budget
};

}  // namespace dc

namespace dc {

/// The quantities an accuracy block may name, with the problems that have them.
struct AccuracyQuantityName {
  const char* name;
  bool normal;      ///< a normal problem's result (tangential problems have these too)
  bool tangential;  ///< a tangential problem's
  bool dynamic;     ///< a dynamic run's (summary.json "peaks")
};
const std::vector<AccuracyQuantityName>& accuracy_quantity_names();

}  // namespace dc
