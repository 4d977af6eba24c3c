// The runs in time for Python: the dynamic simulation of a "dynamic" case (the C++ name,
// DynamicSimulation) and the runs of a paper_cylinder case, returned as the summary dict with the
// time series as NumPy columns (the columns of timeseries.csv). The runs and their summaries are
// the command line's (apps/runs/dynamic_run.hpp, apps/runs/paper_cylinder_run.hpp).
#include <pybind11/stl.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "case_model.hpp"
#include "errors.hpp"
#include "dynamic_accuracy.hpp"
#include "dynamic_run.hpp"
#include "dynamic_subsurface.hpp"
#include "dynamic_temperature.hpp"
#include "dynamic_wear.hpp"
#include "dynamic_sweep.hpp"
#include "module_common.hpp"
#include "paper_cylinder_run.hpp"
#include "python_limits.hpp"
#include "python_runs.hpp"

namespace dc::python {
namespace {

constexpr const char* kRunAdvice = "; the run is in this exception's .result";

}  // namespace

py::dict csv_columns(const std::string& text) {
  std::istringstream in(text);
  std::string header, line, cell;
  std::getline(in, header);
  std::vector<std::string> names;
  for (std::istringstream h(header); std::getline(h, cell, ',');) names.push_back(cell);
  std::vector<std::vector<double>> columns(names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream row(line);
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!std::getline(row, cell, ',')) cell.clear();
      columns[k].push_back(cell.empty() ? std::nan("") : std::strtod(cell.c_str(), nullptr));
    }
  }
  py::dict out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    py::array_t<double> a(static_cast<py::ssize_t>(columns[k].size()));
    std::copy(columns[k].begin(), columns[k].end(), a.mutable_data());
    out[py::str(names[k])] = a;
  }
  return out;
}

/// A sweep's summary with each run's time series (by its file name) as NumPy columns in place
/// of the name.
py::dict with_series(const nlohmann::json& summary, const std::vector<std::string>& files,
                     const std::vector<std::string>& texts) {
  py::dict result = to_python(summary);
  py::dict series;
  for (std::size_t k = 0; k < files.size(); ++k) series[py::str(files[k])] = csv_columns(texts[k]);
  auto columns_of = [&](py::handle run) {
    const py::object name = run["timeseries"];
    if (!name.is_none() && series.contains(name)) run["timeseries"] = series[name];
  };
  if (result.contains("runs"))
    for (py::handle run : py::list(result["runs"])) columns_of(run);
  if (result.contains("run")) columns_of(result["run"]);
  if (result.contains("timeseries") && series.contains(result["timeseries"])) result["timeseries"] = series[result["timeseries"]];
  return result;
}

py::dict run_dynamic_case(const Case& c, bool progress) {
  if (c.sweep) {  // one run per value, each with its time series
    runs::DynamicSweepOutcome out;
    {
      py::gil_scoped_release release;
      out = runs::simulate_dynamic_sweep(c, !progress);
    }
    py::dict result = with_series(out.summary, out.files, out.texts);
    enforce_summary_limits(out.summary, result, kRunAdvice);
    for (const nlohmann::json& run : out.summary["runs"]) enforce_accuracy_target(run, result, kRunAdvice);
    return result;
  }
  // The field inside the bodies from the snapshots' and the peak load's tractions, as the
  // command line's run computes it (dynamic_subsurface.hpp), without its files.
  runs::DynamicOutcome out;
  runs::DynamicWear wear(c);  // every step's wear in each body's frame (dynamic_wear.hpp)
  {
    py::gil_scoped_release release;
    Grid grid = c.grid;  // of the run the states are taken from (an accuracy target chooses it)
    runs::DynamicSubsurface field(c);
    runs::DynamicTemperature temperature(c);
    const int every = c.output.snapshot_every;
    std::function<void(const dynamics::DynamicSample&)> observe;
    if (field.wanted() || temperature.wanted() || wear.wanted())
      observe = [&](const dynamics::DynamicSample& s) {
        wear.observe(grid, s);
        const bool snapshot = every > 0 && s.step % every == 0;
        output::StaticFields fields;
        if (snapshot || temperature.every_step()) {
          fields = runs::dynamic_step_fields(grid, s.contact_state);
          temperature.observe(grid, s, fields, snapshot);
        }
        field.observe(grid, s, snapshot ? &fields : nullptr);
      };
    if (wear.feeds_back())  // the worn depth in the gap (build_case refuses it with an accuracy estimate)
      out = runs::simulate_dynamic(c, progress, observe,
                                   [&wear](const dynamics::StepKinematics& k, std::vector<double>& depth) { wear.worn_depth(k, depth); });
    else
      out = runs::simulate_dynamic_with_accuracy(c, progress, observe, &grid);
    temperature.add_entries(out.summary);
    wear.add_entries(out.summary);
    if (!out.result.interrupted) field.add_entries(grid, {}, out.summary);
  }
  py::dict result = to_python(out.summary);
  // The worn depths (m) as wear.csv and wear_body.csv hold them: fields["wear_base"] (rows the
  // track's world y, fields["wear_base_y"], columns its world x, fields["wear_base_x"]) and
  // fields["wear_body"] (columns the arc s round the circumference, fields["wear_body_s"]); 2-D:
  // one row.
  if (wear.wanted()) {
    py::dict fields;
    for (const auto& [name, axis, strip] : {std::tuple{"wear_base", "wear_base_x", wear.base()},
                                            std::tuple{"wear_body", "wear_body_s", wear.body()}}) {
      if (strip.depth.empty()) continue;
      std::vector<double> at(static_cast<std::size_t>(strip.grid.nx));
      for (int i = 0; i < strip.grid.nx; ++i) at[static_cast<std::size_t>(i)] = strip.grid.xc(i);
      fields[name] = grid_array(strip.grid, strip.depth);
      fields[axis] = py::array_t<double>(static_cast<py::ssize_t>(at.size()), at.data());
      if (std::string(name) == "wear_base" && strip.grid.dimension == 3) {
        std::vector<double> across(static_cast<std::size_t>(strip.grid.ny));
        for (int j = 0; j < strip.grid.ny; ++j) across[static_cast<std::size_t>(j)] = strip.grid.yc(j);
        fields["wear_base_y"] = py::array_t<double>(static_cast<py::ssize_t>(across.size()), across.data());
      }
    }
    result["fields"] = fields;
  }
  result["timeseries"] = csv_columns(out.timeseries);
  if (result.contains("energy")) {  // the audit's history: energy.csv's columns
    py::dict energy = result["energy"];
    energy["series"] = csv_columns(out.energy);
  }
  enforce_summary_limits(out.summary, result, kRunAdvice);
  enforce_accuracy_target(out.summary, result, kRunAdvice);
  return result;
}

py::dict run_paper_cylinder_case(const Case& c, bool progress) {
  runs::PaperCylinderOutcome out;
  {
    py::gil_scoped_release release;
    out = runs::simulate_paper_cylinder(c, !progress);
  }
  py::dict result = with_series(out.summary, out.files, out.texts);
  enforce_summary_limits(out.summary, result, kRunAdvice);
  return result;
}

namespace {

/// A dynamic case set up to run (the case outlives the simulation that refers to it).
class PyDynamicSimulation {
 public:
  explicit PyDynamicSimulation(Case c) : case_(std::move(c)) {
    if (case_.problem != ProblemKind::dynamic)
      throw InputError("problem", std::string("DynamicSimulation takes a \"dynamic\" case, got '") +
                                      to_string(case_.problem) + "'");
  }
  py::dict run(bool progress) const { return run_dynamic_case(case_, progress); }
  const Case& the_case() const { return case_; }

 private:
  Case case_;
};

}  // namespace

void bind_runs(py::module_& m) {
  py::class_<PyDynamicSimulation>(
      m, "DynamicSimulation",
      "DynamicSimulation(case): the moving massive body of a \"dynamic\" case (a dict, JSON text or\n"
      "path): the Newton-Euler equations (2.20)-(2.21) stepped by (3.9)-(3.10), the contact solved\n"
      "in every step. run() returns the summary (the keys of summary.json: status, steps, final,\n"
      "balances, solver with the worst certificate) with 'timeseries': {column: NumPy array} for\n"
      "the columns of timeseries.csv (t, x, y, z, vx, ..., Fx, Fy, Fz, Mx, My, Mz, creepage,\n"
      "stick_fraction, approach, contact_area, n_contact, n_stick, n_slip, kinetic_energy,\n"
      "certificate, newton_iterations, contact_solves, alternations); its 'energy' (summary.json's:\n"
      "dissipated, frictional_power, audit) also holds 'series': {column: NumPy array} for the\n"
      "columns of energy.csv (t, kinetic, elastic, work, dissipated, numerical_damping). A run that stops early is not an exception: its status\n"
      "says 'stopped' and its message why. A limit in the summary's 'limits' that is an error (not\n"
      "accepted by the case) raises ResultLimitError with the run as .result, as solve() does.")
      .def(py::init([](const py::object& c) { return PyDynamicSimulation(case_from(c)); }), py::arg("case"))
      .def("run", &PyDynamicSimulation::run, py::arg("progress") = false,
           "run(progress=False) -> dict: runs to time.t_end (progress on stderr when asked)")
      .def_property_readonly("name", [](const PyDynamicSimulation& s) { return s.the_case().name; });
}

}  // namespace dc::python
