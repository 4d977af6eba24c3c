#include "dynamic_temperature.hpp"

#include <string>

#include "errors.hpp"
#include "temperature_run.hpp"

namespace dc::runs {

void DynamicTemperature::observe(const Grid& grid, const dynamics::DynamicSample& s, output::StaticFields& fields) {
  if (!wanted()) return;
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
  nlohmann::json entry;
  if (work > 0.0 && s.frictional_power > 0.0) {
    fields.dissipation_rate = s.frictional_power / work;  // the shares' sum is the step's power
    const double base_speed = s.state.velocity.x(), body_speed = s.state.omega.y() * case_.dynamic->radius;
    try {
      entry = flash_temperature(case_.thermal, grid, fields, base_speed, body_speed);
    } catch (const InputError& e) {  // 2-D: a surface the contact does not move over has no steady temperature
      entry = {{"max_rise", nullptr}, {"note", e.what()}};
    }
  } else {
    entry = {{"max_rise", 0.0}, {"note", "no frictional heat at this step"}};
  }
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
  t["model"] = "quasi-steady at the snapshots";
  t["states"] = states_;
  summary["temperature"] = t;
}

}  // namespace dc::runs
