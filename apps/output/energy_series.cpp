#include "energy_series.hpp"

#include <cstdio>

namespace dc::output {

namespace {

void put_row(std::ostream& out, double t, double kinetic, double elastic, double work, double dissipated,
             double damping) {
  char line[256];
  const int n = std::snprintf(line, sizeof line, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", t, kinetic, elastic, work,
                              dissipated, damping);
  out.write(line, n);
}

}  // namespace

void append_energy_start(std::ostream& out, double time, double kinetic, double elastic) {
  put_row(out, time, kinetic, elastic, 0.0, 0.0, 0.0);
}

void append_energy_row(std::ostream& out, const dynamics::DynamicSample& s) {
  const dynamics::EnergyAudit& e = s.energy;
  put_row(out, s.state.time, s.kinetic_energy, e.elastic, e.work_of_loads, e.dissipated, e.numerical_damping);
}

}  // namespace dc::output
