// The Python module `dyncontact`: solve a case (dict, JSON text or path) to a summary dict and
// NumPy fields, the half-space operators, and the case model's input errors as Python
// exceptions carrying the key. The solvers are the C++ ones (core/, nlp/), the run and its
// summary the command line's (apps/runs/tangential_run.hpp), so Python and `dyncontact solve`
// agree.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blas_threads.hpp"
#include "case_model.hpp"
#include "errors.hpp"
#include "static_field_files.hpp"
#include "linear_operator.hpp"
#include "module_common.hpp"
#include "output_files.hpp"
#include "output_folder.hpp"
#include "python_limits.hpp"
#include "python_runs.hpp"
#include "result_limits.hpp"
#include "summary_writer.hpp"
#include "subsurface_run.hpp"
#include "subsurface_series.hpp"
#include "tangential_run.hpp"

namespace dc::python {

nlohmann::json case_document(const py::object& arg) {
  if (py::isinstance<py::dict>(arg)) return from_python(arg);
  const std::string text = py::str(py::module_::import("os").attr("fspath")(arg)).cast<std::string>();
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return parse_case_text(text, "case");
  nlohmann::json doc = read_case_file(text);
  if (doc.is_object() && !doc.contains("name")) doc["name"] = std::filesystem::path(text).stem().string();
  return doc;
}

Case case_from(const py::object& arg) { return build_case(case_document(arg), "."); }

StaticSolve solve_static_case(const Case& c, const py::object& out, bool progress) {
  // The folder is locked for the call (another run into it is refused before this one solves).
  output::OutputFolder folder;
  if (!out.is_none())
    folder = output::open_output_folder(c, py::str(py::module_::import("os").attr("fspath")(out)), "out");
  StaticSolve r;
  std::optional<output::SubsurfaceSnapshots> series;  // a history's states, as `dyncontact solve` writes them
  if (folder.lock && c.subsurface.enabled) series.emplace(folder.dir);
  {
    py::gil_scoped_release release;
    r.run = runs::run_static(c, progress, series ? runs::subsurface_file_sink(*series) : nullptr);
  }
  r.solved = c;  // on the grid solved (an accuracy target chooses it)
  r.solved.grid = r.run.grid;
  r.summary = r.run.summary;
  runs::attach_result_limits(r.solved, r.summary);  // as `dyncontact solve` writes them
  r.advice = "; the result is in this exception's .result";
  if (folder.lock) {  // summary.json last: complete or absent
    nlohmann::json files = {{"summary", "summary.json"}};
    output::StaticFieldFiles surface{&r.run.fields, true, r.run.history, r.solved.output.power, &r.run.worn_base,
                                     &r.run.worn_body, &r.run.wear_series};
    output::write_static_field_files(folder.dir, r.solved.grid, surface, files, r.summary);
    if (series && series->count() > 0) files["subsurface_series"] = series->collection();
    if (r.run.subsurface) runs::write_subsurface_files(folder.dir, c, *r.run.subsurface, files);
    r.summary["files"] = files;
    output::write_summary(folder.dir, r.summary);
    r.advice = "; the results are written to " + folder.dir + " and are in this exception's .result";
  }
  return r;
}

}  // namespace dc::python

namespace {

using namespace dc::python;

py::dict fields_dict(const dc::Grid& g, const dc::output::StaticFields& f) {
  std::vector<double> x(g.size()), y(g.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      x[static_cast<std::size_t>(j) * g.nx + i] = g.x0 + (i + 0.5) * g.dx;
      y[static_cast<std::size_t>(j) * g.nx + i] = g.dimension == 2 ? 0.0 : g.y0 + (j + 0.5) * g.dy;
    }
  py::dict d;
  d["x"] = grid_array(g, x);
  d["y"] = grid_array(g, y);
  d["p"] = grid_array(g, f.p);
  d["tx"] = grid_array(g, f.tx);
  d["ty"] = grid_array(g, f.ty);
  d["sx"] = grid_array(g, f.sx);
  d["sy"] = grid_array(g, f.sy);
  d["state"] = grid_array(g, f.state);
  if (!f.temperature_base.empty() && !f.temperature_body.empty()) {  // the flash temperature rise (K) per surface
    d["temperature_base"] = grid_array(g, f.temperature_base);
    d["temperature_body"] = grid_array(g, f.temperature_body);
  }
  return d;
}

py::dict solve(const py::object& case_arg, const py::object& out, bool progress, const py::object& accuracy) {
  nlohmann::json document = case_document(case_arg);
  if (!accuracy.is_none()) {  // accuracy=1e-3: the case's accuracy.target (its other accuracy keys kept)
    if (!py::isinstance<py::float_>(accuracy) && !py::isinstance<py::int_>(accuracy))
      throw dc::InputError("accuracy", "expected a relative error (a number such as 1e-3)");
    if (document.is_object()) {
      if (!document.contains("accuracy") || !document["accuracy"].is_object()) document["accuracy"] = nlohmann::json::object();
      document["accuracy"]["target"] = accuracy.cast<double>();
    }
  }
  const dc::Case c = dc::build_case(document, ".");
  if (c.problem == dc::ProblemKind::dynamic || c.problem == dc::ProblemKind::paper_cylinder) {
    if (!out.is_none())
      throw dc::InputError("out", "solve() writes files for normal and tangential cases; run dynamic and "
                                  "paper_cylinder cases with `dyncontact solve` for their files and plots");
    return c.problem == dc::ProblemKind::dynamic ? run_dynamic_case(c, progress) : run_paper_cylinder_case(c, progress);
  }
  if (c.problem != dc::ProblemKind::normal && c.problem != dc::ProblemKind::tangential)
    throw dc::InputError("problem", std::string("'") + dc::to_string(c.problem) +
                                        "' is run by the command line (dyncontact solve); solve() takes normal, "
                                        "tangential, dynamic and paper_cylinder cases");
  StaticSolve r = solve_static_case(c, out, progress);
  nlohmann::json& summary = r.summary;
  const dc::Case& solved = r.solved;
  const dc::runs::StaticRun& run = r.run;
  const std::string& advice = r.advice;
  py::dict result = to_python(summary);
  py::dict fields = fields_dict(solved.grid, run.fields.back());
  // A "wear" block: each worn body's depth (m), wear.csv's columns.
  if (!run.worn_base.empty()) fields["wear_base"] = grid_array(solved.grid, run.worn_base);
  if (!run.worn_body.empty()) fields["wear_body"] = grid_array(solved.grid, run.worn_body);
  result["fields"] = fields;
  if (!run.wear_series.empty()) {  // the worn depth after the kept updates: wear.pvd's states
    const dc::Grid& g = solved.grid;
    const auto n = static_cast<py::ssize_t>(run.wear_series.size());
    std::vector<py::ssize_t> shape = g.dimension == 2 ? std::vector<py::ssize_t>{n, g.nx}
                                                       : std::vector<py::ssize_t>{n, g.ny, g.nx};
    py::array_t<long long> cycles(n);
    py::array_t<double> depth(shape);  // each state's map in grid order, as grid_array's
    double* to = depth.mutable_data();
    for (py::ssize_t k = 0; k < n; ++k) {
      const dc::output::WornState& state = run.wear_series[static_cast<std::size_t>(k)];
      cycles.mutable_data()[k] = state.cycles;
      for (std::size_t e = 0; e < g.size(); ++e) *to++ = e < state.depth.size() ? state.depth[e] : 0.0;
    }
    result["wear_series"] = py::dict(py::arg("cycles") = cycles, py::arg("depth") = depth);
  }
  enforce_summary_limits(summary, result, advice);
  enforce_accuracy_target(summary, result, advice);
  return result;
}

/// A linear operator of the half-space, applied to NumPy vectors.
class Operator {
 public:
  explicit Operator(std::unique_ptr<dc::LinearOperator> op) : op_(std::move(op)) {}
  py::array_t<double> apply(const py::array_t<double, py::array::c_style | py::array::forcecast>& x) const {
    if (static_cast<std::size_t>(x.size()) != op_->cols())
      throw dc::InputError("x", "expected " + std::to_string(op_->cols()) + " values, got " + std::to_string(x.size()));
    py::array_t<double> y(static_cast<py::ssize_t>(op_->rows()));
    {
      py::gil_scoped_release release;
      op_->apply(x.data(), y.mutable_data());
    }
    return y;
  }
  std::size_t rows() const { return op_->rows(); }
  std::size_t cols() const { return op_->cols(); }
  std::string kind() const { return op_->kind(); }

 private:
  std::shared_ptr<dc::LinearOperator> op_;
};

dc::OperatorKind kind_of(const std::string& kind) {
  if (kind == "dense") return dc::OperatorKind::dense;
  if (kind == "fft") return dc::OperatorKind::fft;
  if (kind == "auto") return dc::OperatorKind::automatic;
  throw dc::InputError("kind", "expected auto, dense or fft, got '" + kind + "'");
}

/// Imports NumPy before anything uses it. An interpreter of the module's Python version that
/// has no NumPy of its own (pyenv's python3 next to Debian's) takes the NumPy of the interpreter
/// the module was built for (only that package: its folder is on sys.path just for the import).
/// A NumPy the module cannot use raises ImportError saying what to do.
void import_numpy() {
  const py::module_ sys = py::module_::import("sys");
  try {
    py::module_::import("numpy");
  } catch (const py::error_already_set&) {
    const py::str dir(DYNCONTACT_NUMPY_DIR);
    py::list path = sys.attr("path");
    path.append(dir);
    try {
      py::module_::import("numpy");
      path.attr("remove")(dir);
    } catch (const py::error_already_set&) {
      path.attr("remove")(dir);
      throw py::import_error(
          "dyncontact needs NumPy, which " + py::str(sys.attr("executable")).cast<std::string>() +
          " does not have: use " DYNCONTACT_PYTHON_EXECUTABLE
          " (the interpreter the module was built for), or install NumPy 1.x for this one "
          "(python3 -m pip install 'numpy<2')");
    }
  }
#if PYBIND11_VERSION_HEX < 0x020C0000
  // pybind11 before 2.12 reads NumPy 1's array structures; NumPy 2 changed them.
  const std::string version = py::str(py::module_::import("numpy").attr("__version__"));
  if (!version.empty() && version[0] != '1' && version[1] == '.')
    throw py::import_error("dyncontact was built with pybind11 " + std::to_string(PYBIND11_VERSION_MAJOR) + "." +
                           std::to_string(PYBIND11_VERSION_MINOR) + ", which supports NumPy 1 only; this interpreter has NumPy " +
                           version + ": use " DYNCONTACT_PYTHON_EXECUTABLE " or install 'numpy<2'");
#endif
}

}  // namespace

PYBIND11_MODULE(dyncontact, m) {
  import_numpy();
  dc::use_one_blas_thread();
  m.doc() =
      "dyncontact: frictional contact between an elastic body and an elastic half-space (after Spector & "
      "Batra), solved as convex programs with certified results.\n\n"
      "  solve(case)                    solve a case (dict, JSON text or path): the summary as a dict (keys\n"
      "                                 of summary.json) with 'fields' (NumPy; normal, tangential) or\n"
      "                                 'timeseries' (NumPy columns; dynamic, paper_cylinder)\n"
      "  subsurface(case)               the elastic field inside the bodies of a solved case: per body stress\n"
      "                                 (depths, ny, nx, 6), displacement, von_mises, tresca (NumPy)\n"
      "  Grid, Materials, grid_centres  the contact grid, the elastic pair, the element centres\n"
      "  HalfSpace                      the half-space's influence operators: HalfSpace(g, m).normal().apply(p)\n"
      "  NormalProblem                  (4.7): NormalProblem(g, m, h).solve(force=P) -> NormalSolution\n"
      "  TangentialProblem              (3.25)/(4.8) with memory: step(...) (shift, torsion), steady_rolling(...),\n"
      "                                 roll(distance, ...) -> TangentialSolution\n"
      "  DynamicSimulation              a dynamic case run in time: DynamicSimulation(case).run()\n"
      "  InputError                     bad input (a ValueError); .key names the key (e.g. 'grid.nx', 'force_x',\n"
      "                                 'grid.x[1]' for a NaN there)\n"
      "  ResultLimitError               a result known to be wrong (an InputError), e.g. a contact cut by the\n"
      "                                 grid: .key, .limits, .result (the result, for inspection)\n"
      "  ResultLimitWarning             a limit that is only a warning (a UserWarning); results list all in 'limits'\n"
      "  SolverFallbackWarning          auto's first backend failed and another answered (a UserWarning); see failed_attempts\n"
      "  OutputError                    a file of solve(out=...) could not be written (an OSError; .filename)\n\n"
      "Example:\n"
      "  import dyncontact, json\n"
      "  r = dyncontact.solve(json.load(open('examples/hertz-sphere.json')))\n"
      "  r['normal_force'], r['max_pressure'], r['fields']['p'].shape\n"
      "  g = dyncontact.Grid(64, 64, -1e-3, 1e-3, -1e-3, 1e-3)\n"
      "  x, y = dyncontact.grid_centres(g)\n"
      "  tp = dyncontact.TangentialProblem(g, dyncontact.Materials(2.1e11, 0.3, 2.1e11, 0.3),\n"
      "                                    (x**2 + y**2) / 0.02, mu=0.3)\n"
      "  s = tp.step(force=100.0, force_x=15.0)   # Cattaneo: s.amplitudes[0] is the shift, s.stick_area";

  bind_errors(m);

  m.def("solve", &solve, py::arg("case"), py::arg("out") = py::none(), py::arg("progress") = false,
        py::arg("accuracy") = py::none(),
        "solve(case, out=None, progress=False, accuracy=None) -> dict\n\n"
        "Solves a case given as a dict, a JSON string or a path to a case file\n"
        "(the format of CASES.md; `dyncontact example NAME` prints complete ones). Returns the\n"
        "summary (the keys of summary.json: normal_force, approach, max_pressure, contact_area,\n"
        "tangential_force, solver with its certificate, ...) with 'fields': NumPy arrays x, y, p,\n"
        "tx, ty, sx, sy, state of shape (ny, nx) (2-D: (nx,)). No files are written unless `out`\n"
        "names a folder (summary.json, fields.csv and, with a subsurface block, subsurface.vti and\n"
        "the planes' CSV as `dyncontact solve` writes them). A dynamic or paper_cylinder case returns its\n"
        "summary with 'timeseries': {column: NumPy array} (the columns of timeseries.csv); a sweep's\n"
        "runs each carry theirs under 'runs'.\n\n"
        "A dict may hold Python or NumPy numbers (np.int64, np.float64, np.bool_) and NumPy arrays\n"
        "of one or two dimensions where the format has lists. Raises InputError (a ValueError whose\n"
        ".key names the case key, e.g. 'normal.force' or 'grid.x[1]') for bad input: NaN or an\n"
        "infinity anywhere, a value of another type, what the case format refuses, and another run\n"
        "writing into `out` (the folder is locked for the call). The summary's 'limits' are those of\n"
        "summary.json (a contact at the grid's edge, too few elements across it, a/R too large): one\n"
        "that is an error (the command line's exit 2) raises ResultLimitError (an InputError; .key,\n"
        ".limits, and .result: this summary with its fields), after writing the files when `out` is\n"
        "given; the others are ResultLimitWarning warnings. OutputError (an OSError) when a file\n"
        "cannot be written.\n\n"
        "A normal or tangential result carries 'accuracy' (docs/accuracy.md): each result's value,\n"
        "extrapolated value and estimated relative error from the grids of 2 and 4 times the element\n"
        "size. accuracy=1e-3 asks for that relative error instead of a grid (the case's accuracy.target;\n"
        "grid.nx/ny may then be left out): the grid is refined until the named quantities\n"
        "(accuracy.quantities, default max_pressure) meet it, else AccuracyError (.result).");

  bind_problems(m);
  bind_runs(m);
  bind_subsurface(m);

  py::class_<dc::Grid>(m, "Grid", "A uniform grid of rectangular elements on the contact plane (m).")
      .def(py::init([](int nx, int ny, double x_min, double x_max, double y_min, double y_max, int dimension) {
             return dc::Grid::make(dimension, nx, ny, x_min, x_max, y_min, y_max);
           }),
           py::arg("nx"), py::arg("ny"), py::arg("x_min"), py::arg("x_max"), py::arg("y_min") = 0.0,
           py::arg("y_max") = 0.0, py::arg("dimension") = 3,
           "Grid(nx, ny, x_min, x_max, y_min, y_max, dimension=3): nx x ny elements over the rectangle\n"
           "(2-D plane strain: dimension=2, ny=1, the y bounds unused).")
      .def_readonly("nx", &dc::Grid::nx)
      .def_readonly("ny", &dc::Grid::ny)
      .def_readonly("dx", &dc::Grid::dx)
      .def_readonly("dy", &dc::Grid::dy)
      .def_readonly("dimension", &dc::Grid::dimension)
      .def("size", &dc::Grid::size, "number of elements")
      .def("__repr__", [](const dc::Grid& g) {
        return "Grid(nx=" + std::to_string(g.nx) + ", ny=" + std::to_string(g.ny) +
               ", dimension=" + std::to_string(g.dimension) + ")";
      });

  py::class_<dc::MaterialPair>(m, "Materials", "The elastic constants of the body and of the half-space (base).")
      .def(py::init([](double body_E, double body_nu, double base_E, double base_nu) {
             return dc::MaterialPair{dc::Elastic::from_E_nu(body_E, body_nu, "materials.body"),
                                     dc::Elastic::from_E_nu(base_E, base_nu, "materials.base")};
           }),
           py::arg("body_E"), py::arg("body_nu"), py::arg("base_E"), py::arg("base_nu"),
           "Materials(body_E, body_nu, base_E, base_nu): Young's moduli (Pa) and Poisson ratios.")
      .def_property_readonly("E_star", &dc::MaterialPair::E_star, "contact modulus E* (Pa)");

  py::class_<Operator>(m, "Operator", "A linear influence operator of the half-space (matrix-free).")
      .def("apply", &Operator::apply, py::arg("x"),
           "apply(x) -> ndarray: the operator times x (e.g. surface displacement (m) from pressure (Pa)).")
      .def_property_readonly("rows", &Operator::rows)
      .def_property_readonly("cols", &Operator::cols)
      .def_property_readonly("kind", &Operator::kind, "dense or fft");

  py::class_<dc::HalfSpace>(m, "HalfSpace",
                            "The elastic half-space discretised on a grid: its influence operators (Boussinesq-Cerruti, "
                            "element-wise constant tractions).")
      .def(py::init([](const dc::Grid& g, const dc::MaterialPair& mat) { return dc::HalfSpace(g, mat); }),
           py::arg("grid"), py::arg("materials"))
      .def(
          "normal", [](const dc::HalfSpace& h, const std::string& kind) { return Operator(h.normal(kind_of(kind))); },
          py::arg("kind") = "auto",
          "normal(kind='auto') -> Operator: normal relative displacement (m) from pressure (Pa), the\n"
          "compliance of both bodies (the paper's B31). kind: auto, dense or fft.")
      .def(
          "tangential",
          [](const dc::HalfSpace& h, const std::string& kind) { return Operator(h.tangential(kind_of(kind))); },
          py::arg("kind") = "auto",
          "tangential(kind='auto') -> Operator: tangential relative displacement from tangential traction\n"
          "(components stacked: all x, then all y; the paper's B22).");
}
