#pragma once
// The flash temperature of a dynamic run (CASES.md "temperature"), quasi-steady at its snapshots
// (output.snapshot_every): at each, the step's frictional power density (the per-element shares
// -tau . ds of the step's slip, scaled so that they sum to the step's frictional power,
// DynamicSample::frictional_power) heats both surfaces, the contact moving over the base at the
// body's velocity V_x and over the body's surface at omega_y R (R = body.radius: the contact
// point below the centre; the library's V_s, temperature_run.hpp). Quasi-steady: it holds when
// the flux and the speeds change little over the time a surface point spends in the contact
// (2a / V); an impact's flux changes within its contact time, which this form does not follow.
// The worst snapshot is reported with every snapshot's maximum; its fields_<step>.csv get the
// `temperature` column.
#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "dynamic_simulation.hpp"
#include "static_fields.hpp"

namespace dc::runs {

class DynamicTemperature {
 public:
  /// `c` must outlive this object.
  explicit DynamicTemperature(const Case& c) : case_(c) {}
  /// Both surfaces have thermal constants (build_case then also requires snapshots).
  bool wanted() const { return case_.thermal.enabled(); }
  /// At a snapshot: the temperature maps into `fields` (the step's, dynamic_step_fields) and the
  /// snapshot's entry kept.
  void observe(const Grid& grid, const dynamics::DynamicSample& s, output::StaticFields& fields);
  /// summary["temperature"]: the worst snapshot's entry (temperature_run.hpp) with its step and
  /// time, and "states": [{step, time, max_rise}]; nothing without snapshots.
  void add_entries(nlohmann::json& summary) const;

 private:
  const Case& case_;
  nlohmann::json states_ = nlohmann::json::array();
  nlohmann::json worst_;
  double worst_rise_ = -1.0;
};

}  // namespace dc::runs
