#pragma once
// The flash temperature of a rolling run (CASES.md "temperature"): the frictional power density
// of the final state, q = -tau . ds / dt (W/m^2; dt = dx / V, output::StaticFields), shared
// between the base and the body by the case's partition, each surface's quasi-steady
// temperature rise from Jaeger's moving source (core/flash_temperature.hpp). Both surfaces
// move through the contact at the rolling speed V (the library's V_s = V: the contact moves
// along +x over both); the creepage's O(xi) difference of the body's surface speed is
// neglected.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "static_fields.hpp"

namespace dc::runs {

/// Computes the maps into `fields` (temperature_base, temperature_body) from its power density
/// (dissipation x dissipation_rate), the contact moving over the base at `base_speed` and over
/// the body's surface at `body_speed` (m/s along +x, the library's V_s), and returns the entry:
/// {max_rise, at, base {max_rise, at, mean_rise}, body {...}, partition, fraction_into_base, heat,
/// peclet {base, body, length}, heated_elements, operator}. A state without a rate (a
/// quasi-static step) has no flux: {"max_rise": null, "note"}.
nlohmann::json flash_temperature(const ThermalSpec& t, const Grid& grid, output::StaticFields& fields,
                                 double base_speed, double body_speed);

/// The power density q (W/m^2) of `fields`: dissipation x dissipation_rate, negative
/// round-off shares set to 0.
std::vector<double> power_density(const output::StaticFields& fields);

/// flash_temperature's entry for the maps `r` of the flux `q`; `model` its "operator" (dense,
/// fft, transient).
nlohmann::json flash_entry(const ThermalSpec& t, const Grid& grid, const std::vector<double>& q,
                           const FlashTemperatureResult& r, double base_speed, double body_speed,
                           const std::string& model);

/// summary.json's "temperature" of a rolling case's final state: both surfaces at the rolling speed.
nlohmann::json add_flash_temperature(const Case& c, const Grid& grid, output::StaticFields& fields);

}  // namespace dc::runs
