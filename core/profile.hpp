#pragma once
// Undeformed gap profiles x3(x1, x2) of (2.6), measured from the first point of contact.
#include <string>
#include <vector>

#include "grid.hpp"

namespace dc {

enum class ProfileType { sphere, ellipsoid, cylinder, flat_punch, quadratic, table };

struct ProfileSpec {
  ProfileType type = ProfileType::sphere;
  double radius = 0.0;                 ///< sphere, cylinder, flat_punch
  double inner_radius = 0.0;           ///< flat_punch: an annulus inner_radius <= r < radius (0: the disc)
  double radius_x = 0.0, radius_y = 0.0;  ///< ellipsoid
  double a = 0.0, b = 0.0;             ///< quadratic: h = a x^2 + b y^2
  double length = 0.0;                 ///< 3-D cylinder: finite length along y (0: whole grid)
  std::string file;                    ///< table: CSV with columns x,y,h
  std::vector<double> table_x, table_y, table_h;  ///< table contents once read

  /// Curvature coefficients (A, B) of h ~ A x^2 + B y^2 for the Hertz estimate; throws for
  /// profiles that have none (flat punch, table).
  void quadratic_coefficients(double& A, double& B) const;
};

/// Gap h at each element centre (m). Elements that can never touch (outside a flat punch or
/// a finite cylinder) get +infinity: the problems fix their traction to zero.
std::vector<double> profile_heights(const ProfileSpec& profile, const Grid& grid);

const char* to_string(ProfileType type);

}  // namespace dc
