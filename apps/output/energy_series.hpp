#pragma once
// energy.csv of a "dynamic" run: the energy audit (dynamics/dynamic_simulation.hpp EnergyAudit)
// at t = 0 and after every accepted step (docs/wear_energy.md "Dynamic runs").
#include <ostream>

#include "dynamic_simulation.hpp"

namespace dc::output {

/// energy.csv's header line.
inline constexpr const char* kEnergyColumns = "t,kinetic,elastic,work,dissipated,numerical_damping\n";

/// The row of t = 0: the initial state's kinetic energy and the elastic energy its contact stores
/// (0 unless the body starts pressed in).
void append_energy_start(std::ostream& out, double time, double kinetic, double elastic);
/// The row of an accepted step.
void append_energy_row(std::ostream& out, const dynamics::DynamicSample& s);

}  // namespace dc::output
