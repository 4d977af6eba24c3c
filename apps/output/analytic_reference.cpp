#include "analytic_reference.hpp"

#include <cmath>
#include <numbers>

#include "hertz.hpp"

namespace dc::output {

double AnalyticReference::pressure(double x, double y) const {
  if (kind == "boussinesq_flat_punch") {
    const double r = std::hypot(x, y);
    return r < semi_axis_x ? hertz::flat_punch_pressure(semi_axis_x, force, r) : 0.0;
  }
  const double s = dimension == 2 ? 1.0 - (x * x) / (semi_axis_x * semi_axis_x)
                                  : 1.0 - (x * x) / (semi_axis_x * semi_axis_x) -
                                        (y * y) / (semi_axis_y * semi_axis_y);
  return s > 0.0 ? max_pressure * std::sqrt(s) : 0.0;
}

double AnalyticReference::contact_area() const {
  if (dimension == 2) return 2.0 * semi_axis_x;
  return std::numbers::pi * semi_axis_x * semi_axis_y;
}

nlohmann::json AnalyticReference::to_json() const {
  nlohmann::json j = {{"kind", kind},
                      {"semi_axis_x", semi_axis_x},
                      {"normal_force", force},
                      {"contact_area", contact_area()}};
  if (dimension == 3) j["semi_axis_y"] = semi_axis_y;
  if (kind == "boussinesq_flat_punch") j["centre_pressure"] = max_pressure;
  else j["max_pressure"] = max_pressure;
  j["approach"] = approach ? nlohmann::json(*approach) : nlohmann::json(nullptr);
  return j;
}

std::optional<AnalyticReference> analytic_reference(const Case& c) {
  const bool static_problem = c.problem == ProblemKind::normal || c.problem == ProblemKind::tangential;
  if (!static_problem) return std::nullopt;
  const ProfileSpec& p = c.profile;
  const double E_star = c.materials.E_star();
  const bool force_control = c.normal.control == Control::force;
  AnalyticReference r;
  r.dimension = c.dimension;
  if (p.type == ProfileType::flat_punch && p.inner_radius > 0.0) return std::nullopt;  // an annulus: none
  if (p.type == ProfileType::flat_punch) {
    r.kind = "boussinesq_flat_punch";
    r.semi_axis_x = r.semi_axis_y = p.radius;
    if (force_control) {
      r.force = c.normal.value;
      r.approach = r.force / (2.0 * p.radius * E_star);
    } else {
      r.approach = c.normal.value;
      r.force = hertz::flat_punch_force(p.radius, c.normal.value, E_star);
    }
    r.max_pressure = r.force / (2.0 * std::numbers::pi * p.radius * p.radius);
    return r;
  }
  if (p.type == ProfileType::table) return std::nullopt;
  double A = 0.0, B = 0.0;
  p.quadratic_coefficients(A, B);
  if (c.dimension == 2) {
    if (!force_control || !(A > 0.0)) return std::nullopt;
    const auto s = hertz::cylinder2d(0.5 / A, c.normal.value, E_star);
    r.kind = "hertz_cylinder_2d";
    r.semi_axis_x = r.semi_axis_y = s.a;
    r.max_pressure = s.p0;
    r.force = c.normal.value;
    return r;
  }
  if (!(A > 0.0 && B > 0.0)) return std::nullopt;
  double P = c.normal.value;
  if (!force_control) {
    P = A == B ? 4.0 / 3.0 * E_star * std::sqrt(0.5 / A) * std::pow(c.normal.value, 1.5)
               : std::pow(c.normal.value / hertz::elliptic(A, B, 1.0, E_star).approach, 1.5);
  }
  if (A == B) {
    const auto s = hertz::sphere(0.5 / A, P, E_star);
    r.kind = "hertz_sphere";
    r.semi_axis_x = r.semi_axis_y = s.a;
    r.max_pressure = s.p0;
    r.approach = s.approach;
  } else {
    const auto s = hertz::elliptic(A, B, P, E_star);
    r.kind = "hertz_elliptic";
    r.semi_axis_x = s.a;
    r.semi_axis_y = s.b;
    r.max_pressure = s.p0;
    r.approach = s.approach;
  }
  if (!force_control) r.approach = c.normal.value;
  r.force = P;
  return r;
}

}  // namespace dc::output
