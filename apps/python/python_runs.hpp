#pragma once
// The runs behind solve(), subsurface() and DynamicSimulation (run_bindings.cpp), and the reading
// of a case given from Python (dyncontact_module.cpp).
#include <pybind11/pybind11.h>

#include <string>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "tangential_run.hpp"

namespace dc::python {

namespace py = pybind11;

/// The case document of a dict, JSON text, or a path (str or os.PathLike): the JSON the case
/// model reads, not yet validated.
nlohmann::json case_document(const py::object& arg);
/// A case given as a dict, JSON text, or a path (str or os.PathLike), validated.
Case case_from(const py::object& arg);

/// A normal or tangential case solved as solve() does it.
struct StaticSolve {
  runs::StaticRun run;
  Case solved;             ///< the case on the grid solved (an accuracy target chooses it)
  nlohmann::json summary;  ///< with the result limits and, when written, "files"
  std::string advice;      ///< where the result is, for the limits' exceptions
};
/// Runs `c` (normal or tangential) with the GIL released; with `out` (a folder, or None) writes
/// summary.json (last), fields.csv and the subsurface block's files there, the folder locked for
/// the call.
StaticSolve solve_static_case(const Case& c, const py::object& out, bool progress);

/// A dynamic case run: the summary dict with 'timeseries' {column: array}.
py::dict run_dynamic_case(const Case& c, bool progress);
/// A paper_cylinder case run (its sweep over the cores): the summary dict, each run of "runs"
/// with its 'timeseries' {column: array}, and the first run's at the top.
py::dict run_paper_cylinder_case(const Case& c, bool progress);

}  // namespace dc::python
