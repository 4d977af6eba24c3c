#include "accuracy_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dc::runs {

double element_size(const Grid& g) { return g.dimension == 3 ? std::sqrt(g.dx * g.dy) : g.dx; }

nlohmann::json grid_json(const Grid& g) {
  nlohmann::json j = {{"nx", g.nx}};
  if (g.dimension == 3) j["ny"] = g.ny;
  return j;
}

namespace {

DiscretisationError edge_element_band(const QuantityValue& q, double h, int dimension);

DiscretisationError estimate_one(const QuantityValue& q, Convergence kind, const std::vector<GridValue>& values,
                                 int dimension, const std::vector<std::vector<std::vector<QuantityValue>>>* shifted,
                                 EstimatedRun run) {
  ErrorEstimateOptions options;
  options.scale = q.scale;
  options.band_at_least_largest_change = dimension == 2;
  if (dimension == 3 && run == EstimatedRun::contact) {  // measured on 3-D contacts (discretisation_error.hpp)
    options.smallest_order = 1.5;
    options.order_bound_when_not_monotone = true;
  }
  if (!shifted || values.size() != 3 || shifted->size() < 3) return estimate_discretisation_error(values, kind, options);
  std::vector<ShiftedGridValue> with_shifts;
  for (std::size_t k = 0; k < values.size(); ++k) {
    double sum = values[k].value;
    int count = 1;
    for (const auto& shift : (*shifted)[k])
      for (const QuantityValue& v : shift)
        if (v.name == q.name) sum += v.value, ++count;
    with_shifts.push_back({values[k].h, values[k].value, sum / count});
  }
  DiscretisationError e = estimate_discretisation_error_shifted(with_shifts, kind, options);
  // A whole-element width in 2-D: its two edges decide it, each placed to within an element, and
  // the shifted placements' extrapolation does not see that (a half-width equal on the nested
  // grids extrapolates to itself): no less than the edge elements' band, nor the spread of the
  // fine grid's shifted placements.
  if (q.whole_elements && e.method != "diverging") {
    double spread = edge_element_band(q, values[0].h, dimension).error;
    for (const auto& shift : (*shifted)[0])
      for (const QuantityValue& v : shift)
        if (v.name == q.name) spread = std::max(spread, std::abs(v.value - values[0].value));
    if (spread > e.error) {
      e.error = spread;
      e.relative_error = e.error / std::max(std::abs(e.value), q.scale);
      e.extrapolated = e.value;
      e.order.reset();
      e.method = "band";
    }
  }
  return e;
}

/// The band of a whole-element area or width from its edge elements: each edge placed to within
/// one element h (the discrete contact set may gain or lose its outermost element: a line
/// contact's half-width measured 0.53 h off Hertz's): a half-width h, a 2-D width (its area) 2 h,
/// a 3-D area of equivalent radius R its perimeter times h, a relative 2 h / R.
DiscretisationError edge_element_band(const QuantityValue& q, double h, int dimension) {
  DiscretisationError e;
  e.value = e.extrapolated = q.value;
  const double size = std::abs(q.value);
  double relative = 0.0;
  if (q.name == "contact_half_width")
    relative = h / size;
  else
    relative = dimension == 2 ? 2.0 * h / size : 2.0 * h / std::sqrt(size / std::numbers::pi);
  e.relative_error = std::isfinite(relative) ? relative : HUGE_VAL;
  e.error = e.relative_error * std::max(size, q.scale);
  e.method = "band";
  return e;
}

}  // namespace

std::vector<EstimatedQuantity> estimate_quantities(
    const std::vector<double>& element_sizes, const std::vector<std::vector<QuantityValue>>& per_level,
    int dimension, const std::vector<std::vector<std::vector<QuantityValue>>>* shifted, EstimatedRun run) {
  std::vector<EstimatedQuantity> out;
  if (per_level.empty()) return out;
  for (const QuantityValue& q : per_level[0]) {
    std::vector<GridValue> values;
    for (std::size_t k = 0; k < per_level.size() && k < element_sizes.size(); ++k)
      for (const QuantityValue& v : per_level[k])
        if (v.name == q.name) values.push_back({element_sizes[k], v.value});
    if (values.size() < 2) continue;
    const auto equal = [&](double v) { return std::abs(v - values[0].value) <= 1e-12 * std::abs(values[0].value); };
    bool same = std::all_of(values.begin(), values.end(), [&](const GridValue& v) { return equal(v.value); });
    if (shifted)
      for (const auto& level : *shifted)
        for (const auto& shift : level)
          for (const QuantityValue& v : shift)
            if (v.name == q.name && !equal(v.value)) same = false;
    const bool zero = std::all_of(values.begin(), values.end(), [&](const GridValue& v) { return std::abs(v.value) <= q.scale; });
    // The same on every grid: a value the case prescribes, left out; but an area or a width that
    // happens to cover the same elements on every grid is not known better than its edge element.
    if (zero || (same && !q.whole_elements)) continue;
    EstimatedQuantity e{q, same ? edge_element_band(q, element_sizes[0], dimension)
                                : estimate_one(q, q.convergence, values, dimension, shifted, run),
                        {}};
    for (const GridValue& v : values) e.values.push_back(v.value);
    out.push_back(std::move(e));
  }
  // A peak that diverges marks a singular edge (a punch's rim): there the force and the approach
  // converge by whole elements at first order, not at O(h^2), and Richardson falls below their
  // error (flat punch, docs/accuracy.md): they get the band.
  const bool singular_edge =
      std::any_of(out.begin(), out.end(), [](const EstimatedQuantity& e) { return e.error.method == "diverging"; });
  if (singular_edge)
    for (EstimatedQuantity& e : out)
      if (e.quantity.convergence == Convergence::smooth) {
        std::vector<GridValue> values;
        for (std::size_t k = 0; k < e.values.size(); ++k) values.push_back({element_sizes[k], e.values[k]});
        e.error = estimate_one(e.quantity, Convergence::band, values, dimension, shifted, run);
      }
  return out;
}

double contact_stiffness(double e_star, double area) { return 2.0 * e_star * std::sqrt(std::max(area, 0.0) / std::numbers::pi); }

void floor_by_unresolved_height(std::vector<EstimatedQuantity>& quantities, double unresolved, double stiffness) {
  if (!(unresolved > 0.0) || !std::isfinite(unresolved)) return;
  for (EstimatedQuantity& q : quantities) {
    const double floor = q.quantity.name == "approach"       ? unresolved
                         : q.quantity.name == "normal_force" ? stiffness * unresolved
                                                             : 0.0;
    if (!(floor > q.error.error) || !std::isfinite(floor)) continue;
    q.error.error = floor;
    q.error.relative_error = floor / std::max(std::abs(q.error.value), q.quantity.scale);
    q.error.extrapolated = q.error.value;
    q.error.order.reset();
    q.error.method = "band";
  }
}

nlohmann::json quantities_json(const std::vector<EstimatedQuantity>& quantities) {
  nlohmann::json q = nlohmann::json::object();
  for (const auto& [value, err, per_grid] : quantities) {
    nlohmann::json entry = {{"value", err.value},
                            {"values", per_grid},
                            {"extrapolated", err.extrapolated},
                            {"error_estimate", err.relative_error},
                            {"error_estimate_absolute", err.error},
                            {"method", err.method}};
    entry["order"] = err.order ? nlohmann::json(*err.order) : nlohmann::json();
    q[value.name] = entry;
  }
  return q;
}

nlohmann::json accuracy_block(const std::vector<GridTime>& grids, const std::string& unavailable,
                              const std::vector<EstimatedQuantity>& quantities, double coarse_seconds,
                              const AccuracySpec& spec) {
  nlohmann::json a;
  a["grid"] = grid_json(grids.front().grid);
  nlohmann::json list = nlohmann::json::array();
  for (const GridTime& l : grids) {
    nlohmann::json g = grid_json(l.grid);
    g["time_s"] = l.seconds;
    // Every grid's own answer is certified as the finest one's: its status (a dynamic run's, or
    // the solver's) and the certificate's residuals.
    if (l.summary) {
      const nlohmann::json& s = *l.summary;
      const nlohmann::json solver = s.contains("solver") && s["solver"].is_object() ? s["solver"] : nlohmann::json::object();
      g["status"] = s.contains("status") && s["status"].is_string() ? s["status"] : solver.value("status", nlohmann::json());
      if (solver.contains("certificate")) g["certificate"] = solver["certificate"];
    }
    list.push_back(g);
  }
  a["grids"] = list;
  if (!unavailable.empty()) {
    a["estimate"] = nullptr;
    a["unavailable"] = unavailable;
  } else {
    a["quantities"] = quantities_json(quantities);
    // The estimate's cost: the other runs over the finest one (3-D about 1/4 + 1/16).
    const double fine = grids.front().seconds;
    a["cost_fraction"] = fine > 0.0 ? coarse_seconds / fine : 0.0;
  }
  a["target"] = spec.target ? nlohmann::json(*spec.target) : nlohmann::json();
  a["met"] = nlohmann::json();
  return a;
}

double named_error(const std::vector<EstimatedQuantity>& quantities, const std::string& name) {
  const DiscretisationError* e = named_estimate(quantities, name);
  return e ? e->relative_error : 0.0;
}

const DiscretisationError* named_estimate(const std::vector<EstimatedQuantity>& quantities, const std::string& name) {
  for (const auto& q : quantities)
    if (q.quantity.name == name) return &q.error;
  return nullptr;
}

TargetGap target_gap(const std::vector<EstimatedQuantity>& quantities, bool available,
                     const std::vector<std::string>& names, double target) {
  TargetGap gap;
  for (const std::string& n : names) {
    double err = available ? named_error(quantities, n) : HUGE_VAL;
    const auto it = std::find_if(quantities.begin(), quantities.end(),
                                 [&](const EstimatedQuantity& q) { return q.quantity.name == n; });
    // Two grids only: not met, one refinement (a factor 2 at order 2: refinement_factor).
    if (available && it != quantities.end() && it->values.size() < 3)
      err = std::max(err, 1.01 * target);
    if (err / target <= gap.worst) continue;
    gap.worst = err / target;
    const DiscretisationError* d = available ? named_estimate(quantities, n) : nullptr;
    gap.order = d && d->method == "band" ? 1.0 : d && d->order ? std::clamp(*d->order, 1.0, 2.0) : 2.0;
  }
  return gap;
}

int refinement_factor(const TargetGap& gap) {
  // The element size the estimate asks for, with a margin of 0.8 on the target; no estimate: 2.
  const double factor = std::isfinite(gap.worst) ? std::pow(gap.worst / 0.8, 1.0 / gap.order) : 2.0;
  return factor > 2.0 ? 4 : 2;
}

}  // namespace dc::runs
