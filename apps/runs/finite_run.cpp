#include "finite_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <utility>

#include "errors.hpp"
#include "exit_codes.hpp"
#include "interrupt.hpp"

#ifdef DYNCONTACT_WITH_FE
#include "static_field_files.hpp"
#include "finite_contact.hpp"
#include "plot_writer.hpp"
#include "progress.hpp"
#include "fe_body_estimate.hpp"
#include "result_limits.hpp"
#include "static_fields.hpp"
#include "summary_writer.hpp"
#include "tangential_run.hpp"
#include "vtu_writer.hpp"
#endif

namespace dc::runs {

#ifdef DYNCONTACT_WITH_FE

bool finite_supported() { return true; }

namespace {

/// The tangential steps (shift, torsion, histories) on the finite body; the summary of the last
/// step with "steps" for a history, as for the tangential problem.
nlohmann::json solve_tangential_steps(const Case& c, FiniteContact& fc, Progress& reporter,
                                      output::StaticFields& last_fields, Eigen::VectorXd& body_u,
                                      SolverReport& report) {
  TangentialProblem& problem = fc.tangential_problem(FrictionLaw::from_spec(*c.friction));
  const TangentialSpec& t = *c.tangential;
  const std::vector<TangentialLoad> loads = t.has_history ? t.history : std::vector<TangentialLoad>{t.load};
  nlohmann::json summary, steps = nlohmann::json::array();
  report.status = SolveStatus::converged;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const TangentialSolution sol = problem.step(loads[k], c.solver, reporter.callback());
    Case step_case = c;
    step_case.normal = loads[k].normal;
    last_fields = tangential_fields(sol, std::max(c.solver.certificate_tol, 1e-12));
    summary = tangential_summary(step_case, sol, last_fields);
    summary["step"] = static_cast<int>(k);
    steps.push_back(summary);
    if (sol.report.status != SolveStatus::converged || k + 1 == loads.size()) report = sol.report;
    if (k + 1 == loads.size()) body_u = fc.body_displacement(sol.tx, sol.ty, sol.normal.pressure);
  }
  if (t.has_history) summary["steps"] = steps;
  summary.erase("step");
  return summary;
}

/// The mean size of the face's elements over the contact (elements with p above the threshold).
double contact_face_element_size(const fe::ContactFace& face, const output::StaticFields& fields) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < fields.p.size(); ++k)
    if (fields.p[k] > fields.contact_threshold && face.face_element_sizes()[k] > 0.0) {
      sum += face.face_element_sizes()[k];
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

/// A solved finite case: what run_static returns, and the body for body.vtu.
struct FiniteRun {
  StaticRun run;
  std::unique_ptr<FiniteContact> contact;
  Eigen::VectorXd body_u;
};

/// Meshes `body` (the case's fe_body, or its remesh) and solves the case on it.
FiniteRun solve_finite_on(const Case& c, const FeBodySpec& body, bool progress) {
  const auto start = std::chrono::steady_clock::now();
  FiniteRun out;
  out.contact = std::make_unique<FiniteContact>(body, c.grid, c.materials.base, c.solver.operator_kind);
  FiniteContact& fc = *out.contact;
  if (progress)
    std::fprintf(stderr, "body: %zu dofs, %zu elements; meshed in %.3g s, factorised in %.3g s\n", fc.body().dofs(),
                 fc.body().mesh().elements.size(), fc.mesh_seconds(), fc.body().factorisation_seconds());
  nlohmann::json& s = out.run.summary;
  output::StaticFields fields;
  SolverReport& report = out.run.report;
  out.run.normal = c.normal;
  {
    Progress reporter("solving " + c.name + " (" + to_string(c.solver.backend) + ")", progress);
    if (c.tangential) {
      s = solve_tangential_steps(c, fc, reporter, fields, out.body_u, report);
      out.run.history = c.tangential->has_history;
      out.run.normal = c.tangential->has_history ? c.tangential->history.back().normal : c.tangential->load.normal;
    } else {
      FiniteNormalSolution sol = fc.solve_normal(c.normal, c.solver, reporter.callback());
      fields = output::normal_fields(sol.contact.pressure, std::max(c.solver.certificate_tol, 1e-12));
      s = output::normal_summary(c, sol.contact, fields);
      out.body_u = sol.body_displacement;
      report = sol.contact.report;
    }
    reporter.finish();
  }
  report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s["solver"]["time_s"] = report.time_s;
  double max_u = 0.0;
  for (Eigen::Index k = 0; k + 2 < out.body_u.size(); k += 3) max_u = std::max(max_u, out.body_u.segment<3>(k).norm());
  s["body_dofs"] = fc.body().dofs();
  s["body_elements"] = fc.body().mesh().elements.size();
  s["max_body_displacement"] = max_u;
  s["mesh_time_s"] = fc.mesh_seconds();
  s["factorisation_time_s"] = fc.body().factorisation_seconds();
  s["program"] = c.fe_body->program;
  s["contact_face_element_size"] = contact_face_element_size(fc.face(), fields);
  s["tilt"] = {fc.tilt()[0], fc.tilt()[1]};
  out.run.fields.push_back(std::move(fields));
  out.run.converged = report.status == SolveStatus::converged;
  out.run.interrupted = interrupt_requested();
  return out;
}

/// The remesh refines the face over the disk of kRemeshRadius times the larger half-width found.
constexpr double kRemeshRadius = 1.5;

/// The contact's half-widths found by the first solve, smaller first: the smaller (an ellipse's
/// minor semi-axis) sets the element size, the larger the refined disk.
std::pair<double, double> found_half_widths(const nlohmann::json& s) {
  const double x = s.value("contact_half_width_x", 0.0), y = s.value("contact_half_width_y", 0.0);
  return std::minmax(x, y);
}

/// The contact_size of a remesh when the case leaves it to the default and the face's elements
/// came out coarser than kFaceResolvedShare of the contact's half-width (a grid wide against
/// its contact): kRemeshShare of it, and no coarser than a compliant body's face_cell_bound;
/// 0 when none is needed or it would not help (bounded below by half a grid cell: finer faces
/// cannot show on the grid).
double remesh_contact_size(const Case& c, const nlohmann::json& s) {
  // The case's own choice, or its own mesh file: a warning, no remesh.
  if (c.fe_body->contact_size > 0.0 || c.fe_body->shape == FeShape::mesh) return 0.0;
  const double half_width = found_half_widths(s).first;
  const double face = s.value("contact_face_element_size", 0.0);
  if (!(half_width > 0.0 && face > kFaceResolvedShare * half_width)) return 0.0;
  const double size = std::max(std::min(kRemeshShare * half_width, face_cell_bound(*c.fe_body, c.materials.base, c.grid)),
                                0.5 * std::min(c.grid.dx, c.grid.dy));
  return size < 0.8 * face ? size : 0.0;
}

/// Solves the case; with the default contact_size, once more on a face remeshed to the contact
/// found when the first mesh did not resolve it (summary.json's "remeshed").
FiniteRun solve_finite(const Case& c, bool progress) {
  check_fe_body_fits(c);  // before meshing: a body the memory cannot hold is bad input
  FiniteRun first = solve_finite_on(c, *c.fe_body, progress);
  const double size = first.run.interrupted ? 0.0 : remesh_contact_size(c, first.run.summary);
  if (size == 0.0) {
    first.run.summary["remeshed"] = false;
    return first;
  }
  if (progress)
    std::fprintf(stderr, "remeshing: the face's elements (%.3g m) are coarse for the contact found; contact_size %.3g m\n",
                 first.run.summary["contact_face_element_size"].get<double>(), size);
  FeBodySpec refined = *c.fe_body;
  refined.contact_size = size;
  if (!refined.refine_radius)  // the contact found, with a margin, rather than the whole grid
    refined.refine_radius = std::min(grid_refine_radius(c.grid), kRemeshRadius * found_half_widths(first.run.summary).second);
  FiniteRun out = solve_finite_on(c, refined, progress);
  out.run.report.time_s += first.run.report.time_s;
  out.run.summary["solver"]["time_s"] = out.run.report.time_s;
  out.run.summary["remeshed"] = true;
  return out;
}

}  // namespace

StaticRun run_finite_static(const Case& c, bool progress) { return solve_finite(c, progress).run; }

int run_finite(const Case& c, const std::string& dir, bool quiet) {
  FiniteRun f = solve_finite(c, !quiet);
  nlohmann::json& s = f.run.summary;
  const SolverReport& report = f.run.report;
  const FiniteContact& fc = *f.contact;
  nlohmann::json files = {{"summary", "summary.json"}, {"body", "body.vtu"}};
  output::StaticFieldFiles surface{&f.run.fields, c.output.fields};
  output::write_static_field_files(dir, c.grid, surface, files, s);
  output::write_body_vtu((std::filesystem::path(dir) / "body.vtu").string(), fc.body().mesh(), f.body_u,
                 fc.body().element_stress(f.body_u));
  if (c.output.plots && !f.run.interrupted) {  // as for the local problems: the contact fields
    Case plotted = c;
    plotted.normal = f.run.normal;
    nlohmann::json plots = nlohmann::json::array();
    for (const auto& p : output::write_static_plots(dir, plotted, f.run.fields.back()))
      plots.push_back(std::filesystem::path(p).filename().string());
    files["plots"] = plots;
  }
  s["files"] = files;
  const std::vector<ResultLimit> limits = attach_result_limits(c, s);
  const std::string summary_path = output::write_summary(dir, s);
  if (!quiet) {
    std::printf("%s: %s (%s, %d iterations, %.3g s; certificate %.2e)\n", c.name.c_str(), to_string(report.status),
                report.backend.c_str(), report.iterations, report.time_s, report.certificate.worst());
    std::printf("  %-16s %-12.5g N\n  %-16s %-12.5g m\n  %-16s %-12.5g Pa\n  %-16s %-12.5g m\n", "normal force",
                s["normal_force"].get<double>(), "approach", s["approach"].get<double>(), "max pressure",
                s["max_pressure"].get<double>(), "body displ.", s["max_body_displacement"].get<double>());
    if (c.tangential)
      std::printf("  %-16s [%.5g, %.5g] N, moment %.5g N m\n", "tangential force",
                  s["tangential_force"][0].get<double>(), s["tangential_force"][1].get<double>(),
                  s["twisting_moment"].get<double>());
    std::printf("wrote %s\n", summary_path.c_str());
    std::fflush(stdout);
  }
  if (report_limits(limits, dir)) return kExitBadInput;
  if (report.status != SolveStatus::converged) {
    if (c.solver.accept_unconverged) return kExitOk;
    std::cerr << "error: solver: did not converge (" << report.message << "); results written to " << dir << "\n";
    return kExitUnconverged;
  }
  return kExitOk;
}

#else

bool finite_supported() { return false; }

[[noreturn]] void no_finite_support() {
  throw InputError("problem", "'finite' needs finite-element support: this build has none (install libgmsh-dev and "
                              "libsuitesparse-dev, then reconfigure with -DDYNCONTACT_WITH_FE=ON)");
}

int run_finite(const Case&, const std::string&, bool) { no_finite_support(); }

StaticRun run_finite_static(const Case&, bool) { no_finite_support(); }

#endif

}  // namespace dc::runs
