// The normal and tangential problems of nlp/ (their C++ names and methods) for Python: set up
// once on a grid, solved many times (warm starts, loading histories with memory).
#include <pybind11/stl.h>

#include <array>
#include <chrono>
#include <memory>
#include <cmath>
#include <optional>
#include <string>

#include "friction_law.hpp"
#include "heights_accuracy.hpp"
#include "module_common.hpp"
#include "normal_problem.hpp"
#include "python_limits.hpp"
#include "summary_entries.hpp"
#include "tangential_accuracy.hpp"
#include "tangential_problem.hpp"

namespace dc::python {
namespace {

using Opt = std::optional<double>;

using HeightArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The undeformed gap per element (m): finite, or +inf where the body cannot touch; NaN and -inf
/// are InputError("heights").
std::vector<double> heights_of(const Grid& g, const HeightArray& a) {
  std::vector<double> h = grid_values(g, a, "heights");
  for (std::size_t k = 0; k < h.size(); ++k)
    if (std::isnan(h[k]) || (std::isinf(h[k]) && h[k] < 0.0))
      throw InputError("heights", "element " + std::to_string(k) + " (in the grid's order) is " +
                                      (std::isnan(h[k]) ? "NaN" : "-inf") +
                                      "; give a finite height (m), or np.inf where the body cannot touch");
  return h;
}

double finite_value(double v, const std::string& key) {
  if (!std::isfinite(v)) throw InputError(key, "must be a finite number");
  return v;
}

/// force=P (N; 2-D N/m) or approach=d (m): exactly one.
NormalSpec normal_load(const Opt& force, const Opt& approach) {
  if (force && approach) throw InputError("approach", "give force or approach, not both");
  if (!force && !approach) throw InputError("force", "give the normal load: force=... (N; 2-D N/m) or approach=... (m)");
  if (force && !(finite_value(*force, "force") > 0.0)) throw InputError("force", "must be positive");
  return force ? NormalSpec{Control::force, *force} : NormalSpec{Control::approach, finite_value(*approach, "approach")};
}

/// One rigid mode by its amplitude or by its resultant: at most one of the two (neither: zero amplitude).
ModeControl mode(const Opt& amplitude, const char* amplitude_key, const Opt& resultant, const char* resultant_key) {
  if (amplitude && resultant)
    throw InputError(resultant_key, std::string("give ") + amplitude_key + " or " + resultant_key + ", not both");
  if (resultant) return {ModeControl::Kind::resultant, finite_value(*resultant, resultant_key)};
  return {ModeControl::Kind::amplitude, amplitude ? finite_value(*amplitude, amplitude_key) : 0.0};
}

/// The load of steady_rolling() and roll(): the normal load, each rolling mode by its creepage
/// (spin) or its resultant, and the rolling speed.
RollingLoad rolling_load(const Opt& force, const Opt& approach, const Opt& creepage_x, const Opt& force_x,
                         const Opt& creepage_y, const Opt& force_y, const Opt& spin, const Opt& moment_z,
                         double velocity) {
  RollingLoad load;
  load.normal = normal_load(force, approach);
  load.modes = {mode(creepage_x, "creepage_x", force_x, "force_x"), mode(creepage_y, "creepage_y", force_y, "force_y"),
                mode(spin, "spin", moment_z, "moment_z")};
  if (!(finite_value(velocity, "velocity") > 0.0)) throw InputError("velocity", "must be positive");
  load.velocity = velocity;
  return load;
}

SolverOptions solver_spec(const std::string& backend, double tol, double certificate_tol, int max_iter) {
  const std::optional<Backend> named = backend_from_string(backend);
  if (!named) throw InputError("backend", "expected auto, ipopt, nlopt or native, got '" + backend + "'");
  SolverOptions s;
  s.backend = *named;
  s.tol = tol;
  s.certificate_tol = certificate_tol;
  s.max_iter = max_iter;
  // The case file's rule (SolverOptions::validate): "<field>: <reason>", the field the argument.
  if (const std::string why = s.validate(); !why.empty()) {
    const auto colon = why.find(": ");
    throw InputError(why.substr(0, colon), why.substr(colon + 2));
  }
  return s;
}

OperatorKind operator_kind(const std::string& kind) {
  if (const std::optional<OperatorKind> named = operator_kind_from_string(kind)) return *named;
  throw InputError("kind", "expected auto, dense or fft, got '" + kind + "'");
}

struct NormalResult {
  Grid grid;
  NormalSolution s;
  nlohmann::json limits;  ///< contact_limits of the solution
  nlohmann::json accuracy;  ///< solve(estimate=True): summary.json's accuracy block; null otherwise
};
struct TangentialResult {
  Grid grid;
  TangentialSolution s;
  nlohmann::json limits;
  nlohmann::json accuracy;  ///< estimate=True: summary.json's accuracy block; null otherwise
};

/// A problem with the grid it was set up on (the C++ classes keep theirs private or by value)
/// and whether a contact reaching the grid's edge is accepted.
struct PyNormalProblem {
  Grid grid;
  NormalProblem problem;
  bool allow_edge_contact = false;
  // What the error estimate sets up again on coarser grids (runs/heights_accuracy.hpp).
  std::vector<double> heights;
  std::shared_ptr<runs::HeightsAccuracy> accuracy;  // its coarse problems
};
struct PyTangentialProblem {
  TangentialProblem problem;
  bool allow_edge_contact = false;
  // Every call recorded, for the coarse grids' histories of an estimate (runs/tangential_accuracy.hpp).
  std::shared_ptr<runs::TangentialAccuracy> accuracy;

  /// `call` solved by `solve` (the fine problem's call), recorded, and estimated when asked.
  template <typename Solve>
  TangentialResult take(runs::TangentialCall call, bool estimate, Solve solve) {
    py::gil_scoped_release release;
    const auto start = std::chrono::steady_clock::now();
    TangentialResult r{problem.grid(), solve(), {}, {}};
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    accuracy->record(std::move(call), r.s.report.backend);
    if (estimate) r.accuracy = accuracy->estimate(r.s, seconds);
    return r;
  }
};

/// The end of a ResultLimitError's message from a problem class (its error limits are a
/// contact cut by the grid's edge: contact_limits).
std::string edge_advice(const char* cls) {
  return std::string("; for ") + cls +
         ": a grid wider than the contact, or allow_edge_contact=True (its grid.allow_edge_contact); the solution is "
         "in this exception's .result";
}

const std::vector<double>& pressure_of(const NormalResult& r) { return r.s.pressure; }
const std::vector<double>& pressure_of(const TangentialResult& r) { return r.s.normal.pressure; }

/// A solution with its limits (from its contact) as a Python object; ResultLimitError when one
/// is an error (a result known to be wrong is not returned as if it were right).
template <typename Result>
py::object checked(Result r, double certificate_tol, bool allow_edge_contact, const char* cls) {
  r.limits = contact_limits(r.grid, pressure_of(r), certificate_tol, allow_edge_contact);
  warn_fallback(output::to_json(r.s.report));
  const nlohmann::json limits = r.limits;
  py::object result = py::cast(std::move(r));
  enforce_limits(limits, result, edge_advice(cls));
  return result;
}

FrictionLaw friction_of(const Opt& mu, const Opt& tresca) {
  if (mu && tresca) throw InputError("tresca", "give mu (Coulomb) or tresca (a bound in Pa), not both");
  if (tresca) {
    if (!(finite_value(*tresca, "tresca") > 0.0)) throw InputError("tresca", "must be positive");
    return FrictionLaw::tresca(*tresca);
  }
  if (!mu) throw InputError("mu", "give the friction: mu=... (Coulomb) or tresca=... (Pa)");
  if (!(finite_value(*mu, "mu") >= 0.0)) throw InputError("mu", "must not be negative");
  return FrictionLaw::coulomb(*mu);
}

constexpr const char* kSolverArgs =
    "Solver options (keywords): backend='auto' (auto, ipopt, nlopt, native), tol=1e-9,\n"
    "certificate_tol=1e-6 (the largest accepted certificate residual), max_iter=1000; tol and\n"
    "certificate_tol from 1e-16 to 0.1, as in a case file's solver block (else InputError).\n"
    "Non-convergence is not an exception: the solution's .converged and .report say so.\n"
    "A contact reaching the grid's edge (the pressure truncated: a wrong result) raises\n"
    "ResultLimitError (key 'grid', .result the solution) unless allow_edge_contact is True; fewer\n"
    "than 4 elements across the contact is a ResultLimitWarning. Both are in the solution's .limits.";

constexpr const char* kAllowEdgeContact =
    "whether a contact reaching the grid's edge is accepted (a warning and an accepted entry in .limits)\n"
    "instead of raising ResultLimitError (the case key grid.allow_edge_contact)";

constexpr const char* kLimitsDoc =
    "the limits of the result, as summary.json's 'limits': a list of {'key', 'message', 'accepted'}\n"
    "(contact at the grid's edge, fewer than 4 elements across the contact); empty when none";

}  // namespace

void bind_problems(py::module_& m) {
  m.def(
      "grid_centres",
      [](const Grid& g) {
        std::vector<double> x(g.size()), y(g.size());
        for (int j = 0; j < g.ny; ++j)
          for (int i = 0; i < g.nx; ++i) {
            x[g.index(i, j)] = g.xc(i);
            y[g.index(i, j)] = g.yc(j);
          }
        return py::make_tuple(grid_array(g, x), grid_array(g, y));
      },
      py::arg("grid"),
      "grid_centres(grid) -> (x, y): the element centres (m) as arrays of shape (ny, nx) (2-D: (nx,)),\n"
      "e.g. to build a profile: h = (x**2 + y**2) / (2 R) for a sphere of radius R.");

  py::class_<NormalResult>(m, "NormalSolution", "A solution of the normal problem (4.7).")
      .def_property_readonly("pressure", [](const NormalResult& r) { return grid_array(r.grid, r.s.pressure); },
                             "pressure p (Pa) per element, shape (ny, nx) (2-D: (nx,))")
      .def_property_readonly("gap", [](const NormalResult& r) { return grid_array(r.grid, r.s.gap); },
                             "deformed gap g (m), 0 in contact")
      .def_property_readonly("approach", [](const NormalResult& r) { return r.s.approach; }, "approach delta (m)")
      .def_property_readonly("force", [](const NormalResult& r) { return r.s.force; }, "sum p A (N; 2-D N/m)")
      .def_property_readonly("converged", [](const NormalResult& r) { return r.s.report.status == SolveStatus::converged; })
      .def_property_readonly("report", [](const NormalResult& r) { return to_python(output::to_json(r.s.report)); },
                             "the solver's report: backend, status, iterations, time_s, certificate, ...")
      .def_property_readonly("limits", [](const NormalResult& r) { return to_python(r.limits); }, kLimitsDoc)
      .def_property_readonly(
          "accuracy", [](const NormalResult& r) { return r.accuracy.is_null() ? py::object(py::none()) : to_python(r.accuracy); },
          "solve(estimate=True): the estimated discretisation error, as summary.json's 'accuracy' block\n"
          "(quantities approach or force, max_pressure, contact_area with value, extrapolated,\n"
          "error_estimate (relative), method, order; or 'unavailable' and why); None otherwise");

  py::class_<PyNormalProblem>(
      m, "NormalProblem",
      "NormalProblem(grid, materials, heights, kind='auto', allow_edge_contact=False): the normal contact\n"
      "problem (4.7), min 1/2 p'Cp + (h - delta)'p over p >= 0, set up once (operator, FFT plans) and\n"
      "solved many times (each solve starts from the last pressure). heights: the undeformed gap h (m)\n"
      "per element, any shape with grid.size() values (np.inf where the body can never touch; NaN and\n"
      "-inf are an InputError). A solution whose contact reaches the grid's edge raises\n"
      "ResultLimitError unless allow_edge_contact=True (see solve()).")
      .def(py::init([](const Grid& g, const MaterialPair& mat, const HeightArray& heights, const std::string& kind,
                       bool allow_edge_contact) {
             std::vector<double> h = heights_of(g, heights);
             const OperatorKind operator_kind_given = operator_kind(kind);
             return PyNormalProblem{g, NormalProblem(g, mat, h, operator_kind_given), allow_edge_contact, h,
                                    std::make_shared<runs::HeightsAccuracy>(g, mat, operator_kind_given)};
           }),
           py::arg("grid"), py::arg("materials"), py::arg("heights"), py::arg("kind") = "auto",
           py::arg("allow_edge_contact") = false)
      .def(
          "solve",
          [](PyNormalProblem& self, const Opt& force, const Opt& approach, const std::string& backend, double tol,
             double certificate_tol, int max_iter, bool estimate) {
            const NormalSpec load = normal_load(force, approach);
            const SolverOptions solver = solver_spec(backend, tol, certificate_tol, max_iter);
            NormalResult r = [&] {
              py::gil_scoped_release release;
              const auto start = std::chrono::steady_clock::now();
              NormalResult out{self.grid, self.problem.solve(load, solver), {}, {}};
              const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
              if (estimate) out.accuracy = self.accuracy->estimate(self.heights, load, solver, out.s, seconds);
              return out;
            }();
            return checked(std::move(r), solver.certificate_tol, self.allow_edge_contact, "NormalProblem");
          },
          py::kw_only(), py::arg("force") = py::none(), py::arg("approach") = py::none(), py::arg("backend") = "auto",
          py::arg("tol") = 1e-9, py::arg("certificate_tol") = 1e-6, py::arg("max_iter") = 1000,
          py::arg("estimate") = false,
          (std::string("solve(*, force=None, approach=None, ..., estimate=False) -> NormalSolution\n\n"
                       "Force control (force=P, N; 2-D N/m; the approach is its multiplier) or approach control\n"
                       "(approach=delta, m). estimate=True: also the solution's .accuracy, the same load solved on\n"
                       "grids of 2 and 4 times the element size, the heights carried to them by cubic\n"
                       "interpolation (exact for a quadratic profile), at 0.25-0.4 of the solve's time (cost_fraction)\n"
                       "(docs/accuracy.md). ") +
           kSolverArgs)
              .c_str())
      .def(
          "set_heights",
          [](PyNormalProblem& self, const HeightArray& h) {
            self.heights = heights_of(self.grid, h);
            self.problem.set_heights(self.heights);
          },
          py::arg("heights"), "set_heights(heights): move the body (a new undeformed gap, m)")
      .def_readwrite("allow_edge_contact", &PyNormalProblem::allow_edge_contact, kAllowEdgeContact)
      .def_property_readonly("grid", [](const PyNormalProblem& self) { return self.grid; });

  py::class_<TangentialResult>(m, "TangentialSolution",
                               "A solution of the tangential problem (3.25)/(4.8) with its normal solution.")
      .def_property_readonly("pressure", [](const TangentialResult& r) { return grid_array(r.grid, r.s.normal.pressure); },
                             "pressure (Pa) per element")
      .def_property_readonly("tx", [](const TangentialResult& r) { return grid_array(r.grid, r.s.tx); },
                             "traction on the body, x (Pa)")
      .def_property_readonly("ty", [](const TangentialResult& r) { return grid_array(r.grid, r.s.ty); },
                             "traction on the body, y (Pa; 2-D: 0)")
      .def_property_readonly("sx", [](const TangentialResult& r) { return grid_array(r.grid, r.s.sx); },
                             "slip increment of the step, x (m; rolling: per unit of travel)")
      .def_property_readonly("sy", [](const TangentialResult& r) { return grid_array(r.grid, r.s.sy); },
                             "slip increment of the step, y")
      .def_property_readonly("bound", [](const TangentialResult& r) { return grid_array(r.grid, r.s.bound); },
                             "friction bound f(p) (Pa)")
      .def_property_readonly("state", [](const TangentialResult& r) { return grid_array(r.grid, r.s.state); },
                             "0 free, 1 stick, 2 slip")
      .def_property_readonly("approach", [](const TangentialResult& r) { return r.s.normal.approach; }, "approach (m)")
      .def_property_readonly("force", [](const TangentialResult& r) { return r.s.normal.force; },
                             "normal force sum p A (N; 2-D N/m)")
      .def_property_readonly(
          "amplitudes", [](const TangentialResult& r) { return r.s.amplitudes; },
          "the rigid modes (given or solved): shift x, y (m) and angle (rad); rolling: creepage x, y and spin (1/m)")
      .def_property_readonly("resultants", [](const TangentialResult& r) { return r.s.resultants; },
                             "(Fx, Fy, Mz) on the body (N, N m; 2-D per unit length)")
      .def_property_readonly("n_stick", [](const TangentialResult& r) { return r.s.n_stick; })
      .def_property_readonly("n_slip", [](const TangentialResult& r) { return r.s.n_slip; })
      .def_property_readonly("stick_area", [](const TangentialResult& r) { return r.s.stick_area; },
                             "area of the stick zone (m^2; 2-D: its length, m)")
      .def_property_readonly("converged", [](const TangentialResult& r) {
        return r.s.report.status == SolveStatus::converged && r.s.normal.report.status == SolveStatus::converged &&
               r.s.outer.converged;
      })
      .def_property_readonly("report", [](const TangentialResult& r) { return to_python(output::to_json(r.s.report)); },
                             "the tangential solver's report (its certificate holds the normal residuals too)")
      .def_property_readonly("limits", [](const TangentialResult& r) { return to_python(r.limits); }, kLimitsDoc)
      .def_property_readonly(
          "accuracy", [](const TangentialResult& r) { return r.accuracy.is_null() ? py::object(py::none()) : to_python(r.accuracy); },
          "estimate=True: the estimated discretisation error of the step, as summary.json's 'accuracy'\n"
          "block (the normal quantities, and as bands Fx, Fy, Mz, the shift or creepage solved for, stick\n"
          "and slip areas; or 'unavailable' and why); None otherwise");

  py::class_<PyTangentialProblem>(
      m, "TangentialProblem",
      "TangentialProblem(grid, materials, heights, mu=None, tresca=None, kind='auto',\n"
      "allow_edge_contact=False): the tangential problem (3.25)/(4.8) on top of the normal one, with\n"
      "Coulomb (mu) or Tresca (a bound, Pa) friction; heights as for NormalProblem. A solution whose\n"
      "contact reaches the grid's edge raises ResultLimitError unless allow_edge_contact=True (the\n"
      "step is taken all the same: the history goes on from it).\n"
      "It keeps its loading history: successive step() calls are a history with memory\n"
      "(Cattaneo-Mindlin), roll() marches from the current state; reset() forgets it.\n"
      "Each rigid mode is given by its amplitude or by its resultant (then solved for):\n"
      "  step:           shift_x | force_x (m | N), shift_y | force_y, angle | moment_z (rad | N m)\n"
      "  steady_rolling: creepage_x | force_x, creepage_y | force_y, spin | moment_z (1/m | N m)\n"
      "Forces are on the body (a shift in +x gives Fx < 0).\n"
      "estimate=True on a call: its solution's .accuracy, the history taken again on grids of 2 and 4\n"
      "times the element size (docs/accuracy.md \"Problems given by their heights\").")
      .def(py::init([](const Grid& g, const MaterialPair& mat, const HeightArray& heights, const Opt& mu,
                       const Opt& tresca, const std::string& kind, bool allow_edge_contact) {
             std::vector<double> h = heights_of(g, heights);
             const FrictionLaw friction = friction_of(mu, tresca);
             const OperatorKind operator_kind_given = operator_kind(kind);
             return PyTangentialProblem{TangentialProblem(g, mat, h, friction, operator_kind_given), allow_edge_contact,
                                        std::make_shared<runs::TangentialAccuracy>(g, mat, std::move(h), friction,
                                                                                   operator_kind_given)};
           }),
           py::arg("grid"), py::arg("materials"), py::arg("heights"), py::arg("mu") = py::none(),
           py::arg("tresca") = py::none(), py::arg("kind") = "auto", py::arg("allow_edge_contact") = false)
      .def(
          "step",
          [](PyTangentialProblem& self, const Opt& force, const Opt& approach, const Opt& shift_x, const Opt& force_x,
             const Opt& shift_y, const Opt& force_y, const Opt& angle, const Opt& moment_z, const std::string& backend,
             double tol, double certificate_tol, int max_iter, bool estimate) {
            TangentialLoad load;
            load.normal = normal_load(force, approach);
            load.modes = {mode(shift_x, "shift_x", force_x, "force_x"), mode(shift_y, "shift_y", force_y, "force_y"),
                          mode(angle, "angle", moment_z, "moment_z")};
            const SolverOptions solver = solver_spec(backend, tol, certificate_tol, max_iter);
            runs::TangentialCall call{runs::TangentialCall::Kind::step, load, {}, 0.0, solver};
            TangentialResult r = self.take(call, estimate, [&] { return self.problem.step(load, solver); });
            return checked(std::move(r), solver.certificate_tol, self.allow_edge_contact, "TangentialProblem");
          },
          py::kw_only(), py::arg("force") = py::none(), py::arg("approach") = py::none(),
          py::arg("shift_x") = py::none(), py::arg("force_x") = py::none(), py::arg("shift_y") = py::none(),
          py::arg("force_y") = py::none(), py::arg("angle") = py::none(), py::arg("moment_z") = py::none(),
          py::arg("backend") = "auto", py::arg("tol") = 1e-9, py::arg("certificate_tol") = 1e-6,
          py::arg("max_iter") = 1000, py::arg("estimate") = false,
          (std::string("step(*, force|approach, shift_x|force_x, shift_y|force_y, angle|moment_z, ...) -> "
                       "TangentialSolution\n\n"
                       "One quasi-static step of the loading history (shift, torsion): amplitudes are TOTAL rigid\n"
                       "displacements since the unloaded state. "
                       "estimate=True: also the solution's .accuracy, the same history taken on grids of 2 and 4\n"
                       "times the element size (docs/accuracy.md \"Problems given by their heights\"). ") +
           kSolverArgs)
              .c_str())
      .def(
          "steady_rolling",
          [](PyTangentialProblem& self, const Opt& force, const Opt& approach, const Opt& creepage_x, const Opt& force_x,
             const Opt& creepage_y, const Opt& force_y, const Opt& spin, const Opt& moment_z, double velocity,
             const std::string& backend, double tol, double certificate_tol, int max_iter, bool estimate) {
            const RollingLoad load =
                rolling_load(force, approach, creepage_x, force_x, creepage_y, force_y, spin, moment_z, velocity);
            const SolverOptions solver = solver_spec(backend, tol, certificate_tol, max_iter);
            runs::TangentialCall call{runs::TangentialCall::Kind::steady_rolling, {}, load, 0.0, solver};
            TangentialResult r =
                self.take(call, estimate, [&] { return self.problem.steady_rolling(load, solver); });
            return checked(std::move(r), solver.certificate_tol, self.allow_edge_contact, "TangentialProblem");
          },
          py::kw_only(), py::arg("force") = py::none(), py::arg("approach") = py::none(),
          py::arg("creepage_x") = py::none(), py::arg("force_x") = py::none(), py::arg("creepage_y") = py::none(),
          py::arg("force_y") = py::none(), py::arg("spin") = py::none(), py::arg("moment_z") = py::none(),
          py::arg("velocity") = 1.0, py::arg("backend") = "auto", py::arg("tol") = 1e-9,
          py::arg("certificate_tol") = 1e-6, py::arg("max_iter") = 1000, py::arg("estimate") = false,
          (std::string("steady_rolling(*, force|approach, creepage_x|force_x, creepage_y|force_y, spin|moment_z,\n"
                       "               velocity=1.0, ...) -> TangentialSolution\n\n"
                       "Steady rolling in +x (Carter, Kalker): creepages and spin given, or the forces (then the\n"
                       "creepages are solved for: solution.amplitudes). "
                       "estimate=True: also the solution's .accuracy, the same history taken on grids of 2 and 4\n"
                       "times the element size (docs/accuracy.md \"Problems given by their heights\"). ") +
           kSolverArgs)
              .c_str())
      .def(
          "roll",
          [](PyTangentialProblem& self, double distance, const Opt& force, const Opt& approach, const Opt& creepage_x,
             const Opt& force_x, const Opt& creepage_y, const Opt& force_y, const Opt& spin, const Opt& moment_z,
             double velocity, const std::string& backend, double tol, double certificate_tol, int max_iter,
             bool estimate) {
            const RollingLoad load =
                rolling_load(force, approach, creepage_x, force_x, creepage_y, force_y, spin, moment_z, velocity);
            const SolverOptions solver = solver_spec(backend, tol, certificate_tol, max_iter);
            runs::TangentialCall call{runs::TangentialCall::Kind::roll, {}, load, distance, solver};
            TangentialResult r =
                self.take(call, estimate, [&] { return self.problem.roll(load, distance, solver); });
            return checked(std::move(r), solver.certificate_tol, self.allow_edge_contact, "TangentialProblem");
          },
          py::arg("distance"), py::kw_only(), py::arg("force") = py::none(), py::arg("approach") = py::none(),
          py::arg("creepage_x") = py::none(), py::arg("force_x") = py::none(), py::arg("creepage_y") = py::none(),
          py::arg("force_y") = py::none(), py::arg("spin") = py::none(), py::arg("moment_z") = py::none(),
          py::arg("velocity") = 1.0, py::arg("backend") = "auto", py::arg("tol") = 1e-9,
          py::arg("certificate_tol") = 1e-6, py::arg("max_iter") = 1000, py::arg("estimate") = false,
          (std::string("roll(distance, *, the arguments of steady_rolling) -> TangentialSolution\n\n"
                       "Transient rolling: marches `distance` (m) in +x from the current state (memory kept),\n"
                       "e.g. Cattaneo's state rolling into Carter's. "
                       "estimate=True: also the solution's .accuracy, the same history taken on grids of 2 and 4\n"
                       "times the element size (docs/accuracy.md \"Problems given by their heights\"). ") +
           kSolverArgs)
              .c_str())
      .def(
          "reset",
          [](PyTangentialProblem& self) {
            self.problem.reset();
            self.accuracy->reset();
          },
          "reset(): forget the loading history (back to the unloaded state)")
      .def_readwrite("allow_edge_contact", &PyTangentialProblem::allow_edge_contact, kAllowEdgeContact)
      .def_property_readonly("grid", [](const PyTangentialProblem& self) { return self.problem.grid(); });
}

}  // namespace dc::python
