// dyncontact.subsurface(case, ...): a normal or tangential case solved as solve() does, and the
// elastic field inside its bodies from the solved tractions (the case's "subsurface" block,
// apps/runs/subsurface_run.hpp) as NumPy arrays: per body the stresses (Voigt xx, yy, zz, yz, xz,
// xy, as subsurface.vti), the displacements, von Mises and Tresca's tau_1, of shape
// (depths, ny, nx[, components]) (2-D: ny = 1), with the depths and the element centres.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "errors.hpp"
#include "module_common.hpp"
#include "python_limits.hpp"
#include "python_runs.hpp"
#include "subsurface_run.hpp"

namespace dc::python {
namespace {

/// Components `comps` of the field as an array (depths, ny, nx, comps.size()).
py::array_t<double> field_components(const SubsurfaceResult& f, const std::vector<int>& comps) {
  const Grid& g = f.grid;
  const std::size_t n = g.size(), nd = f.depths.size(), nc = comps.size();
  py::array_t<double> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(nd), g.ny, g.nx, static_cast<py::ssize_t>(nc)});
  double* out = a.mutable_data();
  for (std::size_t k = 0; k < nd; ++k)
    for (std::size_t e = 0; e < n; ++e)  // e = i + nx j: the (ny, nx) order
      for (std::size_t c = 0; c < nc; ++c) out[(k * n + e) * nc + c] = f.component(k, comps[c])[e];
  return a;
}

/// A measure (layout k * N + e) as an array (depths, ny, nx).
py::array_t<double> measure_array(const Grid& g, std::size_t depths, const std::vector<double>& v) {
  py::array_t<double> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(depths), g.ny, g.nx});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::array_t<double> vector_array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict subsurface(const py::object& case_arg, const py::object& depths, const py::object& bodies,
                    const py::object& out, bool progress) {
  nlohmann::json document = case_document(case_arg);
  const auto problem = document.is_object() ? document.find("problem") : document.end();
  const bool static_problem = problem != document.end() && problem->is_string() &&
                              (*problem == "normal" || *problem == "tangential");
  if (static_problem) {  // the field is what is asked for: the block, with these depths and bodies
    if (!document.contains("subsurface")) document["subsurface"] = nlohmann::json::object();
    nlohmann::json& block = document["subsurface"];
    if (block.is_object()) {
      if (!depths.is_none()) block["depths"] = from_python(depths, "subsurface.depths");
      if (!bodies.is_none()) block["bodies"] = from_python(bodies, "subsurface.bodies");
    }
  }
  const Case c = build_case(document, ".");
  if (c.problem != ProblemKind::normal && c.problem != ProblemKind::tangential)
    throw InputError("problem", std::string("subsurface() takes normal and tangential cases, got '") +
                                    to_string(c.problem) + "'");
  StaticSolve r = solve_static_case(c, out, progress);
  py::dict result;
  result["summary"] = to_python(r.summary);
  if (!r.run.subsurface) throw InputError("subsurface", "the run computed no subsurface field");
  const runs::SubsurfaceRun& field = *r.run.subsurface;
  const Grid& g = r.solved.grid;
  std::vector<double> x(static_cast<std::size_t>(g.nx)), y(static_cast<std::size_t>(g.ny));
  for (int i = 0; i < g.nx; ++i) x[static_cast<std::size_t>(i)] = g.xc(i);
  for (int j = 0; j < g.ny; ++j) y[static_cast<std::size_t>(j)] = g.yc(j);
  result["depths"] = vector_array(field.depths);
  result["x"] = vector_array(x);
  result["y"] = vector_array(y);
  py::dict per_body;
  for (const runs::BodySubsurface& b : field.bodies) {
    py::dict d;
    d["stress"] = field_components(b.field, {kSxx, kSyy, kSzz, kSyz, kSxz, kSxy});
    d["displacement"] = field_components(b.field, {kUx, kUy, kUz});
    d["von_mises"] = measure_array(g, field.depths.size(), b.measures.von_mises);
    d["tresca"] = measure_array(g, field.depths.size(), b.measures.tresca);
    per_body[py::str(b.name)] = d;
  }
  result["bodies"] = per_body;
  result["rigid"] = py::cast(field.rigid);
  enforce_summary_limits(r.summary, result, r.advice);
  enforce_accuracy_target(r.summary, result, r.advice);
  return result;
}

}  // namespace

void bind_subsurface(py::module_& m) {
  m.def("subsurface", &subsurface, py::arg("case"), py::arg("depths") = py::none(), py::arg("bodies") = py::none(),
        py::arg("out") = py::none(), py::arg("progress") = false,
        "subsurface(case, depths=None, bodies=None, out=None, progress=False) -> dict\n\n"
        "Solves a normal or tangential case (a dict, JSON text or path, as solve()) and returns the\n"
        "linear elastic field inside its bodies from the solved tractions (docs/subsurface.md): the\n"
        "case's \"subsurface\" block (added when absent), its depths and bodies replaced by `depths`\n"
        "(m into each body, >= 0 and increasing: a sequence or 'start:stop:count') and `bodies`\n"
        "('base', 'body') when given. The dict holds\n"
        "  depths (nd,), x (nx,), y (ny,)    the depths and the element centres (2-D: y = [0], ny = 1)\n"
        "  bodies: {name: {stress (nd, ny, nx, 6): Voigt xx, yy, zz, yz, xz, xy (Pa, tension positive),\n"
        "                  displacement (nd, ny, nx, 3), von_mises (nd, ny, nx), tresca (nd, ny, nx)}}\n"
        "  rigid                              the bodies named but rigid (no field)\n"
        "  summary                            the summary (summary.json's keys, with 'subsurface' maxima)\n"
        "in the arrays' order of subsurface.vti (x fastest, then y, then depth). With `out` the run's\n"
        "files are written there as by `dyncontact solve`: summary.json, fields.csv, subsurface.vti\n"
        "(evenly spaced depths) and the planes' CSV. Errors as solve(): InputError naming the key\n"
        "(subsurface.depths, subsurface.bodies, ...), ResultLimitError and AccuracyError with this dict\n"
        "as .result.");
}

}  // namespace dc::python
