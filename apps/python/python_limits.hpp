#pragma once
// The module's exceptions and the result limits (apps/runs/result_limits.hpp) in Python: bad input
// raises InputError with .key; a result the program knows to be wrong (a limit that is an error,
// as `dyncontact solve` exits 2 for) raises ResultLimitError carrying the limits and the result;
// a limit that is only a warning (or accepted by the case) is a ResultLimitWarning.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid.hpp"

namespace dc::python {

namespace py = pybind11;

/// Registers InputError (a ValueError; every C++ dc::InputError becomes one with its .key),
/// ResultLimitError (an InputError with .key, .limits and .result), ResultLimitWarning and
/// SolverFallbackWarning (UserWarnings).
void bind_errors(py::module_& m);

/// Applies the limits of a result (entries of limits_json: key, message, accepted): the first one
/// not accepted raises ResultLimitError (its key and message, then `advice`: where the results are
/// and how to accept them) with .limits (all of them) and .result; otherwise each one is a
/// ResultLimitWarning.
void enforce_limits(const nlohmann::json& limits, const py::object& result, const std::string& advice);

/// A SolverFallbackWarning (a UserWarning) when a solver report (to_json(SolverReport)) says that
/// `auto`'s first backend failed and another answered ("fallback_warning"); nothing otherwise.
void warn_fallback(const nlohmann::json& solver);

/// AccuracyError (a RuntimeError with .result) when the summary's accuracy target was not met
/// (the command line's exit 3); nothing otherwise.
void enforce_accuracy_target(const nlohmann::json& summary, const py::object& result, const std::string& advice);

/// warn_fallback on a summary's "solver", then enforce_limits on its "limits" and on those of
/// each of its "runs" (a sweep).
void enforce_summary_limits(const nlohmann::json& summary, const py::object& result, const std::string& advice);

/// The limits (limits_json) of a contact found by NormalProblem or TangentialProblem on `grid`,
/// by the command line's rules on the contact's size: reaching the grid's edge (an error unless
/// `allow_edge_contact`), fewer than 4 elements across. Elements whose pressure is within
/// `certificate_tol` of the peak count as free, as for a case. The heights are the user's: no
/// radius of curvature, so a/R is not checked.
nlohmann::json contact_limits(const Grid& grid, const std::vector<double>& pressure, double certificate_tol,
                              bool allow_edge_contact);

}  // namespace dc::python
