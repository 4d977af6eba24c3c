#pragma once
// The "wear" block (CASES.md): a local wear law (core/wear_law.hpp) applied over a repeated
// load cycle of a shift or torsion history, or over repeated passes of steady rolling, the worn
// depth added to the gap (2.6) between profile updates (apps/runs/wear_run.hpp).
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
  /// Steady rolling: the body's rolling radius R (m; wear.rolling_radius, a project extension,
  /// default the profile's 1/(2A) of h ~ A x^2 + B y^2): a cycle is one revolution, a travel of
  /// 2 pi R, and the track is passed once per cycle. 0 for a history.
  double rolling_radius = 0.0;
  /// A dynamic run (wear.gap_feedback, a project extension, default true): the worn depth under
  /// the contact enters the gap (2.6) of the following steps; false: reported only.
  bool gap_feedback = true;
};

}  // namespace dc
