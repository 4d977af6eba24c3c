#pragma once
// Helpers shared by the binding files of the Python module: JSON <-> Python (python_values.hpp),
// grid fields as NumPy arrays, and the module's parts registered one file each.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "errors.hpp"
#include "grid.hpp"
#include "python_values.hpp"  // from_python, to_python

namespace dc::python {

namespace py = pybind11;

/// A field on the grid as a NumPy array of shape (ny, nx) (3-D) or (nx,) (2-D); zeros when empty.
template <typename T>
py::array_t<T> grid_array(const Grid& g, const std::vector<T>& v) {
  std::vector<py::ssize_t> shape =
      g.dimension == 2 ? std::vector<py::ssize_t>{g.nx} : std::vector<py::ssize_t>{g.ny, g.nx};
  py::array_t<T> a(shape);
  T* out = a.mutable_data();
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = v.empty() ? T(0) : v[i];
  return a;
}

/// A field given from Python (any shape with one value per element, e.g. (ny, nx)) as a vector
/// in the grid's element order; InputError naming `key` when the size is wrong.
inline std::vector<double> grid_values(const Grid& g, const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
                                       const std::string& key) {
  if (static_cast<std::size_t>(a.size()) != g.size())
    throw InputError(key, "expected " + std::to_string(g.size()) + " values (one per element), got " +
                              std::to_string(a.size()));
  return std::vector<double>(a.data(), a.data() + a.size());
}

/// A CSV text with a header line (timeseries.csv) as {column: NumPy array}; empty cells are NaN.
py::dict csv_columns(const std::string& text);

void bind_problems(py::module_& m);  // problem_bindings.cpp: NormalProblem, TangentialProblem
void bind_runs(py::module_& m);      // run_bindings.cpp: DynamicSimulation, csv_columns
void bind_subsurface(py::module_& m);  // subsurface_bindings.cpp: subsurface()

}  // namespace dc::python
