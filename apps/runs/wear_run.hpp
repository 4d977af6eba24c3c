#pragma once
// Wear that changes the profile (CASES.md "wear", docs/wear_energy.md "Wear"): a shift or
// torsion history's steps are one load cycle, repeated wear.cycles times. The grid does not
// move, so each worn body's depth is a map on it and both add to the gap (2.6). An outer loop
// around the history: solve the cycle on the current gap, sum its wear map (core/wear_law.hpp),
// extrapolate it over n cycles (cycle jumping: n bounded by wear.update), add it to the worn
// depth and update the gap, until every cycle is done. The steps before wear.cycle_from_step
// (the first loading) are solved once, at the start, their wear added once.
// Steady rolling: a cycle is one pass (one revolution of the body, rolling_radius R), one steady
// solve; every point of the track at lateral y passes the whole contact, so both bodies' maps
// are uniform along x (rolling_pass_depth), their volumes over a travel of 2 pi R per cycle.
#include "tangential_run.hpp"

namespace dc::runs {

/// Solves case `c` (c.wear set) as above: the summary of the last cycle solved (its steps, on the
/// gap before the last update) with "wear" added, its fields, and each body's worn depth.
StaticRun run_wear(const Case& c, bool progress);

}  // namespace dc::runs
