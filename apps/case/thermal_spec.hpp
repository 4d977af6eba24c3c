#pragma once
// materials.<body>.thermal and the "temperature" block (CASES.md): each surface's conductivity
// and diffusivity, and how the frictional heat is shared between the two (the flash
// temperature, core/flash_temperature.hpp), and the model of it (quasi-steady or transient).
#include <optional>

#include "flash_temperature.hpp"
#include "moving_heat_source.hpp"

namespace dc {

struct ThermalSpec {
  /// materials.<body>.thermal: {"conductivity": W/(m K), "diffusivity": m^2/s}.
  std::optional<ThermalProperties> body, base;
  /// temperature.partition: "auto" (= "equal_mean"), "equal_mean", "equal_max", "pointwise", or
  /// a number, the fraction of the heat into the base in [0, 1] (HeatPartition::Rule::fixed).
  HeatPartition partition;
  /// temperature.model: "quasi_steady" (the default: Jaeger's steady moving source at each
  /// state, core/flash_temperature.hpp) or "transient" (dynamic runs: the temperature stepped
  /// with the run from a cold start, core/transient_flash_temperature.hpp).
  enum class Model { quasi_steady, transient } model = Model::quasi_steady;
  /// The flash temperature is computed when both surfaces have thermal constants.
  bool enabled() const { return body && base; }
};

}  // namespace dc
