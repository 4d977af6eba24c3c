#include "contact_limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dc {
namespace {

/// Whether the profile's contact is unbounded along y (3-D cylinder without a length,
/// quadratic with b = 0): it reaches the grid's y edges by construction.
bool unbounded_profile(const ContactSpec& c) {
  const ProfileSpec& p = c.profile;
  if (c.dimension != 3) return false;
  return (p.type == ProfileType::cylinder && p.length == 0.0) ||
         (p.type == ProfileType::quadratic && (p.a == 0.0 || p.b == 0.0));
}

/// Radii of curvature along x and y (0: none, e.g. a flat punch or a table; an fe_body: its
/// hemisphere's radius).
void curvature_radii(const ContactSpec& c, double& rx, double& ry) {
  rx = ry = 0.0;
  if (c.fe_body) {
    if (c.fe_body->shape == FeShape::hemisphere) rx = ry = c.fe_body->radius;
    return;
  }
  const ProfileSpec& p = c.profile;
  if (p.type == ProfileType::flat_punch || p.type == ProfileType::table) return;
  double A = 0.0, B = 0.0;
  p.quadratic_coefficients(A, B);  // h = A x^2 + B y^2: R = 1 / (2 A)
  if (A > 0.0) rx = 0.5 / A;
  if (B > 0.0 && c.dimension == 3) ry = 0.5 / B;
}

std::string format(const char* f, double a, double b = 0.0) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, a, b);
  return buf;
}

}  // namespace

std::vector<ResultLimit> result_limits(const ContactSpec& c, const ContactSize& size) {
  std::vector<ResultLimit> out;
  if (size.edge_fraction > 0.0) {
    ResultLimit l{"grid", "", false};
    l.message = format("the contact reaches the edge of the grid (%.3g %% of the edge elements are in contact): the "
                       "pressure is truncated there and the results are wrong; enlarge grid.extent or grid.x",
                       100.0 * size.edge_fraction) +
                (c.dimension == 3 ? "/grid.y" : "");
    if (unbounded_profile(c)) {
      l.message += " (this profile's contact is unbounded along y: its ends are cut by the grid)";
    } else if (c.allow_edge_contact) {
      l.message += " (accepted: grid.allow_edge_contact)";
      l.accepted = true;
    } else {
      l.message += ", or set grid.allow_edge_contact: true to accept a truncated contact";
      l.error = true;
    }
    out.push_back(l);
  }
  const int across = std::min(size.across_x, c.dimension == 3 ? size.across_y : size.across_x);
  if (size.across_x >= 0 && across < 4)
    out.push_back({"grid",
                   format("only %.0f element(s) across the contact: its pressure distribution is not resolved (the "
                          "peak pressure can be off by a large factor); refine the grid (8 or more across)",
                          across),
                   false});
  // An fe_body's face elements too wide for the contact: the body's compliance, and so the
  // pressure, is not resolved (kFaceResolvedShare).
  const double half_width = c.dimension == 3 ? std::min(size.half_width_x, size.half_width_y) : size.half_width_x;
  if (size.face_element_size > 0.0 && half_width > 0.0 && size.face_element_size > kFaceResolvedShare * half_width)
    out.push_back({"fe_body.contact_size",
                   format("the body's face elements over the contact are %.3g m, %.2g times the contact's "
                          "half-width: the pressure is not resolved (expect errors of 5 %% or more); give "
                          "fe_body.contact_size of a sixth of the half-width or less, or a grid closer to the "
                          "contact (the default is an eighth of the grid's reach)",
                          size.face_element_size, size.face_element_size / half_width),
                   false});
  // A body more compliant than the half-space: its face must also resolve the grid's cells.
  if (size.face_element_size > 0.0 && c.fe_body) {
    const double bound = face_cell_bound(*c.fe_body, c.materials.base, c.grid);
    if (size.face_element_size > 1.25 * bound)  // Gmsh's edges come out up to ~1.15 x the size asked
      out.push_back({"fe_body.contact_size",
                     format("the body is %.3g times as compliant as the half-space and its face elements over the "
                            "contact are %.3g m: within them the pressure's grid-scale modes meet the half-space "
                            "alone (expect a noisy pressure and a slow solve); give fe_body.contact_size of at most ",
                            body_compliance_ratio(*c.fe_body, c.materials.base), size.face_element_size) +
                         format("%.3g m (%.2g grid cells), or leave it to the default", bound,
                                bound / std::min(c.grid.dx, c.grid.dy)),
                     false});
  }
  double rx = 0.0, ry = 0.0;
  curvature_radii(c, rx, ry);
  double ratio = 0.0;
  if (rx > 0.0) ratio = std::max(ratio, size.half_width_x / rx);
  if (ry > 0.0) ratio = std::max(ratio, size.half_width_y / ry);
  // Hertz's theory (and this program's half-space model) needs a << R: small strains, and
  // the contact small against the body. Beyond a/R ~ 0.1 the errors grow; from 0.3 the
  // result is not that of the physical problem.
  if (ratio > 0.1) {
    ResultLimit l{"materials", "", false};
    l.message = format("the contact half-width a is %.3g times the body's radius of curvature R (a/R = %.3g): linear "
                       "elasticity and the half-space model need a/R << 1 (Hertz: below about 0.1)",
                       ratio, ratio);
    if (ratio <= 0.3) {
      l.message += "; expect errors of order (a/R)^2";
    } else if (c.allow_large_strain) {
      l.message += "; the result is not that of the physical body (accepted: materials.allow_large_strain)";
      l.accepted = true;
    } else {
      l.message += "; the result is not that of the physical body (stiffer materials or a smaller load reduce "
                   "a/R), or set materials.allow_large_strain: true to accept it";
      l.error = true;
    }
    out.push_back(l);
  }
  return out;
}

}  // namespace dc
