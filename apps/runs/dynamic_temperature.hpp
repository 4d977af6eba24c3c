#pragma once
// The flash temperature of a dynamic run (CASES.md "temperature"): the step's frictional power
// density (the per-element shares -tau . ds of the step's slip, scaled so that they sum to the
// step's frictional power, DynamicSample::frictional_power) heats both surfaces, the contact
// moving over the base at the body's velocity V_x and over the body's surface at omega_y R
// (R = body.radius: the contact point below the centre; the library's V_s, temperature_run.hpp).
//   temperature.model "quasi_steady" (the default): at each snapshot (output.snapshot_every)
//     the steady moving-source temperature of that step's flux and speeds
//     (core/flash_temperature.hpp). It holds when the flux and the speeds change little over
//     the time a surface point spends in the contact (2a / V); an impact's flux changes within
//     its contact time, which this form does not follow.
//   temperature.model "transient": both surfaces stepped with the run from a cold start, every
//     accepted step with its length, flux and speeds (core/transient_flash_temperature.hpp), the
//     maps reported at the snapshots: a start from rest, an impact, a varying speed or a growing
//     contact is followed, and a steady state reaches the quasi-steady map.
// The worst snapshot is reported with every snapshot's maximum; its fields_<step>.csv get the
// `temperature` column.
#include <memory>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "dynamic_simulation.hpp"
#include "static_fields.hpp"
#include "transient_flash_temperature.hpp"

namespace dc::runs {

class DynamicTemperature {
 public:
  /// `c` must outlive this object.
  explicit DynamicTemperature(const Case& c) : case_(c) {}
  /// Both surfaces have thermal constants (build_case then also requires snapshots).
  bool wanted() const { return case_.thermal.enabled(); }
  /// The model needs every step's fields (transient), not only the snapshots'.
  bool every_step() const { return wanted() && case_.thermal.model == ThermalSpec::Model::transient; }
  /// After an accepted step: `fields` its fields (dynamic_step_fields) when `snapshot` or
  /// every_step(). The transient model advances; at a snapshot the maps go into `fields` and
  /// the snapshot's entry is kept.
  void observe(const Grid& grid, const dynamics::DynamicSample& s, output::StaticFields& fields, bool snapshot);
  /// summary["temperature"]: the worst snapshot's entry (temperature_run.hpp) with its step and
  /// time, "model", and "states": [{step, time, max_rise}]; nothing without snapshots.
  void add_entries(nlohmann::json& summary) const;

 private:
  /// The step's power density's shares into fields.dissipation and its rate: false without heat.
  bool heat_of_step(const Grid& grid, const dynamics::DynamicSample& s, output::StaticFields& fields) const;
  nlohmann::json transient_step(const Grid& grid, const dynamics::DynamicSample& s, output::StaticFields& fields,
                                bool heated);
  void keep(const dynamics::DynamicSample& s, nlohmann::json entry);

  const Case& case_;
  std::unique_ptr<TransientFlashTemperature> transient_;  ///< made at the run's first step (its grid)
  double last_time_ = 0.0;                                ///< the previous step's end (s)
  nlohmann::json states_ = nlohmann::json::array();
  nlohmann::json worst_;
  double worst_rise_ = -1.0;
};

}  // namespace dc::runs
