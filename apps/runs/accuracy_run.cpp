#include "accuracy_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

#include "accuracy_estimate.hpp"
#include "accuracy_quantities.hpp"
#include "discretisation_error.hpp"
#include "grid_interpolation.hpp"
#include "heights_accuracy.hpp"
#include "interrupt.hpp"
#include "resource_estimate.hpp"
#include "solve_case.hpp"
#include "tangential_run.hpp"

namespace dc::runs {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}


int fewest_across(const nlohmann::json& summary) {
  const nlohmann::json& a = summary.value("elements_across_contact", nlohmann::json());
  if (a.is_number()) return a.get<int>();
  if (a.is_array() && a.size() == 2) return std::min(a[0].get<int>(), a[1].get<int>());
  return 0;
}

/// One solved grid.
struct GridSolve {
  Grid grid;
  StaticRun run;
  double seconds = 0.0;
};

/// The grids solved so far, by element counts (a refinement by 2 reuses the last two grids).
class GridSolves {
 public:
  GridSolves(const Case& c, bool progress) : case_(c), progress_(progress) {}
  /// The coarse grids take the backend that solved the fine one (auto would give the smallest
  /// grids to Ipopt, at several times the native solver's time); the fallbacks stay. A fine grid
  /// (a refinement) takes the case's own choice: the start grid's Ipopt, kept, took 20 s on a
  /// 5632-strip line contact the native solver solves in 0.03 s.
  void use_backend_of(const SolverReport& fine) {
    if (case_.solver.backend != Backend::automatic) return;
    if (const auto b = backend_from_string(fine.backend); b && *b != Backend::automatic) backend_ = *b;
  }
  /// `g` solved (once: a grid asked for again is the one solved before); a normal case from the
  /// pressure of `warm_from` interpolated to `g` (a refinement starts from the coarser answer);
  /// `coarse`: one of an estimate's coarse or shifted grids.
  const GridSolve& solve(const Grid& g, const GridSolve* warm_from = nullptr, bool coarse = false) {
    const auto key = std::make_tuple(g.nx, g.ny, g.x0, g.y0);
    const auto found = solved_.find(key);
    if (found != solved_.end() && same_bounds(found->second.grid, g)) return found->second;
    Case on_grid = case_;
    on_grid.grid = g;
    on_grid.solver.backend = coarse ? backend_ : case_.solver.backend;
    // The same operator on every grid: auto would build the dense matrix on the smaller ones,
    // which costs more than their FFT solve.
    if (on_grid.solver.operator_kind == OperatorKind::automatic && g.size() < case_.grid.size())
      on_grid.solver.operator_kind = OperatorKind::fft;
    GridSolve s;
    s.grid = g;
    std::vector<double> warm;
    if (warm_from && case_.problem == ProblemKind::normal && !warm_from->run.fields.empty())
      warm = interpolate_to_grid(warm_from->grid, warm_from->run.fields.back().p, g);
    const auto start = Clock::now();
    s.run = run_static_once(on_grid, progress_, warm.empty() ? nullptr : &warm);
    s.seconds = seconds_since(start);
    return solved_[key] = std::move(s);
  }
  /// The case's gap heights on `g` (contact_heights, unworn).
  std::vector<double> heights(const Grid& g) const {
    Case on_grid = case_;
    on_grid.grid = g;
    return contact_heights(on_grid);
  }
  double certificate_tol() const { return case_.solver.certificate_tol; }

 private:
  static bool same_bounds(const Grid& a, const Grid& b) {
    return a.x0 == b.x0 && a.y0 == b.y0 && a.x_max() == b.x_max() && a.y_max() == b.y_max();
  }
  const Case& case_;
  bool progress_;
  Backend backend_ = case_.solver.backend;
  std::map<std::tuple<int, int, double, double>, GridSolve> solved_;
};

/// The estimate of a fine grid: its coarsenings by 2 and 4 where they still resolve the contact
/// and converge.
struct Estimate {
  std::vector<const GridSolve*> levels;  // finest first
  std::string unavailable;               // why there is none (empty: there is one)
  std::vector<EstimatedQuantity> quantities;
  double coarse_seconds = 0.0;
  bool interrupted = false;  // during a coarse solve
};

/// A history's results at its peak load step (the largest normal force; the last of equal ones),
/// else the summary's own.
int peak_load_step_index(const nlohmann::json& summary) {
  if (!summary.contains("steps") || !summary["steps"].is_array() || summary["steps"].empty()) return -1;
  const nlohmann::json& steps = summary["steps"];
  std::size_t peak = 0;
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (std::abs(steps[k].value("normal_force", 0.0)) >= std::abs(steps[peak].value("normal_force", 0.0))) peak = k;
  return static_cast<int>(peak);
}

const nlohmann::json& peak_load_step(const nlohmann::json& summary) {
  const int k = peak_load_step_index(summary);
  return k < 0 ? summary : summary["steps"][static_cast<std::size_t>(k)];
}

Estimate estimate_on(GridSolves& solves, const Grid& fine_grid, const GridSolve* warm_from = nullptr) {
  Estimate e;
  const GridSolve& fine = solves.solve(fine_grid, warm_from);
  e.levels.push_back(&fine);
  if (!fine.run.converged || fine.run.interrupted) {
    e.unavailable = fine.run.interrupted ? "interrupted" : "the solve did not converge";
    return e;
  }
  solves.use_backend_of(fine.run.report);
  const int min_across = fine_grid.dimension == 3 ? kMinAcross3d : kMinAcross2d;
  const int across = fewest_across(peak_load_step(fine.run.summary));
  for (int factor : {2, 4}) {
    if (across / factor < min_across) {
      if (e.levels.size() == 1)
        e.unavailable = "the contact is " + std::to_string(across) + " elements across: a grid of twice the element "
                        "size would have fewer than " + std::to_string(min_across);
      break;
    }
    const GridSolve* solved = nullptr;
    try {
      solved = &solves.solve(coarsened(fine_grid, factor), nullptr, true);
    } catch (const Interrupted&) {  // the fine answer stands; the run says it was interrupted
      e.unavailable = "interrupted";
      e.interrupted = true;
      return e;
    }
    const GridSolve& coarse = *solved;
    e.coarse_seconds += coarse.seconds;
    if (!coarse.run.converged) {
      if (e.levels.size() == 1) e.unavailable = "the solve on the grid of twice the element size did not converge";
      break;
    }
    e.levels.push_back(&coarse);
  }
  if (e.levels.size() < 2) return e;
  auto quantities_of = [](const GridSolve& l) { return accuracy_quantities(peak_load_step(l.run.summary)); };
  std::vector<std::vector<QuantityValue>> per_level;
  for (const GridSolve* l : e.levels) per_level.push_back(quantities_of(*l));
  // 2-D: every size also on the grids shifted by a third and two thirds of an element
  // (estimate_discretisation_error_shifted); skipped where one of them fails or cuts the contact.
  std::vector<std::vector<std::vector<QuantityValue>>> shifted(e.levels.size());
  bool use_shifted = fine_grid.dimension == 2 && e.levels.size() == 3;
  for (std::size_t k = 0; k < e.levels.size() && use_shifted; ++k)
    for (double share : {1.0 / 3.0, 2.0 / 3.0}) {
      const Grid& g = e.levels[k]->grid;
      const double dx = share * g.dx;
      const GridSolve* s = nullptr;
      try {
        s = &solves.solve(Grid::make(2, g.nx, 1, g.x0 + dx, g.x_max() + dx, 0.0, 0.0), nullptr, true);
      } catch (const Interrupted&) {
        e.interrupted = true;
        use_shifted = false;
        break;
      }
      e.coarse_seconds += s->seconds;
      if (!s->run.converged || s->run.summary.value("contact_touches_boundary", false)) {
        use_shifted = false;
        break;
      }
      shifted[k].push_back(quantities_of(*s));
    }
  std::vector<double> sizes;
  for (const GridSolve* l : e.levels) sizes.push_back(element_size(l->grid));
  e.quantities = estimate_quantities(sizes, per_level, fine_grid.dimension, use_shifted ? &shifted : nullptr);
  // A profile varying on the coarse grids' scale (a measured table): the approach is no more
  // certain than the height detail they miss (2-D: the shifted grids sample the profile afresh).
  const int peak = peak_load_step_index(fine.run.summary);
  if (fine_grid.dimension == 3 && !fine.run.fields.empty()) {
    const std::size_t k = peak < 0 ? fine.run.fields.size() - 1 : static_cast<std::size_t>(peak);
    const double unresolved = heights_estimate::unresolved_in_contact(
        fine_grid, solves.heights(fine_grid), fine.run.fields[std::min(k, fine.run.fields.size() - 1)].p,
        solves.certificate_tol());
    const nlohmann::json& peak_step = peak_load_step(fine.run.summary);
    const double e_star = fine.run.summary.at("materials").at("E_star").get<double>();
    floor_by_unresolved_height(e.quantities, unresolved, contact_stiffness(e_star, peak_step.value("contact_area", 0.0)));
  }
  return e;
}

nlohmann::json accuracy_json(const Estimate& e, const AccuracySpec& spec) {
  std::vector<GridTime> grids;
  for (const GridSolve* l : e.levels) grids.push_back({l->grid, l->seconds, &l->run.summary});
  nlohmann::json a = accuracy_block(grids, e.unavailable, e.quantities, e.coarse_seconds, spec);
  const int k = peak_load_step_index(e.levels.front()->run.summary);
  if (k >= 0) a["step"] = k;  // a history's peak load
  return a;
}

std::vector<std::string> target_quantities(const AccuracySpec& spec) {
  return spec.quantities.empty() ? std::vector<std::string>{"max_pressure"} : spec.quantities;
}

/// The grid `g` with its bounds grown by `factor` about their centre and the element size kept
/// (element counts rounded up to a multiple of 4).
Grid grown(const Grid& g, double factor) {
  auto count = [&](int n) { return 4 * static_cast<int>(std::ceil(n * factor / 4.0)); };
  const int nx = count(g.nx);
  const double cx = 0.5 * (g.x0 + g.x_max()), hx = 0.5 * nx * g.dx;
  if (g.dimension == 2) return Grid::make(2, nx, 1, cx - hx, cx + hx, 0.0, 0.0);
  const int ny = count(g.ny);
  const double cy = 0.5 * (g.y0 + g.y_max()), hy = 0.5 * ny * g.dy;
  return Grid::make(3, nx, ny, cx - hx, cx + hx, cy - hy, cy + hy);
}

StaticRun finish(const Estimate& e, nlohmann::json accuracy) {
  StaticRun run = e.levels.front()->run;
  run.interrupted = run.interrupted || e.interrupted;
  run.summary["accuracy"] = std::move(accuracy);
  return run;
}

/// accuracy.target: refine until every named quantity's estimated error is below the target.
StaticRun refine_to_target(const Case& c, bool progress) {
  const AccuracySpec& spec = c.accuracy;
  const double target = *spec.target;
  const auto names = target_quantities(spec);
  const auto start = Clock::now();
  GridSolves solves(c, progress);
  Grid grid = c.grid;
  int refinements = 0, growths = 0;
  const GridSolve* previous = nullptr;  // the last fine grid: the next one starts from its answer
  for (;;) {
    const Estimate e = estimate_on(solves, grid, previous);
    previous = e.levels.front();
    const GridSolve& fine = *e.levels.front();
    nlohmann::json a = accuracy_json(e, spec);
    a["quantities_targeted"] = names;
    a["refinements"] = refinements;
    a["extent_growths"] = growths;
    a["time_s"] = seconds_since(start);
    auto stop = [&](const char* why) {
      a["met"] = std::string(why) == "target";
      a["stopped_by"] = why;
      return finish(e, a);
    };
    if (e.interrupted || fine.run.interrupted) return stop("interrupted");
    if (!fine.run.converged) return stop("unconverged");
    // The contact reaches the grid's edge: grow the bounds, keep the element size.
    const bool at_edge = fine.run.summary.value("contact_touches_boundary", false) && !c.allow_edge_contact;
    // A named peak without a continuum value (a singular edge): no grid meets a target on it.
    for (const std::string& n : names)
      if (const DiscretisationError* d = named_estimate(e.quantities, n); d && d->method == "diverging")
        return stop("diverging");
    const TargetGap gap = target_gap(e.quantities, e.unavailable.empty(), names, target);
    if (!at_edge && gap.worst <= 1.0) return stop("target");
    Grid next = at_edge ? grown(grid, 1.5) : grid;
    if (at_edge) {
      ++growths;
    } else {
      const int factor = refinement_factor(gap);
      next = refined(grid, factor);
      if (static_cast<double>(next.size()) > static_cast<double>(spec.max_elements) && factor > 2)
        next = refined(grid, 2);
      ++refinements;
    }
    if (static_cast<double>(next.size()) > static_cast<double>(spec.max_elements)) return stop("max_elements");
    if (!grid_fits_in_memory(c, next, available_memory_bytes())) return stop("max_memory");
    // The next solves' time, from this grid's (a little worse than linear in the elements).
    const double growth = static_cast<double>(next.size()) / static_cast<double>(grid.size());
    const double predicted = (fine.seconds + e.coarse_seconds) * std::pow(growth, 1.1);
    if (seconds_since(start) + predicted > spec.max_seconds) return stop("max_seconds");
    grid = next;
  }
}

}  // namespace

Grid refined(const Grid& g, int factor) {
  if (g.dimension == 2) return Grid::make(2, g.nx * factor, 1, g.x0, g.x_max(), 0.0, 0.0);
  return Grid::make(3, g.nx * factor, g.ny * factor, g.x0, g.x_max(), g.y0, g.y_max());
}

Grid coarsened(const Grid& g, int factor) {
  auto count = [&](int n) { return std::max(1, static_cast<int>(std::lround(static_cast<double>(n) / factor))); };
  if (g.dimension == 2) return Grid::make(2, count(g.nx), 1, g.x0, g.x_max(), 0.0, 0.0);
  return Grid::make(3, count(g.nx), count(g.ny), g.x0, g.x_max(), g.y0, g.y_max());
}

StaticRun run_static_with_accuracy(const Case& c, bool progress) {
  const bool applies = c.problem == ProblemKind::normal || c.problem == ProblemKind::tangential;
  if (!applies || !c.accuracy.estimate) return run_static_once(c, progress);
  if (c.accuracy.target) return refine_to_target(c, progress);
  GridSolves solves(c, progress);
  const Estimate e = estimate_on(solves, c.grid);
  // An interrupted history has no estimate: its coarse grids would solve the whole history.
  if (e.levels.front()->run.interrupted) return e.levels.front()->run;
  return finish(e, accuracy_json(e, c.accuracy));
}

void print_accuracy(const nlohmann::json& a) {
  std::string grids;
  for (const auto& g : a["grids"])
    grids += (grids.empty() ? "" : ", ") + std::to_string(g["nx"].get<int>()) +
             (g.contains("ny") ? " x " + std::to_string(g["ny"].get<int>()) : std::string());
  if (a.contains("unavailable")) {
    std::printf("  %-16s no estimate: %s\n", "accuracy", a["unavailable"].get<std::string>().c_str());
  } else {
    std::printf("  %-16s estimated relative error (grids %s; %.0f %% extra time)\n", "accuracy", grids.c_str(),
                100.0 * a["cost_fraction"].get<double>());
    for (const auto& [name, q] : a["quantities"].items()) {
      std::printf("    %-18s %-12.6g +- %.2g", name.c_str(), q["value"].get<double>(), q["error_estimate"].get<double>());
      if (q["order"].is_number()) std::printf("  (order %.2f)", q["order"].get<double>());
      std::printf("  %s\n", q["method"].get<std::string>().c_str());
    }
  }
  if (a["target"].is_number())
    std::printf("  %-16s %.3g on %s: %s (%s)\n", "target", a["target"].get<double>(), a["grid"].dump().c_str(),
                a["met"].get<bool>() ? "met" : "NOT met", a.value("stopped_by", std::string()).c_str());
}

std::string missed_target_message(const nlohmann::json& a) {
  std::ostringstream text;
  text << "the target " << a.value("target", 0.0) << " was not met (stopped by " << a.value("stopped_by", std::string("?"))
       << " on " << a.value("grid", nlohmann::json()).dump();
  // The named quantity whose estimate is furthest from the target.
  std::string worst;
  double largest = -1.0;
  if (a.contains("quantities") && a["quantities"].is_object() && a.contains("quantities_targeted"))
    for (const auto& n : a["quantities_targeted"]) {
      const std::string name = n.get<std::string>();
      if (!a["quantities"].contains(name)) continue;
      const nlohmann::json& e = a["quantities"][name].value("error_estimate", nlohmann::json());
      const double err = e.is_number() ? e.get<double>() : HUGE_VAL;  // null: diverging
      if (err > largest) largest = err, worst = name;
    }
  if (!worst.empty()) text << "; largest estimate: " << worst << " " << largest;
  text << ")";
  return text.str();
}

bool accuracy_target_missed(const nlohmann::json& summary) {
  if (!summary.contains("accuracy")) return false;
  const nlohmann::json& a = summary["accuracy"];
  return a.value("met", nlohmann::json()).is_boolean() && !a["met"].get<bool>();
}

}  // namespace dc::runs
