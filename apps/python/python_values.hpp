#pragma once
// Python values <-> JSON values, walked element by element (no text in between): a case given as
// a dict becomes the JSON the case model reads, a summary becomes a dict. Each value read from
// Python is checked where it stands, so a bad one is an InputError naming its key path
// ("normal.force", "grid.x[1]").
#include <pybind11/pybind11.h>

#include <string>

#include <nlohmann/json.hpp>

namespace dc::python {

namespace py = pybind11;

/// The JSON of a Python value: None, bool, int, float, str, os.PathLike (its path as a string),
/// dict (string keys), list and tuple, NumPy scalars (bool, integer, floating) and NumPy arrays
/// of one or two dimensions (as nested lists). Throws InputError naming `key` (the value's key
/// path; "case" at the top) for NaN or an infinity, an unsupported type, a dict key that is not a
/// string, or nesting deeper than kMaxJsonDepth.
nlohmann::json from_python(const py::handle& value, const std::string& key = "");

/// The Python value of JSON (objects as dicts, arrays as lists); NaN and infinities as None, as
/// summary.json writes them.
py::object to_python(const nlohmann::json& value);

}  // namespace dc::python
