#pragma once
// The blocks of a "paper_cylinder" case (CASES.md, docs/paper_cylinder.md): the paper's
// dimensionless inputs, or the dimensional ones (body, loads, time, with materials and
// friction), the time scheme, the traction model and a sweep. Read into PaperCylinderSpec;
// the model itself (dynamics/paper_cylinder) never sees JSON.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "dynamic_spec.hpp"  // ValueRate

namespace dc {

/// Dimensional inputs (per unit length in 2-D).
struct PaperCylinderBody {
  double mass = 0.0;       ///< M (kg)
  double radius = 0.0;     ///< R (m)
  double inertia_y = 0.0;  ///< I about the axis (kg m^2)
  std::array<double, 3> position{}, velocity{}, omega{};  ///< body.initial (velocity[0] > 0)
  bool has_position = false;
  ValueRate force_x, force_z, moment_y;  ///< loads.force.x (T_ex), loads.force.z (-P), loads.moment.y
  double dt = 0.0, t_end = 0.0;          ///< time (s)
};

struct PaperCylinderSpec {
  bool dimensional = false;  ///< body/loads/time given instead of "dimensionless"
  /// "dimensionless" keys as given (the model's defaults for the others).
  std::optional<double> gamma_bar, M0_bar, eta, epsilon, v_bar0, t_bar_end, T_bar, mu;
  std::optional<double> dt;  ///< dimensionless inputs: time.dt, a step of t_bar
  PaperCylinderBody body;    ///< dimensional inputs
  bool bdf2 = false;         ///< time.scheme
  std::string traction_model = "carter_poritsky";  ///< or "numerical"
};

}  // namespace dc
