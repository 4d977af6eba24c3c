// dyncontact validate CASE.json [--set path=value ...]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "analytic_reference.hpp"
#include "errors.hpp"
#include "resource_estimate.hpp"
#include "dynamic_limits.hpp"
#include "fe_body_estimate.hpp"
#include "result_limits.hpp"
#include "cli_common.hpp"
#include "finite_run.hpp"
#include "paper_cylinder_run.hpp"
#include "commands.hpp"

namespace dc::cli {
namespace {

struct ValidateArgs {
  std::string case_path;
  std::vector<std::string> sets;
};

std::string material_text(const Elastic& m) {
  if (m.rigid) return "rigid";
  char b[96];
  std::snprintf(b, sizeof b, "E = %.4g Pa, nu = %.4g (G = %.4g Pa)", m.E, m.nu, m.G);
  return b;
}

std::string profile_text(const ProfileSpec& p, int dimension) {
  char b[160];
  switch (p.type) {
    case ProfileType::sphere: std::snprintf(b, sizeof b, "sphere, R = %.4g m", p.radius); break;
    case ProfileType::ellipsoid:
      std::snprintf(b, sizeof b, "ellipsoid, Rx = %.4g m, Ry = %.4g m", p.radius_x, p.radius_y);
      break;
    case ProfileType::cylinder:
      if (dimension == 3 && p.length > 0.0)
        std::snprintf(b, sizeof b, "cylinder along y, R = %.4g m, length %.4g m", p.radius, p.length);
      else
        std::snprintf(b, sizeof b, "cylinder, R = %.4g m", p.radius);
      break;
    case ProfileType::flat_punch:
      if (p.inner_radius > 0.0)
        std::snprintf(b, sizeof b, "annular flat punch, radii %.4g m to %.4g m", p.inner_radius, p.radius);
      else
        std::snprintf(b, sizeof b, "flat punch, radius %.4g m", p.radius);
      break;
    case ProfileType::quadratic: std::snprintf(b, sizeof b, "quadratic, h = %.4g x^2 + %.4g y^2", p.a, p.b); break;
    case ProfileType::table:
      std::snprintf(b, sizeof b, "table '%s' (%zu points)", p.file.c_str(), p.table_h.size());
      break;
  }
  return b;
}

int run_validate(const ValidateArgs& args) {
  const Case c = load_case(args.case_path, args.sets);
  const bool two_d = c.dimension == 2;
  std::printf("case '%s': problem %s, %s\n", c.name.c_str(), to_string(c.problem),
              two_d ? "2-D (plane strain, per unit length)" : "3-D");
  if (!c.description.empty()) std::printf("  %s\n", c.description.c_str());
  const bool static_problem = c.problem == ProblemKind::normal || c.problem == ProblemKind::tangential;
  if (static_problem || c.has_block("materials")) {
    // A finite-element body's compliance is its mesh's (fe_body), not the rigid stand-in of the pair.
    const std::string body = c.fe_body ? "finite elements (fe_body)" : material_text(c.materials.body);
    std::printf("  body:     %s\n  base:     %s\n  E*:       %.4g Pa%s\n", body.c_str(),
                material_text(c.materials.base).c_str(), c.materials.E_star(),
                c.fe_body ? " (the half-space's share)" : "");
  }
  if (static_problem || c.has_block("profile"))
    std::printf("  profile:  %s\n", profile_text(c.profile, c.dimension).c_str());
  if (static_problem || c.has_block("normal")) {
    if (c.normal.control == Control::force)
      std::printf("  normal:   force %.4g %s\n", c.normal.value, two_d ? "N/m" : "N");
    else
      std::printf("  normal:   approach %.4g m\n", c.normal.value);
  }
  if (c.friction) {
    const FrictionSpec& f = *c.friction;
    if (f.law == FrictionLawKind::coulomb) std::printf("  friction: Coulomb, mu = %.4g\n", f.mu);
    else if (f.law == FrictionLawKind::tresca) std::printf("  friction: Tresca, bound %.4g Pa\n", f.bound);
    else std::printf("  friction: table of %zu points\n", f.pressure.size());
  }
  const Grid& g = c.grid;
  if (static_problem || c.has_block("grid")) {
    if (two_d)
      std::printf("  grid:     %d strips, x in [%.4g, %.4g] m, dx = %.4g m\n", g.nx, g.x0, g.x_max(), g.dx);
    else
      std::printf("  grid:     %d x %d = %zu elements, x in [%.4g, %.4g] m, y in [%.4g, %.4g] m, dx = %.4g m, "
                  "dy = %.4g m\n",
                  g.nx, g.ny, g.size(), g.x0, g.x_max(), g.y0, g.y_max(), g.dx, g.dy);
  }
  if (c.fe_body && c.fe_body->shape != FeShape::mesh) {
    if (c.fe_body->contact_size > 0.0) {
      std::printf("  face:     contact_size %.4g m (given)\n", c.fe_body->contact_size);
    } else {
      const double bound = default_contact_size_bound(*c.fe_body, c.materials.base, g);
      if (bound == 0.0)
        std::printf("  face:     contact_size a quarter of the coarse elements (the grid holds no origin to bound it)");
      else if (bound == face_cell_bound(*c.fe_body, c.materials.base, g))
        std::printf("  face:     contact_size at most %.4g m (%.2g grid cells: the body is %.3g times as compliant as "
                    "the half-space)",
                    bound, bound / std::min(g.dx, g.dy), body_compliance_ratio(*c.fe_body, c.materials.base));
      else
        std::printf("  face:     contact_size at most %.4g m (an eighth of the grid's reach)", bound);
      std::printf("%s\n", c.problem == ProblemKind::finite
                              ? "; meshed again to the contact found when coarser than a third of its half-width"
                              : "");
    }
    if (const auto e = runs::estimate_fe_body(c)) {
      std::printf("  body:     about %.3g tetrahedra, %.3g dofs; about %.3g GB and %.2g s (one thread; a remesh to "
                  "the contact found can add to it)\n",
                  e->tetrahedra, e->dofs, e->memory_bytes / 1e9, e->seconds);
      runs::check_fe_body_fits(c);  // throws naming fe_body.elements or fe_body.contact_size
    }
  }
  if (static_problem) {
    const runs::ResourceEstimate est = runs::estimate_resources(c);
    std::printf("  estimate: %s operator, about %.3g MB and %.2g s per solve%s\n            (%s)\n", est.operator_kind.c_str(),
                est.memory_bytes / 1e6, est.seconds,
                est.solves > 1 ? (", " + std::to_string(est.solves) + " solves").c_str() : "", est.basis.c_str());
    if (est.memory_bytes > 4e9)
      std::fprintf(stderr, "warning: grid: the estimated memory (%.3g GB) may exceed this machine's\n",
                   est.memory_bytes / 1e9);
  }
  std::printf("  solver:   backend %s, tol %.3g, certificate tolerance %.3g, at most %d iterations\n",
              to_string(c.solver.backend), c.solver.tol, c.solver.certificate_tol, c.solver.max_iter);
  if (const auto ref = output::analytic_reference(c)) {
    const char* label = ref->kind == "boussinesq_flat_punch" ? "Boussinesq" : "Hertz";
    if (two_d)
      std::printf("  %s:    a = %.4g m (%.1f strips across), p0 = %.4g Pa\n", label, ref->semi_axis_x,
                  2.0 * ref->semi_axis_x / g.dx, ref->max_pressure);
    else
      std::printf("  %s:    a = %.4g m, b = %.4g m (%.1f x %.1f elements across), %s = %.4g Pa, force %.4g N, "
                  "approach %.4g m\n",
                  label, ref->semi_axis_x, ref->semi_axis_y, 2.0 * ref->semi_axis_x / g.dx,
                  2.0 * ref->semi_axis_y / g.dy, ref->kind == "boussinesq_flat_punch" ? "centre p" : "p0",
                  ref->max_pressure, ref->force, ref->approach.value_or(NAN));
    const bool beyond = ref->semi_axis_x > std::min(-g.x0, g.x_max()) ||
                        (!two_d && ref->semi_axis_y > std::min(-g.y0, g.y_max()));
    ContactSize size;
    size.half_width_x = ref->semi_axis_x;
    size.half_width_y = ref->semi_axis_y;
    size.edge_fraction = beyond ? 1.0 : 0.0;
    size.across_x = static_cast<int>(2.0 * ref->semi_axis_x / g.dx);
    size.across_y = two_d ? size.across_x : static_cast<int>(2.0 * ref->semi_axis_y / g.dy);
    for (ResultLimit l : result_limits(c, size)) {
      if (l.key == "grid" && beyond)  // an estimate: the share of the edge is not known before solving
        l.message = std::string("the ") + label + " contact reaches beyond the grid: " +
                    l.message.substr(l.message.find(": ") + 2);
      if (l.error) throw InputError(l.key, l.message);
      std::fprintf(stderr, "warning: %s: %s\n", l.key.c_str(), l.message.c_str());
    }
    if (2.0 * ref->semi_axis_x / g.dx < 6.0 || (!two_d && 2.0 * ref->semi_axis_y / g.dy < 6.0))
      std::fprintf(stderr, "warning: grid: fewer than 6 elements across the contact; refine the grid\n");
  }
  if (c.problem == ProblemKind::paper_cylinder) runs::validate_paper_cylinder(c);
  else if (c.problem == ProblemKind::dynamic) {
    std::printf("dynamic: %.6g s in steps of %.6g s (%s), normal model %s, contact model %s, %s\n", c.dynamic->t_end,
                c.dynamic->dt, c.dynamic->bdf2 ? "bdf2" : "bdf1", to_string(c.dynamic->normal_model),
                to_string(c.dynamic->contact_model), c.friction ? "with friction" : "frictionless");
    if (const auto e = dynamics::estimate_dynamic_contact(c)) {
      if (e->load > 0.0)
        std::printf("  largest contact (Hertz, %.4g N): a = %.4g m, b = %.4g m (%.1f x %.1f elements across), "
                    "approach %.4g m\n",
                    e->load, e->half_width_x, e->half_width_y, 2.0 * e->half_width_x / g.dx,
                    2.0 * e->half_width_y / g.dy, e->approach);
      if (e->contact_time > 0.0)
        std::printf("  impact:   Hertz contact time %.4g s, %.1f steps of time.dt (at least %.0f needed)\n",
                    e->contact_time, e->steps_per_contact, dynamics::kMinStepsPerContact);
    }
    for (const ResultLimit& l : dynamics::dynamic_limits_before(c))  // throws for the errors
      std::fprintf(stderr, "warning: %s: %s\n", l.key.c_str(), l.message.c_str());
    if (c.sweep) {  // every run's case read and checked
      const std::vector<SweepPoint> points = sweep_points(c);
      for (const SweepPoint& p : points) dynamics::dynamic_limits_before(p.run);
      std::printf("sweep: %zu runs over %s\n", points.size(), c.sweep->key.c_str());
    }
  }
  else if (c.problem == ProblemKind::finite && !runs::finite_supported())
    std::printf("note: this build has no finite-element support (needs libgmsh-dev, libsuitesparse-dev)\n");
  else if (c.problem != ProblemKind::normal && c.problem != ProblemKind::tangential && c.problem != ProblemKind::finite)
    std::printf("note: the solver for problem '%s' is not implemented in this build yet\n", to_string(c.problem));
  std::printf("valid\n");
  return runs::kExitOk;
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* sub = app.add_subcommand("validate", "Check a case file and describe it, without solving");
  sub->footer(
      "Reads and checks a case file exactly as `solve` would (unknown keys, types, ranges, the grid against the "
      "profile) and prints what it understood: materials and E*, profile, load, grid size and spacing, and the "
      "closed-form (Hertz/Boussinesq) contact size, peak pressure and approach where one applies, with a warning "
      "when the grid is too small or too coarse for that contact. Exit code 0 when the case is valid, 2 "
      "otherwise (the message names the offending key).");
  sub->add_option("case", args->case_path, "case file (JSON)")->required();
  sub->add_option("-s,--set", args->sets, "override a case key: path=value (repeatable)")->allow_extra_args(false);
  sub->callback([args, &exit_code] { exit_code = run_validate(*args); });
}

}  // namespace dc::cli
