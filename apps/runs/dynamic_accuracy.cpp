#include "dynamic_accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "accuracy_estimate.hpp"
#include "accuracy_run.hpp"
#include "errors.hpp"
#include "resource_estimate.hpp"

namespace dc::runs {
namespace dynamic_estimate {  // named: the unity build puts accuracy_run.cpp's own in the same unit

using Clock = std::chrono::steady_clock;
using OnStep = std::function<void(const dynamics::DynamicSample&)>;

struct Level {
  Grid grid;
  DynamicOutcome out;
};

struct Estimate {
  std::vector<Level> levels;  // finest first
  std::string unavailable;
  std::vector<EstimatedQuantity> quantities;
  double coarse_seconds = 0.0;
  /// The time steps' part of each quantity's error (relative, by name), from the run on the
  /// finest grid with coarser steps; `time_unavailable` says why there is none.
  std::vector<std::pair<std::string, double>> time_errors;
  std::string time_unavailable;
};

/// The time steps' error of the peaks: the finest grid run again with twice the step (fixed
/// steps: bdf2 second order, bdf1 first) or 4 times the tolerances (adaptive: the error about
/// proportional to them), Richardson with Roache's 1.25. Added to each peak's grid estimate, so
/// that error_estimate bounds the answer's distance to the continuum in space and in time.
void add_time_errors(const Case& c, Estimate& e) {
  Case coarser = c;
  coarser.grid = e.levels.front().grid;
  DynamicSpec& d = *coarser.dynamic;
  double ratio = 4.0, order = 1.0;
  if (d.adaptive) {
    d.rtol *= 4.0;
    d.atol *= 4.0;
  } else {
    d.dt *= 2.0;
    ratio = 2.0;
    order = d.bdf2 ? 2.0 : 1.0;
  }
  DynamicOutcome run;
  try {
    run = simulate_dynamic(coarser, false, {});
  } catch (const InputError& error) {  // a step the limits refuse before the run
    e.time_unavailable = std::string("the run with coarser time steps is refused: ") + error.what();
    return;
  }
  e.coarse_seconds += run.elapsed;
  if (!run.result.completed) {
    e.time_unavailable = "the run with coarser time steps did not complete";
    return;
  }
  for (EstimatedQuantity& q : e.quantities)
    for (const QuantityValue& v : run.peaks)
      if (v.name == q.quantity.name) {
        const double absolute = 1.25 * std::abs(q.error.value - v.value) / (std::pow(ratio, order) - 1.0);
        const double relative = q.error.value != 0.0 ? absolute / std::abs(q.error.value) : 0.0;
        e.time_errors.emplace_back(q.quantity.name, relative);
        q.error.error += absolute;
        q.error.relative_error += relative;
      }
}

DynamicOutcome run_on(const Case& c, const Grid& g, bool progress, const OnStep& on_step) {
  Case on_grid = c;
  on_grid.grid = g;
  return simulate_dynamic(on_grid, progress, on_step);
}

/// Elements across the largest contact of the run (from its area: a disk in 3-D).
int elements_across(const DynamicOutcome& out, const Grid& g) {
  const double area = out.summary.at("peaks").value("max_contact_area", 0.0);
  const double n = area / g.area();
  return static_cast<int>(g.dimension == 3 ? 2.0 * std::sqrt(n / std::numbers::pi) : n);
}

Estimate estimate_on(const Case& c, const Grid& fine_grid, bool progress, const OnStep& on_step) {
  Estimate e;
  e.levels.push_back({fine_grid, run_on(c, fine_grid, progress, on_step)});
  const DynamicOutcome& fine = e.levels.front().out;
  if (!fine.result.completed) {
    e.unavailable = fine.result.interrupted ? "interrupted" : "the run did not complete";
    return e;
  }
  const int min_across = fine_grid.dimension == 3 ? kMinAcross3d : kMinAcross2d;
  const int across = elements_across(fine, fine_grid);
  for (int factor : {2, 4}) {
    if (across / factor < min_across) {
      if (e.levels.size() == 1)
        e.unavailable = "the largest contact is " + std::to_string(across) + " elements across: a grid of twice "
                        "the element size would have fewer than " + std::to_string(min_across);
      break;
    }
    const Grid coarse_grid = coarsened(fine_grid, factor);
    DynamicOutcome coarse;
    try {
      coarse = run_on(c, coarse_grid, false, {});
    } catch (const InputError& error) {  // refused before the run (dynamic_limits_before)
      if (e.levels.size() == 1) e.unavailable = std::string("the coarser grid is refused: ") + error.what();
      break;
    }
    e.coarse_seconds += coarse.elapsed;
    if (!coarse.result.completed) {
      if (e.levels.size() == 1) e.unavailable = "the run on the grid of twice the element size did not complete";
      break;
    }
    e.levels.push_back({coarse_grid, std::move(coarse)});
  }
  if (e.levels.size() < 2) return e;
  std::vector<double> sizes;
  std::vector<std::vector<QuantityValue>> per_level;
  for (const Level& l : e.levels) {
    sizes.push_back(element_size(l.grid));
    per_level.push_back(l.out.peaks);
  }
  e.quantities =
      estimate_quantities(sizes, per_level, e.levels.front().grid.dimension, nullptr, EstimatedRun::dynamic_peaks);
  add_time_errors(c, e);
  return e;
}

nlohmann::json accuracy_json(const Estimate& e, const AccuracySpec& spec) {
  std::vector<GridTime> grids;
  for (const Level& l : e.levels) grids.push_back({l.grid, l.out.elapsed, &l.out.summary});
  nlohmann::json a = accuracy_block(grids, e.unavailable, e.quantities, e.coarse_seconds, spec);
  if (!e.unavailable.empty()) return a;
  for (const auto& [name, relative] : e.time_errors) {
    nlohmann::json& q = a["quantities"][name];
    q["time_error_estimate"] = relative;
    q["grid_error_estimate"] = q["error_estimate"].get<double>() - relative;
  }
  if (!e.time_unavailable.empty()) a["time_error_unavailable"] = e.time_unavailable;
  return a;
}

DynamicOutcome finish(Estimate& e, nlohmann::json accuracy) {
  DynamicOutcome out = std::move(e.levels.front().out);
  out.summary["accuracy"] = std::move(accuracy);
  return out;
}

}  // namespace dynamic_estimate



DynamicOutcome simulate_dynamic_with_accuracy(const Case& c, bool progress, const dynamic_estimate::OnStep& on_step,
                                              Grid* on_step_grid) {
  if (c.problem != ProblemKind::dynamic || !c.accuracy.estimate) return simulate_dynamic(c, progress, on_step);
  const AccuracySpec& spec = c.accuracy;
  if (!spec.target) {
    dynamic_estimate::Estimate e = dynamic_estimate::estimate_on(c, c.grid, progress, on_step);
    return dynamic_estimate::finish(e, dynamic_estimate::accuracy_json(e, spec));
  }
  const std::vector<std::string> names =
      spec.quantities.empty() ? std::vector<std::string>{"max_normal_force"} : spec.quantities;
  const auto start = dynamic_estimate::Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(dynamic_estimate::Clock::now() - start).count(); };
  Grid grid = c.grid;
  int refinements = 0;
  for (;;) {
    dynamic_estimate::Estimate e = dynamic_estimate::estimate_on(c, grid, progress, {});
    const DynamicOutcome& fine = e.levels.front().out;
    nlohmann::json a = dynamic_estimate::accuracy_json(e, spec);
    a["quantities_targeted"] = names;
    a["refinements"] = refinements;
    auto stop = [&](const std::string& why) {
      a["met"] = why == "target";
      a["stopped_by"] = why;
      a["time_s"] = elapsed();
      if (on_step) {  // the chosen grid once more, for the caller's snapshots
        if (on_step_grid) *on_step_grid = grid;
        e.levels.front().out = dynamic_estimate::run_on(c, grid, false, on_step);
        a["time_s"] = elapsed();
      }
      return dynamic_estimate::finish(e, a);
    };
    if (fine.result.interrupted) return stop("interrupted");
    if (!fine.result.completed) return stop("unconverged");
    const TargetGap gap = target_gap(e.quantities, e.unavailable.empty(), names, *spec.target);
    if (gap.worst <= 1.0) return stop("target");
    // A finer grid cannot mend the time steps' part: the case's time.dt (or time.rtol) must change.
    for (const auto& [name, relative] : e.time_errors)
      if (std::find(names.begin(), names.end(), name) != names.end() && relative > 0.8 * *spec.target)
        return stop("time_steps");
    const int factor = refinement_factor(gap);
    Grid next = refined(grid, factor);
    if (static_cast<double>(next.size()) > static_cast<double>(spec.max_elements) && factor > 2) next = refined(grid, 2);
    if (static_cast<double>(next.size()) > static_cast<double>(spec.max_elements)) return stop("max_elements");
    if (!grid_fits_in_memory(c, next, available_memory_bytes())) return stop("max_memory");
    const double growth = static_cast<double>(next.size()) / static_cast<double>(grid.size());
    if (elapsed() + (fine.elapsed + e.coarse_seconds) * std::pow(growth, 1.1) > spec.max_seconds)
      return stop("max_seconds");
    grid = next;
    ++refinements;
  }
}

}  // namespace dc::runs
