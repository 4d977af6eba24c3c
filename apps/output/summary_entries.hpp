#pragma once
// The summary.json entries of what the solvers report (CASES.md "solver", "limits"): a solve's
// report with its certificate and the backends tried, and the result limits.
#include <vector>

#include <nlohmann/json.hpp>

#include "contact_limits.hpp"
#include "solver_report.hpp"

namespace dc::output {

/// The certificate's residuals by name.
nlohmann::json to_json(const Certificate& certificate);

/// The `solver` object of summary.json.
nlohmann::json to_json(const SolverReport& report);

/// Summary entries: [{key, message, level ("error" or "warning"), accepted}]: a warning is
/// accepted only when a key of the case accepted it (grid.allow_edge_contact, ...).
nlohmann::json limits_json(const std::vector<ResultLimit>& limits);

}  // namespace dc::output
