#pragma once
// Solving a normal case for the command line: progress, fields, summary.
#include <string>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "normal_problem.hpp"
#include "static_fields.hpp"

namespace dc::runs {

struct NormalRun {
  NormalSolution solution;
  output::StaticFields fields;
  nlohmann::json summary;  ///< summary.json content (without "files")
  bool converged() const { return solution.report.status == SolveStatus::converged; }
};

/// Solves with dc::solve_normal_case, a progress line on stderr when `progress` and the
/// solve takes over a second.
/// `warm_pressure`: the solve's start (one pressure per element), else cold.
NormalRun run_normal(const Case& c, bool progress, const std::vector<double>* warm_pressure = nullptr);

}  // namespace dc::runs
