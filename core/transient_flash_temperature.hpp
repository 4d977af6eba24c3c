#pragma once
// The time-stepped flash temperature of the two surfaces of a contact (the transient form of
// flash_temperature.hpp): each surface a half-space of its own (transient_heat.hpp) heated by
// its share of the frictional flux q of each step, the contact moving over the base at V_base
// and over the body's surface at V_body (moving_heat_source.hpp's sign), both varying from
// step to step.
//
// The partition per step (flash_temperature.hpp's rules, with the history in them): by
// linearity each surface's temperature after the step is its free part F_s (its history, no
// new heat) plus its share of the step's response R_s (the whole flux into that surface), and
// with f the fraction into the base
//   T_base = F_base + f R_base,   T_body = F_body + (1 - f) R_body.
//   equal_mean: equal means over the heated elements,
//               f = (mean F_body + mean R_body - mean F_base) / (mean R_base + mean R_body),
//   equal_max:  equal maxima (max T_base - max T_body rises with f: bisection to 1e-12),
//   fixed:      f given;
// f is kept in [0, 1] (a surface whose history is hotter than the other's whole response
// takes no heat). `pointwise` is not offered (InputError naming `partition`).
#include <string>
#include <vector>

#include "flash_temperature.hpp"
#include "transient_heat.hpp"

namespace dc {

class TransientFlashTemperature {
 public:
  /// `step`, `duration`, `options`: transient_heat.hpp's (the depth grid). Errors (InputError)
  /// name `base_key` / `body_key` with the failing member, `partition_key` for the partition.
  TransientFlashTemperature(const Grid& grid, const ThermalProperties& base, const ThermalProperties& body,
                            const HeatPartition& partition, double step, double duration,
                            const TransientHeatOptions& options = {}, const std::string& base_key = "base",
                            const std::string& body_key = "body", const std::string& partition_key = "partition");

  /// One step of h (s) with the flux `heat_flux` (grid.size() values >= 0, W/m^2) constant over
  /// it: both surfaces' temperatures at its end, their statistics and the step's fraction.
  FlashTemperatureResult step(double h, double base_speed, double body_speed, const std::vector<double>& heat_flux);

  const TransientHeat& surface(BodySide side) const { return side == BodySide::base ? base_ : body_; }

 private:
  double fraction(const std::vector<double>& q) const;

  Grid grid_;
  HeatPartition partition_;
  TransientHeat base_, body_;
  std::vector<double> free_base_, free_body_, response_base_, response_body_;
};

}  // namespace dc
