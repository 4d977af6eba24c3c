#pragma once
// A static run with its discretisation error (issue 28, docs/accuracy.md): the case solved on
// its grid and again on grids of 2 and 4 times the element size (the same bounds), each result's
// error estimated by Richardson extrapolation or bounded by a band (core/discretisation_error.hpp),
// and, with accuracy.target, the grid refined (and its extent grown where the contact reaches
// the edge) until the named results meet the target or a budget stops it.
#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "grid.hpp"

namespace dc::runs {

struct StaticRun;

/// The grid of `g`'s bounds with round(n / factor) elements along each axis (at least 1).
Grid coarsened(const Grid& g, int factor);

/// The grid of `g`'s bounds with `factor` times the elements along each axis.
Grid refined(const Grid& g, int factor);

/// The accuracy block's lines on stdout: the grids, each result's estimated relative error, the
/// target and whether it was met.
void print_accuracy(const nlohmann::json& accuracy);

/// run_static_once (tangential_run.hpp) on the case's grid, or on the grids the target asks
/// for, with summary["accuracy"] (CASES.md) when c.accuracy.estimate. The run returned is that
/// of the finest grid solved; its `grid` says which.
StaticRun run_static_with_accuracy(const Case& c, bool progress);

/// True when the summary's accuracy block holds a target that was not met (exit 3).
bool accuracy_target_missed(const nlohmann::json& summary);
/// "the target 0.001 was not met (stopped by max_seconds on {"nx":6144}; largest estimate:
/// contact_half_width 0.00024)": the summary's accuracy block of a missed target, in words.
std::string missed_target_message(const nlohmann::json& accuracy);

}  // namespace dc::runs
