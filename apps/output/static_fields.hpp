#pragma once
// The per-element result of a static problem as written to fields.csv, and the contact
// measures of summary.json derived from it.
#include <vector>

#include <nlohmann/json.hpp>

#include "grid.hpp"

namespace dc::output {

/// Element states of fields.csv.
enum ElementState : int { kFree = 0, kStick = 1, kSlip = 2 };

struct StaticFields {
  std::vector<double> p;             ///< pressure (Pa)
  std::vector<double> tx, ty;        ///< tangential traction (Pa); empty = 0
  std::vector<double> sx, sy;        ///< slip (m); empty = 0
  std::vector<double> bound;         ///< friction bound f(p) (Pa); empty for a normal problem
  std::vector<int> state;            ///< ElementState per element
  double contact_threshold = 0.0;    ///< elements with p > this are in contact
  /// The frictional work of the step per area, -tau . ds (J/m^2; >= 0 under Coulomb); empty:
  /// not computed (a normal problem).
  std::vector<double> dissipation;
  /// Per second, the rate turning `dissipation` into the power density (W/m^2): V / dx in
  /// rolling, 1/dt in a dynamic step; 0 for a quasi-static step (fields.csv: "dissipation").
  double dissipation_rate = 0.0;
  /// The flash temperature rise of each surface (K; apps/runs/temperature_run.hpp); empty: not
  /// computed (fields.csv then has no `temperature` column).
  std::vector<double> temperature_base, temperature_body;
};

/// Normal problem: no tangential traction; state 1 (kStick: "in contact") where
/// p > threshold, 0 elsewhere. threshold = relative_threshold * max p (a solver leaves
/// round-off pressures of that relative size outside the contact).
StaticFields normal_fields(const std::vector<double>& pressure, double relative_threshold);

struct ContactMeasures {
  int n_contact = 0;
  double contact_area = 0.0;  ///< m^2 (2-D: m)
  double max_pressure = 0.0;
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;  ///< element edges of the contact region
  bool touches_boundary = false;  ///< a contact element lies on the grid's edge
  int n_edge = 0, n_edge_contact = 0;  ///< elements on the grid's edge; of those, in contact
  int n_across_x = 0, n_across_y = 0;  ///< elements across the contact region along x, y
  /// The largest pressure on the contact's rim (contact elements beside a free one, or on the
  /// grid's edge) over the largest pressure: about sqrt(2 h / a) at a Hertzian edge, where the
  /// pressure falls to zero; 1 where the pressure peaks at the rim (a punch's singular edge).
  double rim_pressure_ratio = 0.0;
};

ContactMeasures contact_measures(const Grid& grid, const StaticFields& fields);

/// The normal-problem keys of summary.json: n_contact, contact_area, max_pressure,
/// contact_half_width (2-D), plus extras (contact_extent, contact_touches_boundary, ...).
void add_contact_measures(nlohmann::json& summary, const Grid& grid, const StaticFields& fields);

}  // namespace dc::output
