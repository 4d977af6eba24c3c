#pragma once
// summary.json (contract: shared spec CASES.md, "Output: summary.json").
#include <string>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "normal_problem.hpp"
#include "static_fields.hpp"

namespace dc::output {

/// schema, name, problem, dimension and the grid/material description every summary has.
nlohmann::json summary_header(const Case& c);

/// The summary of a solved normal case: header, solver{...}, normal_force, approach,
/// contact_area, max_pressure, n_contact, contact_half_width (2-D), and the analytic
/// reference ("hertz") with relative differences where a closed form applies.
nlohmann::json normal_summary(const Case& c, const NormalSolution& solution, const StaticFields& fields);

/// Writes `summary` as indented JSON to dir/summary.json; returns the path.
std::string write_summary(const std::string& dir, const nlohmann::json& summary);

}  // namespace dc::output
