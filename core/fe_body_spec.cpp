// The finite-element body's sizes that follow from the grid and the materials (fe_body_spec.hpp).
#include "fe_body_spec.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dc {

double grid_refine_radius(const Grid& grid) {
  return std::max(0.0, std::min({-grid.x0, grid.x_max(), -grid.y0, grid.y_max()}));
}

double grid_contact_size(const Grid& grid) { return grid_refine_radius(grid) / 8.0; }

namespace {

/// (1 - nu^2) / E of the isotropic material with the Voigt-averaged bulk and shear moduli of C.
double voigt_normal_compliance(const fe::Stiffness& C) {
  const double diag = C(0, 0) + C(1, 1) + C(2, 2), off = C(0, 1) + C(0, 2) + C(1, 2);
  const double K = (diag + 2.0 * off) / 9.0;
  const double G = (diag - off + 3.0 * (C(3, 3) + C(4, 4) + C(5, 5))) / 15.0;
  const double E = 9.0 * K * G / (3.0 * K + G), nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
  return (1.0 - nu * nu) / E;
}

}  // namespace

double body_compliance_ratio(const FeBodySpec& body, const Elastic& halfspace) {
  const double base = halfspace.normal_compliance();
  if (!(base > 0.0)) return 0.0;
  double worst = voigt_normal_compliance(body.material.C);
  for (const auto& r : body.regions) worst = std::max(worst, voigt_normal_compliance(r.material.C));
  return worst / base;
}

double face_cell_bound(const FeBodySpec& body, const Elastic& halfspace, const Grid& grid) {
  const double ratio = body_compliance_ratio(body, halfspace);
  if (!(ratio > 1.0)) return std::numeric_limits<double>::infinity();
  return std::max(0.5, 4.0 / std::sqrt(ratio)) * std::min(grid.dx, grid.dy);
}

double default_contact_size_bound(const FeBodySpec& body, const Elastic& halfspace, const Grid& grid) {
  double bound = face_cell_bound(body, halfspace, grid);
  if (const double reach = grid_contact_size(grid); reach > 0.0) bound = std::min(bound, reach);
  return std::isfinite(bound) ? bound : 0.0;
}

}  // namespace dc
