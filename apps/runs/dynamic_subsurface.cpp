#include "dynamic_subsurface.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fatigue_over_run.hpp"
#include "first_yield.hpp"
#include "subsurface_run.hpp"

namespace dc::runs {

output::StaticFields dynamic_step_fields(const Grid& grid, const dynamics::ContactState& cs) {
  if (cs.fields) {
    const TangentialSolution& t = *cs.fields;
    output::StaticFields f;
    f.p = t.normal.pressure;
    f.tx = t.tx;
    f.ty = t.ty;
    f.sx = t.sx;
    f.sy = t.sy;
    f.bound = t.bound;
    f.state = t.state;
    return f;
  }
  if (cs.pressure) return output::normal_fields(*cs.pressure, 1e-9);
  return output::normal_fields(std::vector<double>(grid.size(), 0.0), 1e-9);
}

DynamicSubsurface::DynamicSubsurface(const Case& c)
    : case_(c), wanted_(c.subsurface.enabled || c.yields.base || c.yields.body || c.fatigue.base) {}

void DynamicSubsurface::observe(const Grid& grid, const dynamics::DynamicSample& s,
                                const output::StaticFields* snapshot) {
  if (!wanted_) return;
  const double x = s.state.position.x(), y = s.state.position.y();
  if (snapshot) states_.keep(s.step, s.state.time, x, y, *snapshot);
  const double force = std::abs(s.contact.force.z());
  if (states_.exceeds_peak(force))
    states_.keep_peak(s.step, s.state.time, x, y, force, dynamic_step_fields(grid, s.contact_state));
}

std::optional<SubsurfaceSeries> DynamicSubsurface::add_entries(const Grid& grid, const SubsurfaceSink& write,
                                                               nlohmann::json& summary) const {
  if (!wanted_ || states_.empty()) return std::nullopt;
  const Case& c = case_;
  const bool fe_body = c.dynamic && c.dynamic->fe_body;
  Case fc = with_verdict_bodies(c);
  if (fe_body) std::erase(fc.subsurface.bodies, std::string("body"));  // its stresses: body.pvd
  const std::vector<SubsurfaceState> states = states_.states();
  std::optional<FatigueOverRun> fatigue;  // Dang Van on the base's points over the snapshots
  if (c.fatigue.base) fatigue.emplace("base", *c.fatigue.base, grid, subsurface_series_depths(fc, grid, states), states);
  SubsurfaceSeries series = subsurface_series(fc, grid, states, [&](const SubsurfaceState& st, const SubsurfaceRun& run) {
    if (fatigue) fatigue->add(st, run);
    return write ? write(st, run) : std::string();
  });
  if (fatigue) summary["fatigue"] = {{"base", fatigue->to_json()}};
  summary["subsurface"] = subsurface_series_json(series, grid.dimension, true);
  for (nlohmann::json& state : summary["subsurface"]["states"])
    if (state["step"] == states_.peak_step()) state["peak_normal_force"] = true;
  if (fe_body) summary["subsurface"]["body"] = {{"finite_element", true}, {"see", "body.pvd"}};
  if (c.yields.base || c.yields.body) summary["yield"] = worst_yield_json(c, series, grid.dimension, true);
  return series;
}

}  // namespace dc::runs
