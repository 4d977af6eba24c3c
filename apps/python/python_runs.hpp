#pragma once
// The runs behind solve() and DynamicSimulation (run_bindings.cpp), and the reading of a case
// given from Python (dyncontact_module.cpp).
#include <pybind11/pybind11.h>

#include "case_model.hpp"

namespace dc::python {

namespace py = pybind11;

/// A case given as a dict, JSON text, or a path (str or os.PathLike), validated.
Case case_from(const py::object& arg);

/// A dynamic case run: the summary dict with 'timeseries' {column: array}.
py::dict run_dynamic_case(const Case& c, bool progress);
/// A paper_cylinder case run (its sweep over the cores): the summary dict, each run of "runs"
/// with its 'timeseries' {column: array}, and the first run's at the top.
py::dict run_paper_cylinder_case(const Case& c, bool progress);

}  // namespace dc::python
