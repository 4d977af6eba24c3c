#pragma once
// A dynamic run with its discretisation error (issue 28, docs/accuracy.md): the run on its grid
// and again on grids of 2 and 4 times the element size (the same bounds, the same time steps),
// the error of each peak (dynamic_peaks.hpp: the largest contact force and approach, the contact
// time, the rebound speed; the largest area as a band) estimated as for the static results; with
// accuracy.target the grid of the whole run refined by 2 or 4 until the named peaks meet it or a
// budget stops it. Opt-in (accuracy.estimate: true, or a target): every coarse grid runs the
// whole run again.
#include <functional>

#include "case_model.hpp"
#include "dynamic_run.hpp"

namespace dc::runs {

/// simulate_dynamic, with summary["accuracy"] when c.accuracy.estimate. The outcome is that of
/// the finest grid run (summary "grid" and "accuracy.grid" say which). `on_step` sees the steps
/// of that run only: with a target, the chosen grid is run once more for it, and `on_step_grid`
/// (when given) is set to that grid before.
DynamicOutcome simulate_dynamic_with_accuracy(const Case& c, bool progress,
                                              const std::function<void(const dynamics::DynamicSample&)>& on_step = {},
                                              Grid* on_step_grid = nullptr);

}  // namespace dc::runs
