#include "tangential_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "accuracy_run.hpp"
#include "finite_run.hpp"
#include "fatigue_over_run.hpp"
#include "fatigue_run.hpp"
#include "first_yield.hpp"
#include "shakedown_run.hpp"
#include "interrupt.hpp"
#include "normal_run.hpp"
#include "progress.hpp"
#include "solve_case.hpp"
#include "summary_entries.hpp"
#include "summary_writer.hpp"
#include "wear_run.hpp"
#include "temperature_run.hpp"

namespace dc::runs {
namespace {

/// A solver leaves round-off pressures outside the contact; those within the certificate
/// tolerance of the peak count as free (as in run_normal).
double contact_threshold(const Case& c) { return std::max(c.solver.certificate_tol, 1e-12); }

nlohmann::json pair(double x, double y) { return nlohmann::json::array({x, y}); }

nlohmann::json friction_json(const FrictionSpec& f) {
  nlohmann::json j = {{"law", to_string(f.law)}};
  if (f.law == FrictionLawKind::coulomb) j["mu"] = f.mu;
  if (f.law == FrictionLawKind::tresca) j["bound"] = f.bound;
  if (f.law == FrictionLawKind::table) {
    j["pressure"] = f.pressure;
    j["bound"] = f.bound_table;
  }
  return j;
}

/// Keys of the whole case that are not per step (left out of the entries of "steps").
bool case_level_key(const std::string& key) {
  static const char* keys[] = {"schema", "name",     "problem",  "dimension", "version",
                               "grid",   "materials", "profile", "friction",  "regime"};
  return std::any_of(std::begin(keys), std::end(keys), [&](const char* k) { return key == k; });
}

bool has_history(const Case& c) { return c.tangential && c.tangential->has_history; }

/// summary.json's "energy" of a tangential solution (CASES.md). Every step: `dissipated`, the
/// frictional work sum -tau . ds A of the step (J; 2-D J/m). Steady rolling at speed V (per step
/// of travel dx, dt = dx / V) also the powers (W; 2-D W/m): `frictional_power` = dissipated / dt,
/// `creep_power` -(F_x xi + F_y eta + M_z phi) V, and `scheme_power` the upwind scheme's share
/// sum tau . (C - S C)(tau, p) A / dt, with creep = frictional + scheme to round-off
/// (TangentialSolution::convective_elastic_work; O(dx): the continuum has none).
nlohmann::json energy_json(const Case& c, const TangentialSolution& sol, const output::StaticFields& f) {
  double work = 0.0;
  for (double w : f.dissipation) work += w;
  work *= c.grid.area();
  // A roll over a distance: every marching step's work (the fields are the last step's).
  nlohmann::json e = {{"dissipated", std::isfinite(sol.marched_frictional_work) ? sol.marched_frictional_work : work}};
  if (sol.rolling && std::isfinite(sol.convective_elastic_work) && c.tangential) {
    const double V = c.tangential->rolling.velocity, rate = V / c.grid.dx;
    const auto& a = sol.amplitudes;
    const auto& r = sol.resultants;
    const double creep = -(r[0] * a[0] + r[1] * a[1] + r[2] * a[2]) * V;
    const double frictional = work * rate, scheme = sol.convective_elastic_work * rate;
    e["frictional_power"] = frictional;
    e["creep_power"] = creep;
    e["scheme_power"] = scheme;
    e["balance"] = creep != 0.0 ? (creep - frictional - scheme) / std::abs(creep) : 0.0;
  }
  return e;
}

}  // namespace

bool TangentialRun::converged() const {
  return !steps.empty() && std::all_of(steps.begin(), steps.end(), [](const TangentialSolution& s) {
           return s.report.status == SolveStatus::converged;
         });
}

double TangentialRun::total_time_s() const {
  double t = 0.0;
  for (const auto& s : steps) t += s.report.time_s;
  return t;
}

const SolverReport& TangentialRun::report() const {
  for (const auto& s : steps)
    if (s.report.status != SolveStatus::converged) return s.report;
  return steps.back().report;
}

output::StaticFields tangential_fields(const TangentialSolution& s, double relative_threshold) {
  output::StaticFields f = output::normal_fields(s.normal.pressure, relative_threshold);
  f.tx = s.tx;
  f.ty = s.ty;
  f.sx = s.sx;
  f.sy = s.sy;
  f.bound = s.bound;
  for (std::size_t e = 0; e < f.state.size(); ++e)
    if (f.state[e] != output::kFree)
      f.state[e] = (e < s.state.size() && s.state[e] == output::kStick) ? output::kStick : output::kSlip;
  f.dissipation.assign(s.tx.size(), 0.0);
  for (std::size_t e = 0; e < f.dissipation.size(); ++e)
    f.dissipation[e] = 0.0 - (s.tx[e] * (e < s.sx.size() ? s.sx[e] : 0.0) +
                         (e < s.ty.size() && e < s.sy.size() ? s.ty[e] * s.sy[e] : 0.0));
  return f;
}

void add_tangential_measures(nlohmann::json& s, const Grid& grid, const TangentialSolution& sol,
                             const output::StaticFields& f) {
  // A rolling solution is reported by its creepage and spin, except a step of a rolling history
  // that rolls no distance (TangentialProblem::roll, no marching step): that one is quasi-static
  // and reports the rigid shift it took.
  const bool rolling = sol.rolling;
  const auto& a = sol.amplitudes;
  const auto& r = sol.resultants;
  s["tangential_force"] = pair(r[0], r[1]);
  s["twisting_moment"] = r[2];
  s["creepage"] = rolling ? pair(a[0], a[1]) : nlohmann::json();
  s["spin"] = rolling ? nlohmann::json(a[2]) : nlohmann::json();
  s["rigid_shift"] = rolling ? nlohmann::json() : pair(a[0], a[1]);
  s["rotation"] = rolling ? nlohmann::json() : nlohmann::json(a[2]);
  if (sol.shift_undetermined) s["rigid_shift_undetermined"] = true;  // mu = 0: any shift, zero traction
  int n_stick = 0, n_slip = 0;
  double capacity = 0.0;
  for (std::size_t e = 0; e < f.state.size(); ++e) {
    n_stick += f.state[e] == output::kStick;
    n_slip += f.state[e] == output::kSlip;
    if (e < sol.bound.size()) capacity += sol.bound[e];
  }
  s["n_stick"] = n_stick;
  s["n_slip"] = n_slip;
  s["stick_area"] = n_stick * grid.area();
  s["slip_area"] = n_slip * grid.area();
  s["friction_capacity"] = capacity * grid.area();  // sum f(p) A: the largest tangential force
}

nlohmann::json tangential_summary(const Case& c, const TangentialSolution& sol, const output::StaticFields& f) {
  nlohmann::json s = output::normal_summary(c, sol.normal, f);
  s["normal_solver"] = s["solver"];
  s["solver"] = output::to_json(sol.report);
  const std::string regime = c.tangential ? to_string(c.tangential->regime) : "";
  s["regime"] = regime;
  if (c.friction) s["friction"] = friction_json(*c.friction);
  add_tangential_measures(s, c.grid, sol, f);
  if (regime == "rolling") s["velocity"] = c.tangential->rolling.velocity;
  s["energy"] = energy_json(c, sol, f);
  if (regime == "rolling" && has_history(c)) s["distance"] = sol.distance;  // rolled in this step (m)
  s["outer_iterations"] = sol.outer.iterations;
  s["outer_last_change"] = sol.outer.last_change;
  s["outer_coupling_residual"] = sol.outer.coupling_residual;
  s["outer_converged"] = sol.outer.converged;
  s["marching_steps"] = regime == "rolling" ? nlohmann::json(sol.marching_steps) : nlohmann::json();
  s["newton_iterations"] = regime == "rolling" ? nlohmann::json(sol.newton_iterations) : nlohmann::json();
  return s;
}

TangentialRun run_tangential(const Case& c, bool progress) {
  std::vector<TangentialSolution> steps;
  {
    Progress reporter("solving " + c.name + " (" + to_string(c.solver.backend) + ")", progress);
    steps = solve_tangential_case(c, reporter.callback());
    reporter.finish();
  }
  return tangential_run_of(c, std::move(steps), c.tangential->step_normals());
}

TangentialRun tangential_run_of(const Case& c, std::vector<TangentialSolution> solutions,
                                std::vector<NormalSpec> normals) {
  TangentialRun run;
  run.steps = std::move(solutions);
  run.normal = std::move(normals);
  run.normal.resize(run.steps.size(), c.normal);
  run.interrupted = interrupt_requested();
  nlohmann::json steps = nlohmann::json::array();
  double rolled = 0.0, dissipated = 0.0;
  Case step_case = c;  // one copy, its load set per step (a copy per step is slow for long histories)
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    step_case.normal = run.normal[k];
    run.fields.push_back(tangential_fields(run.steps[k], contact_threshold(c)));
    if (run.steps[k].rolling) run.fields.back().dissipation_rate = c.tangential->rolling.velocity / c.grid.dx;
    run.summary = tangential_summary(step_case, run.steps[k], run.fields.back());
    dissipated += run.summary["energy"]["dissipated"].get<double>();
    run.summary["energy"]["dissipated_total"] = dissipated;  // over the steps so far
    if (run.summary.contains("distance")) {  // a rolling history: the distance rolled so far
      rolled += run.steps[k].distance;
      run.summary["total_distance"] = rolled;
    }
    nlohmann::json entry = {{"step", k}};
    for (auto it = run.summary.begin(); it != run.summary.end(); ++it)
      if (!case_level_key(it.key())) entry[it.key()] = it.value();
    steps.push_back(std::move(entry));
  }
  if (has_history(c)) {
    run.summary["steps"] = steps;
    run.summary["all_steps_converged"] = run.converged();
    // The history's solver is its worst step's (the first that did not converge, else the last).
    const SolverReport& worst = run.report();
    run.summary["solver"] = output::to_json(worst);
    for (std::size_t k = 0; k < run.steps.size(); ++k)
      if (&run.steps[k].report == &worst) run.summary["solver"]["step"] = k;
    run.summary["solver"]["time_s"] = run.total_time_s();  // the whole history; each step's in "steps"
  }
  return run;
}

namespace {

/// The states of a history whose field is computed: every step, or every
/// output.snapshot_every-th and the last.
std::vector<SubsurfaceState> history_states(const Case& c, const StaticRun& run) {
  std::vector<SubsurfaceState> states;
  const int every = c.output.snapshot_every;
  for (std::size_t k = 0; k < run.fields.size(); ++k)
    if (every <= 0 || k % static_cast<std::size_t>(every) == 0 || k + 1 == run.fields.size())
      states.push_back({static_cast<int>(k), static_cast<double>(k), &run.fields[k]});
  return states;
}

}  // namespace

StaticRun run_static(const Case& c, bool progress, const SubsurfaceSink& history_sink) {
  // A worn profile is solved on the case's grid, its cycles in an outer loop (wear_run.hpp).
  StaticRun run = c.wear ? run_wear(c, progress) : run_static_with_accuracy(c, progress);
  // The flash temperature of the final state (temperature_run.hpp): rolling cases only (build_case).
  if (c.thermal.enabled() && run.converged && !run.interrupted && !run.fields.empty())
    run.summary["temperature"] = add_flash_temperature(c, run.grid, run.fields.back());
  // The field inside the bodies from the final state's tractions (subsurface_run.hpp), also for
  // a yield strength (first_yield.hpp).
  const bool yields = c.yields.body || c.yields.base;
  const bool fatigue = c.fatigue.body || c.fatigue.base;
  if ((c.subsurface.enabled || yields || c.shakedown || fatigue) && run.converged && !run.interrupted && !run.fields.empty()) {
    const nlohmann::json& s = run.summary;
    const bool steps = s.contains("steps") && s["steps"].is_array() && !s["steps"].empty();
    const Case fc = with_verdict_bodies(c);
    // A shift or torsion history holds its material points in place: their fatigue is over the
    // steps (one load cycle), not a rolling passage (fatigue_over_run.hpp).
    const bool fixed_points = run.history && c.tangential && c.tangential->regime != TangentialRegime::rolling;
    std::vector<FatigueOverRun> fatigue_over_steps;
    if (run.history) {  // every state's field, the worst over the history; the final state's at the same depths
      const std::vector<SubsurfaceState> states = history_states(c, run);
      if (fatigue && fixed_points) {
        const std::vector<double> depths = subsurface_series_depths(fc, run.grid, states);
        if (c.fatigue.base) fatigue_over_steps.emplace_back("base", *c.fatigue.base, run.grid, depths, states);
        if (c.fatigue.body) fatigue_over_steps.emplace_back("body", *c.fatigue.body, run.grid, depths, states);
      }
      run.subsurface_series =
          subsurface_series(fc, run.grid, states, [&](const SubsurfaceState& st, const SubsurfaceRun& field) {
            for (FatigueOverRun& f : fatigue_over_steps) f.add(st, field);
            return history_sink ? history_sink(st, field) : std::string();
          });
      const SubsurfaceSeries& series = *run.subsurface_series;
      run.subsurface = compute_subsurface(fc, run.grid, run.fields.back(), series.depths);
      run.summary["subsurface"] = subsurface_series_json(series, run.grid.dimension, false);
      if (yields) run.summary["yield"] = worst_yield_json(c, series, run.grid.dimension, false);
    } else {
      run.subsurface = compute_subsurface(fc, run.grid, run.fields.back(), s);
      run.summary["subsurface"] = subsurface_json(*run.subsurface, run.grid.dimension);
      if (yields) run.summary["yield"] = first_yield_json(first_yield(c, run), run.grid.dimension);
    }
    if (fatigue && fixed_points) {
      nlohmann::json f = nlohmann::json::object();
      for (const FatigueOverRun& over : fatigue_over_steps) f[over.body()] = over.to_json();
      run.summary["fatigue"] = f;
    } else if (fatigue) {
      run.summary["fatigue"] = fatigue_json(c, *run.subsurface);
    }
    if (c.shakedown) run.summary["shakedown"] = shakedown_json(c, *run.subsurface, steps ? s["steps"].back() : s);
  }
  return run;
}

StaticRun run_static_once(const Case& c, bool progress, const std::vector<double>* warm_pressure) {
  StaticRun out;
  if (c.problem == ProblemKind::finite) out = run_finite_static(c, progress);
  out.grid = c.grid;
  if (c.problem == ProblemKind::finite) return out;
  if (c.problem == ProblemKind::tangential) {
    TangentialRun run = run_tangential(c, progress);
    out.summary = std::move(run.summary);
    out.fields = std::move(run.fields);
    out.normal = run.normal.back();
    out.report = run.report();
    out.report.time_s = run.total_time_s();
    out.converged = run.converged();
    out.history = has_history(c);
    out.interrupted = run.interrupted;
    return out;
  }
  NormalRun run = run_normal(c, progress, warm_pressure);
  out.summary = std::move(run.summary);
  out.fields.push_back(std::move(run.fields));
  out.normal = c.normal;
  out.report = run.solution.report;
  out.converged = run.converged();
  out.interrupted = interrupt_requested();
  return out;
}

}  // namespace dc::runs
