#pragma once
// Closed-form reference of a normal case (Hertz, Boussinesq), for summaries, plots and
// `dyncontact validate`. Only where the closed form applies (see analytic_reference()).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "case_model.hpp"

namespace dc::output {

struct AnalyticReference {
  std::string kind;        ///< hertz_sphere | hertz_elliptic | hertz_cylinder_2d | boussinesq_flat_punch
  double semi_axis_x = 0;  ///< a (m); flat punch: its radius
  double semi_axis_y = 0;  ///< b (m); 2-D: = a
  double max_pressure = 0; ///< p0 (Pa); flat punch: the centre pressure P/(2 pi a^2)
  double force = 0;        ///< N (2-D: N/m), given or implied by the approach
  std::optional<double> approach;  ///< m; none in 2-D (relative to a reference length)
  int dimension = 3;

  /// The closed-form pressure at (x, y) (0 outside the contact; the punch's rim is singular).
  double pressure(double x, double y) const;
  /// Contact area (2-D: contact width 2a).
  double contact_area() const;
  nlohmann::json to_json() const;
};

/// Sphere, ellipsoid, quadratic (both curvatures > 0) in 3-D; cylinder or quadratic in 2-D
/// under force control; the flat punch in 3-D. Otherwise none.
std::optional<AnalyticReference> analytic_reference(const Case& c);

}  // namespace dc::output
