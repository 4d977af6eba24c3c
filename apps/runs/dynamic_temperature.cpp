#include "dynamic_temperature.hpp"

#include <string>
#include <vector>

#include "errors.hpp"
#include "temperature_run.hpp"

namespace dc::runs {

bool DynamicTemperature::heat_of_step(const Grid& grid, const dynamics::DynamicSample& s,
                                      output::StaticFields& fields) const {
  const std::size_t n = fields.tx.size();
  fields.dissipation.assign(n, 0.0);
  double work = 0.0;
  for (std::size_t e = 0; e < n; ++e) {
    const double w = -(fields.tx[e] * (e < fields.sx.size() ? fields.sx[e] : 0.0) +
                       (e < fields.ty.size() && e < fields.sy.size() ? fields.ty[e] * fields.sy[e] : 0.0));
    fields.dissipation[e] = w;
    work += w;
  }
  work *= grid.area();
  if (!(work > 0.0 && s.frictional_power > 0.0)) {
    fields.dissipation_rate = 0.0;
    return false;
  }
  fields.dissipation_rate = s.frictional_power / work;  // the shares' sum is the step's power
  return true;
}

nlohmann::json DynamicTemperature::transient_step(const Grid& grid, const dynamics::DynamicSample& s,
                                                  output::StaticFields& fields, bool heated) {
  const ThermalSpec& t = case_.thermal;
  const double base_speed = s.state.velocity.x(), body_speed = s.state.omega.y() * case_.dynamic->radius;
  if (!transient_ || s.step == 1) {  // a run's first step (an accuracy estimate runs the case again)
    const double dt = case_.dynamic->dt, t_end = case_.dynamic->t_end;
    transient_ = std::make_unique<TransientFlashTemperature>(grid, *t.base, *t.body, t.partition, dt,
                                                             std::max(t_end, dt), TransientHeatOptions{},
                                                             "materials.base.thermal", "materials.body.thermal",
                                                             "temperature.partition");
    last_time_ = 0.0;
    states_ = nlohmann::json::array();
    worst_ = nullptr;
    worst_rise_ = -1.0;
  }
  const double h = s.state.time - last_time_;
  last_time_ = s.state.time;
  const std::vector<double> q = heated ? power_density(fields) : std::vector<double>(grid.size(), 0.0);
  const FlashTemperatureResult r = transient_->step(h, base_speed, body_speed, q);
  fields.temperature_base = r.base;
  fields.temperature_body = r.body;
  nlohmann::json entry = flash_entry(t, grid, q, r, base_speed, body_speed, "transient");
  if (!heated) entry["note"] = "no frictional heat at this step";
  return entry;
}

void DynamicTemperature::observe(const Grid& grid, const dynamics::DynamicSample& s, output::StaticFields& fields,
                                 bool snapshot) {
  if (!wanted() || (!snapshot && !every_step())) return;
  const bool heated = heat_of_step(grid, s, fields);
  nlohmann::json entry;
  if (every_step()) {
    entry = transient_step(grid, s, fields, heated);
    if (!snapshot) {
      fields.temperature_base.clear();
      fields.temperature_body.clear();
      return;
    }
  } else if (heated) {
    const double base_speed = s.state.velocity.x(), body_speed = s.state.omega.y() * case_.dynamic->radius;
    try {
      entry = flash_temperature(case_.thermal, grid, fields, base_speed, body_speed);
    } catch (const InputError& e) {  // 2-D: a surface the contact does not move over has no steady temperature
      entry = {{"max_rise", nullptr}, {"note", e.what()}};
    }
  } else {
    entry = {{"max_rise", 0.0}, {"note", "no frictional heat at this step"}};
  }
  keep(s, std::move(entry));
}

void DynamicTemperature::keep(const dynamics::DynamicSample& s, nlohmann::json entry) {
  entry["step"] = s.step;
  entry["time"] = s.state.time;
  states_.push_back({{"step", s.step}, {"time", s.state.time}, {"max_rise", entry["max_rise"]}});
  if (entry["max_rise"].is_number() && entry["max_rise"].get<double>() > worst_rise_) {
    worst_rise_ = entry["max_rise"].get<double>();
    worst_ = entry;
  }
}

void DynamicTemperature::add_entries(nlohmann::json& summary) const {
  if (!wanted() || states_.empty()) return;
  nlohmann::json t = worst_.is_null() ? nlohmann::json{{"max_rise", nullptr}, {"note", "no snapshot had a temperature"}}
                                      : worst_;
  t["model"] = every_step() ? "transient, stepped with the run" : "quasi-steady at the snapshots";
  t["states"] = states_;
  summary["temperature"] = t;
}

}  // namespace dc::runs
