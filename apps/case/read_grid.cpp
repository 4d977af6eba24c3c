// The "grid" block (CASES.md): explicit bounds or `extent` sized by the Hertz contact, and the
// check that the profile touches inside the grid.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "case_readers.hpp"
#include "errors.hpp"
#include "hertz.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

/// Hertz semi-axes (x, y) of the case's contact, for `extent` grids.
void hertz_semi_axes(const Case& c, bool has_normal, double& ax, double& ay) {
  const ProfileSpec& p = c.profile;
  if (p.type == ProfileType::flat_punch) {
    ax = ay = p.radius;
    return;
  }
  if (p.type == ProfileType::table)
    throw InputError("grid.extent", "a table profile has no Hertz estimate: give explicit grid.x (and grid.y) bounds");
  if (!has_normal && c.problem == ProblemKind::dynamic)
    throw InputError("grid.extent", "a dynamic case's grid is sized by the Hertz contact of a downward load "
                                    "(loads.force.z < 0) or of an impact (body.initial.velocity z < 0); with neither, "
                                    "give the grid's bounds grid.x and grid.y");
  if (!has_normal)
    throw InputError("grid.extent", "needs normal.force or normal.approach to size the Hertz contact");
  const double E_star = c.materials.E_star();
  const bool approach = c.normal.control == Control::approach;
  const char* approach_2d =
      "with normal.approach the 2-D/line contact width is not fixed by Hertz (the plane-strain approach "
      "depends on a reference length): give explicit grid.x bounds";
  double A = 0.0, B = 0.0;
  p.quadratic_coefficients(A, B);
  if (c.dimension == 2) {
    if (approach) throw InputError("grid.extent", approach_2d);
    ax = hertz::cylinder2d(0.5 / A, c.normal.value, E_star).a;
    ay = ax;
    return;
  }
  if (A == 0.0 || B == 0.0) {
    if (p.type == ProfileType::cylinder && p.length > 0.0) {
      if (approach) throw InputError("grid.extent", approach_2d);
      ax = hertz::cylinder2d(p.radius, c.normal.value / p.length, E_star).a;
      ay = 0.5 * p.length;
      return;
    }
    throw InputError("grid.extent", "the contact of this profile is unbounded along one axis "
                                    "(give the cylinder a length, or explicit grid bounds)");
  }
  double P = c.normal.value;
  if (A == B) {  // axisymmetric: the sphere formulas, P = 4/3 E* sqrt(R) approach^(3/2)
    const double R = 0.5 / A;
    if (approach) P = 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(c.normal.value, 1.5);
    ax = ay = hertz::sphere(R, P, E_star).a;
    return;
  }
  if (approach) {  // approach ~ P^(2/3): invert from the unit-load solution
    const double d1 = hertz::elliptic(A, B, 1.0, E_star).approach;
    P = std::pow(c.normal.value / d1, 1.5);
  }
  const auto s = hertz::elliptic(A, B, P, E_star);
  ax = s.a;
  ay = s.b;
}

std::vector<double> bounds(const JsonBlock& o, const char* k) {
  const auto v = o.numbers(k);
  if (v.size() != 2) throw InputError(o.key(k), "expected [min, max]");
  if (!(v[1] > v[0])) throw InputError(o.key(k), "expected [min, max] with min < max");
  return v;
}

}  // namespace

Grid read_grid(const json& j, const Case& c, bool has_normal) {
  JsonBlock o(j, "grid");
  const bool three_d = c.dimension == 3;
  o.allow({"nx", "ny", "x", "y", "extent", "allow_edge_contact"});
  (void)o.boolean_or("allow_edge_contact", false);  // read into Case by build_case
  // With an accuracy target the element counts are the refinement's start (optional): about 16
  // elements across the closed-form contact estimate (extent k: nx = 2 k * 8), a multiple of 4
  // so that the grids of 2 and 4 times the element size cover the same bounds.
  const bool target = c.accuracy.target.has_value();
  const double start_extent = o.has("extent") ? o.positive("extent") : 1.5;
  const int start_count = std::max(16, 4 * static_cast<int>(std::ceil(2.0 * start_extent * (three_d ? 8 : 32) / 4.0)));
  const int nx = target && !o.has("nx") ? start_count : o.integer("nx");
  if (nx < 1) throw InputError("grid.nx", "must be at least 1, got " + std::to_string(nx));
  // One element across cannot represent a pressure distribution (a 1 x 1 grid puts the whole
  // load on one uniform element: the peak comes out about 3 times too low).
  if (nx == 1)
    throw InputError("grid.nx", "one element across cannot resolve the contact pressure; use at least 2 (about "
                                "8 or more across the contact for a usable peak pressure)");
  int ny = 1;
  if (three_d) {
    ny = target && !o.has("ny") ? start_count : o.integer("ny");
    if (ny < 1) throw InputError("grid.ny", "must be at least 1, got " + std::to_string(ny));
    if (ny == 1)
      throw InputError("grid.ny", "one element across cannot resolve the contact pressure in 3-D; use at least 2 "
                                  "(or dimension 2 for a plane-strain line contact)");
  } else if (o.has("ny")) {
    ny = o.integer("ny");
    if (ny != 1) throw InputError("grid.ny", "must be 1 (or omitted) in 2-D, got " + std::to_string(ny));
  }
  if (static_cast<double>(nx) * ny > 4194304.0)
    throw InputError("grid", "too many elements (" + std::to_string(static_cast<long long>(nx) * ny) +
                                 "; at most 2048 x 2048)");
  const bool has_x = o.has("x"), has_extent = o.has("extent") || (target && !o.has("x"));
  if (has_x && has_extent) throw InputError("grid.extent", "give either extent or x/y bounds, not both");
  if (has_extent) {
    if (three_d && o.has("y")) throw InputError("grid.y", "give either extent or x/y bounds, not both");
    const double k = start_extent;
    double ax = 0.0, ay = 0.0;
    hertz_semi_axes(c, has_normal, ax, ay);
    if (!(std::isfinite(ax) && ax > 0.0 && std::isfinite(ay) && ay > 0.0))
      throw InputError("grid.extent", "the Hertz estimate of the contact size is not finite");
    return Grid::make(c.dimension, nx, ny, -k * ax, k * ax, -k * ay, k * ay);
  }
  if (!has_x) throw InputError("grid.x", "missing required key (give x [min, max]" +
                                             std::string(three_d ? " and y" : "") + ", or extent)");
  const auto x = bounds(o, "x");
  if (!three_d) return Grid::make(2, nx, 1, x[0], x[1], 0.0, 0.0);
  if (!o.has("y")) throw InputError("grid.y", "missing required key (3-D grids need y [min, max])");
  const auto y = bounds(o, "y");
  return Grid::make(3, nx, ny, x[0], x[1], y[0], y[1]);
}

/// The profile must be able to touch inside the grid: its first point of contact lies in the
/// grid and some element has a finite gap. Otherwise the normal problem cannot carry the load.
void check_contact_in_grid(const Case& c) {
  const Grid& g = c.grid;
  const std::vector<double> h = profile_heights(c.profile, g);
  if (std::none_of(h.begin(), h.end(), [](double v) { return std::isfinite(v); }))
    throw InputError("grid", "no element centre lies under the profile (refine the grid or enlarge the punch)");
  const ProfileSpec& p = c.profile;
  double px = 0.0, py = 0.0;
  bool free_x = false, free_y = false;  // the contact is a line along that axis
  double half_len_y = 0.0;              // finite cylinder: the line's half-length
  if (p.type == ProfileType::table) {
    const auto k = static_cast<std::size_t>(std::min_element(p.table_h.begin(), p.table_h.end()) - p.table_h.begin());
    px = p.table_x[k];
    py = p.table_y[k];
    const bool single_row = std::all_of(p.table_y.begin(), p.table_y.end(), [&](double v) { return v == p.table_y[0]; });
    free_y = single_row;
  } else if (p.type == ProfileType::cylinder) {
    free_y = true;
    half_len_y = 0.5 * p.length;
  } else if (p.type == ProfileType::quadratic) {
    free_x = p.a == 0.0;
    free_y = p.b == 0.0;
  }
  const double tx = 1e-12 * (g.x_max() - g.x0), ty = 1e-12 * (g.y_max() - g.y0);
  bool inside = free_x || (px >= g.x0 - tx && px <= g.x_max() + tx);
  if (g.dimension == 3 && !free_y) inside = inside && py >= g.y0 - ty && py <= g.y_max() + ty;
  if (g.dimension == 3 && free_y && half_len_y > 0.0)
    inside = inside && g.y_max() > -half_len_y && g.y0 < half_len_y;
  if (!inside) {
    std::string where = "grid x in [" + fmt(g.x0) + ", " + fmt(g.x_max()) + "]";
    if (g.dimension == 3) where += ", y in [" + fmt(g.y0) + ", " + fmt(g.y_max()) + "]";
    throw InputError("grid", "the contact point lies outside the grid (" + where + " does not contain (" +
                                 fmt(px) + ", " + fmt(py) + "), where the profile first touches): " +
                                 "the contact could not carry the load");
  }
}

}  // namespace dc
