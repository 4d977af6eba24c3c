#include "python_limits.hpp"

#include <algorithm>

#include "accuracy_run.hpp"
#include "case_model.hpp"
#include "errors.hpp"
#include "output_files.hpp"
#include "python_values.hpp"
#include "result_limits.hpp"
#include "static_fields.hpp"
#include "summary_entries.hpp"

namespace dc::python {
namespace {

// The module's exception types (owned by the module, which lives to the interpreter's end).
PyObject* g_input_error = nullptr;
PyObject* g_result_limit_error = nullptr;
PyObject* g_result_limit_warning = nullptr;
PyObject* g_solver_fallback_warning = nullptr;
PyObject* g_accuracy_error = nullptr;

struct ResultLimitTag {};    // py::exception's C++ type: none is thrown (enforce_limits raises)
struct ResultLimitWarningTag {};
struct SolverFallbackWarningTag {};
struct AccuracyErrorTag {};

/// An exception instance of `type` with `message` and .key.
py::object error_with_key(PyObject* type, const std::string& message, const std::string& key) {
  py::object err = py::handle(type)(message);
  err.attr("key") = key;
  return err;
}

}  // namespace

void bind_errors(py::module_& m) {
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<ResultLimitTag> result_limit_error(m, "ResultLimitError", input_error);
  static py::exception<ResultLimitWarningTag> result_limit_warning(m, "ResultLimitWarning", PyExc_UserWarning);
  g_input_error = input_error.ptr();
  g_result_limit_error = result_limit_error.ptr();
  g_result_limit_warning = result_limit_warning.ptr();
  static py::exception<SolverFallbackWarningTag> solver_fallback_warning(m, "SolverFallbackWarning", PyExc_UserWarning);
  g_solver_fallback_warning = solver_fallback_warning.ptr();
  solver_fallback_warning.attr("__doc__") =
      "The first backend of 'auto' failed and another gave the answer (a UserWarning): the result's solver\n"
      "report lists the failed attempts ('failed_attempts', with the native solver's iteration history).";
  input_error.attr("__doc__") =
      "Bad input (a ValueError): .key names the case key (e.g. 'grid.nx', 'normal.force', 'grid.x[1]') or the\n"
      "argument (e.g. 'force_x', 'heights'); the message says why.";
  result_limit_error.attr("__doc__") =
      "A result the program knows to be wrong (an InputError: the input must change, as `dyncontact solve`\n"
      "exits 2), e.g. a contact cut by the grid's edge. .key names the case key to change (e.g. 'grid'),\n"
      ".limits lists every limit of the result ({'key', 'message', 'accepted'}, as summary.json's\n"
      "'limits'), .result holds the result for inspection (solve(): the summary dict with its fields;\n"
      "NormalProblem, TangentialProblem: the solution). solve(..., out=DIR) has written its files first.";
  result_limit_warning.attr("__doc__") =
      "A limit of a result that is not an error (a UserWarning), e.g. a contact resolved by fewer than\n"
      "4 elements, or one the case accepts (grid.allow_edge_contact): the result's 'limits' list it too.";
  static py::exception<AccuracyErrorTag> accuracy_error(m, "AccuracyError", PyExc_RuntimeError);
  g_accuracy_error = accuracy_error.ptr();
  accuracy_error.attr("__doc__") =
      "The accuracy asked for (solve(..., accuracy=...) or the case's accuracy.target) was not reached\n"
      "within accuracy.max_elements, the memory available or accuracy.max_seconds (a RuntimeError;\n"
      "`dyncontact solve` exits 3).\n"
      ".result holds the result of the finest grid solved, with its 'accuracy' block (met: False,\n"
      "stopped_by, the estimated error of each quantity).";
  static py::exception<dc::OutputError> output_error(m, "OutputError", PyExc_OSError);
  output_error.attr("__doc__") =
      "A file of solve(out=...) could not be written (an OSError: errno, strerror and filename when a\n"
      "system call failed, e.g. a full disk).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      const py::object err = error_with_key(g_input_error, e.what(), e.key());
      PyErr_SetObject(g_input_error, err.ptr());
    } catch (const dc::OutputError& e) {  // OSError(errno, strerror, filename) when a system call failed
      py::object err = e.error_number() != 0 ? py::handle(output_error.ptr())(e.error_number(), e.reason(), e.path())
                                             : py::handle(output_error.ptr())(e.what());
      if (e.error_number() == 0) err.attr("filename") = e.path();
      PyErr_SetObject(output_error.ptr(), err.ptr());
    }
  });
}

void enforce_limits(const nlohmann::json& limits, const py::object& result, const std::string& advice) {
  if (!limits.is_array()) return;
  for (const nlohmann::json& l : limits) {
    if (l.value("level", std::string("warning")) != "error") continue;
    const std::string key = l.value("key", "");
    py::object err = error_with_key(g_result_limit_error, key + ": " + l.value("message", "") + advice, key);
    err.attr("limits") = to_python(limits);
    err.attr("result") = result;
    PyErr_SetObject(g_result_limit_error, err.ptr());
    throw py::error_already_set();
  }
  for (const nlohmann::json& l : limits) {
    const std::string text = l.value("key", "") + ": " + l.value("message", "");
    if (PyErr_WarnEx(g_result_limit_warning, text.c_str(), 1) != 0) throw py::error_already_set();  // an error filter
  }
}

void enforce_accuracy_target(const nlohmann::json& summary, const py::object& result, const std::string& advice) {
  if (!runs::accuracy_target_missed(summary)) return;
  const nlohmann::json& a = summary["accuracy"];
  py::object err = py::handle(g_accuracy_error)("accuracy: " + runs::missed_target_message(a) + advice);
  err.attr("result") = result;
  PyErr_SetObject(g_accuracy_error, err.ptr());
  throw py::error_already_set();
}

void warn_fallback(const nlohmann::json& solver) {
  if (!solver.is_object() || !solver.contains("fallback_warning")) return;
  const std::string text = "solver: " + solver["fallback_warning"].get<std::string>();
  if (PyErr_WarnEx(g_solver_fallback_warning, text.c_str(), 1) != 0) throw py::error_already_set();
}

void enforce_summary_limits(const nlohmann::json& summary, const py::object& result, const std::string& advice) {
  if (summary.contains("solver")) warn_fallback(summary["solver"]);
  if (summary.contains("limits")) enforce_limits(summary["limits"], result, advice);
  if (summary.contains("runs") && summary["runs"].is_array())
    for (const nlohmann::json& run : summary["runs"])
      if (run.is_object() && run.contains("limits")) enforce_limits(run["limits"], result, advice);
}

nlohmann::json contact_limits(const Grid& grid, const std::vector<double>& pressure, double certificate_tol,
                              bool allow_edge_contact) {
  Case c;  // the grid's part of a case: what result_limits reads
  c.dimension = grid.dimension;
  c.grid = grid;
  c.allow_edge_contact = allow_edge_contact;
  c.profile.type = ProfileType::table;  // heights given as values: no radius of curvature
  nlohmann::json measures;
  output::add_contact_measures(measures, grid, output::normal_fields(pressure, std::max(certificate_tol, 1e-12)));
  return output::limits_json(result_limits(c, runs::measured_contact_size(c, measures)));
}

}  // namespace dc::python
