#pragma once
// A rough estimate of the memory and time of a static case before it is solved (`validate`),
// from the grid size and the operator kind the solver will pick.
#include <string>

#include "case_model.hpp"

namespace dc::runs {

struct ResourceEstimate {
  std::string operator_kind;  ///< "dense" or "fft" (what solver.operator / auto gives)
  double memory_bytes = 0.0;  ///< the compliance operators and the solver's work vectors
  double seconds = 0.0;       ///< one normal (+ tangential) solve by the native solver
  int solves = 1;             ///< solves of the case (history steps; 1 otherwise)
  std::string basis;          ///< how it was estimated, for the user
};

ResourceEstimate estimate_resources(const Case& c);
/// The same case on another grid (an accuracy refinement's next grid), without copying the case.
ResourceEstimate estimate_resources(const Case& c, const Grid& grid);

/// The memory this process may use (bytes): the smaller of MemAvailable and RLIMIT_AS
/// (+infinity when neither is known).
double available_memory_bytes();

/// True when the case on `grid` (its estimate_resources memory, twice over: the estimate is
/// within a factor of a few, and a refinement keeps the coarser grids' answers) fits in
/// `available_bytes`: the accuracy refinement's memory budget (stopped_by "max_memory").
bool grid_fits_in_memory(const Case& c, const Grid& grid, double available_bytes);

}  // namespace dc::runs
