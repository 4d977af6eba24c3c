#pragma once
// The "wear" block (CASES.md): a local wear law (core/wear_law.hpp) applied over a repeated
// load cycle of a shift or torsion history, the worn depth added to the gap (2.6) between
// profile updates (apps/runs/wear_run.hpp).
#include <vector>

#include "wear_law.hpp"

namespace dc {

struct WearSpec {
  WearLaw law;
  bool base = true, body = true;  ///< wear.bodies: the bodies that wear (default both)
  long long cycles = 1;           ///< wear.cycles: how many times the cycle is run (>= 1)
  /// wear.update: the profile is updated after at most `update_cycles` cycles (0: no bound) and
  /// after at most the cycles that wear `update_max_depth` (m) at the deepest element (0: no
  /// bound); neither given: after every cycle.
  long long update_cycles = 0;
  double update_max_depth = 0.0;
  /// wear.cycle_from_step (project extension): the history's steps before it are solved once
  /// (the first loading), those from it on form the repeated cycle. Default 0: every step.
  int cycle_from_step = 0;
};

}  // namespace dc
