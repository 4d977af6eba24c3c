#pragma once
// The result limits (nlp/contact_limits.hpp) of a static run from its summary.json, and their
// report on stderr.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "contact_limits.hpp"

namespace dc::runs {

/// The contact size of a solved static case from its summary (add_contact_measures keys).
ContactSize measured_contact_size(const Case& c, const nlohmann::json& summary);

/// Prints each limit to stderr (error: / warning:, errors saying that the results are in `dir`
/// for inspection); true when one is an error (the run must exit 2).
bool report_limits(const std::vector<ResultLimit>& limits, const std::string& dir);

/// The limits of a solved static case (normal, tangential, finite; a history: its last step)
/// from its summary's contact measures, added to the summary as "limits" (limits_json) and
/// returned: one function for `solve` and Python's solve().
std::vector<ResultLimit> attach_result_limits(const Case& c, nlohmann::json& summary);

}  // namespace dc::runs
