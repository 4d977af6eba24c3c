#include "yield_criterion.hpp"

#include <cmath>

#include "number_text.hpp"

namespace dc {

const char* to_string(YieldKind kind) {
  switch (kind) {
    case YieldKind::von_mises: return "von_mises";
    case YieldKind::tresca_plane_xz: return "tresca_plane_xz";
    case YieldKind::tresca_inscribed: return "tresca_inscribed";
  }
  return "?";
}

double YieldCriterion::shear_yield() const {
  return kind == YieldKind::von_mises ? strength / std::sqrt(3.0) : strength;
}

Eigen::MatrixXd YieldCriterion::factor() const {
  const double k = shear_yield();
  if (kind != YieldKind::tresca_plane_xz) return deviatoric_coordinate_map() / k;
  Eigen::MatrixXd l = Eigen::MatrixXd::Zero(2, 6);
  l(0, index_of(VoigtComponent::xx)) = 0.5 / k;
  l(0, index_of(VoigtComponent::zz)) = -0.5 / k;
  l(1, index_of(VoigtComponent::xz)) = 1.0 / k;
  return l;
}

double YieldCriterion::ratio(const Voigt& s) const {
  const double k = shear_yield();
  if (kind != YieldKind::tresca_plane_xz) return sqrt_j2(s) / k;
  return std::hypot(0.5 * (s[0] - s[2]), s[4]) / k;
}

double YieldCriterion::exact_ratio(const Voigt& s) const {
  return kind == YieldKind::tresca_inscribed ? tresca_shear(s) / shear_yield() : ratio(s);
}

double YieldCriterion::outer_factor() const {
  return kind == YieldKind::tresca_inscribed ? 2.0 / std::sqrt(3.0) : 1.0;
}

std::string YieldCriterion::validate() const {
  if (!std::isfinite(strength) || strength <= 0.0)
    return "strength: must be positive and finite, got " + six_digits(strength);
  return "";
}

}  // namespace dc
