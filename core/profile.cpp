// Profiles (2.6). Table profiles: ProfileSpec::table_x/table_y/table_h are the CSV columns as
// read (one entry per row, any order); they must form a regular lattice (every distinct x
// with every distinct y, or a single y row: then h depends on x only). Heights at element
// centres are interpolated along x on the rows, then along y, by the cubic Hermite of limited
// slopes (core/limited_hermite.hpp: a continuous slope, exact for quadratics, no overshoot at
// steps); the table covers half a node spacing beyond its outer nodes, an element centre beyond that is an
// InputError.
#include "profile.hpp"
#include "profile_turned.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "errors.hpp"
#include "limited_hermite.hpp"

namespace dc {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Sorted distinct values, merging those closer than `tol` (a regular table written with
/// printf rounding still has one column per abscissa).
std::vector<double> distinct(std::vector<double> v, double tol) {
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x - out.back() > tol) out.push_back(x);
  return out;
}

/// Index of the lattice value nearest to x (the lattice is sorted).
std::size_t nearest(const std::vector<double>& axis, double x) {
  auto it = std::lower_bound(axis.begin(), axis.end(), x);
  if (it == axis.begin()) return 0;
  if (it == axis.end()) return axis.size() - 1;
  const auto hi = static_cast<std::size_t>(it - axis.begin());
  return (x - axis[hi - 1] <= axis[hi] - x) ? hi - 1 : hi;
}

}  // namespace

/// The table's points rearranged on their regular lattice: h[ix + mx * iy].
struct TableLattice {
  std::vector<double> xs, ys, h;

  explicit TableLattice(const ProfileSpec& p) {
    const std::size_t n = p.table_h.size();
    if (n == 0) throw InputError("profile.file", "the table has no rows");
    if (p.table_x.size() != n || p.table_y.size() != n)
      throw InputError("profile.file", "columns x, y and h must have the same length");
    auto span = [](const std::vector<double>& v) {
      const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
      return *hi - *lo;
    };
    const double sx = span(p.table_x), sy = span(p.table_y);
    xs = distinct(p.table_x, 1e-9 * sx);
    ys = distinct(p.table_y, 1e-9 * sy);
    const std::size_t mx = xs.size(), my = ys.size();
    if (mx * my != n)
      throw InputError("profile.file",
                       "the table is not a regular lattice: " + std::to_string(mx) + " distinct x times " +
                           std::to_string(my) + " distinct y != " + std::to_string(n) + " rows");
    if (mx < 2) throw InputError("profile.file", "the table needs at least two distinct x values");
    h.assign(n, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t ix = nearest(xs, p.table_x[k]), iy = nearest(ys, p.table_y[k]);
      double& slot = h[ix + mx * iy];
      if (!std::isnan(slot))
        throw InputError("profile.file", "the point (" + std::to_string(p.table_x[k]) + ", " +
                                             std::to_string(p.table_y[k]) + ") appears twice");
      if (!std::isfinite(p.table_h[k]))
        throw InputError("profile.file", "h must be finite (row " + std::to_string(k + 1) + ")");
      slot = p.table_h[k];
    }
  }

  /// Position of x in the sorted axis as (cell index, position t in the cell: 0 at its lower
  /// node, 1 at its upper). The table covers half a node spacing beyond its outer nodes (a table
  /// at a grid's element centres covers the grid's elements, so finer grids over the same bounds
  /// are covered too; t from -1/2 to 3/2 in the outer cells); beyond that it throws.
  static void locate(const std::vector<double>& axis, double x, std::size_t& cell, double& t) {
    const std::size_t n = axis.size();
    const double tol = 1e-9 * (axis.back() - axis.front());
    const double lo = axis[0] - 0.5 * (axis[1] - axis[0]), hi = axis[n - 1] + 0.5 * (axis[n - 1] - axis[n - 2]);
    if (x < lo - tol || x > hi + tol) throw InputError("profile.file", "grid extends outside the table");
    auto it = std::upper_bound(axis.begin(), axis.end(), x);
    const std::size_t upper = std::clamp<std::size_t>(static_cast<std::size_t>(it - axis.begin()), 1, n - 1);
    cell = upper - 1;
    t = std::clamp((x - axis[cell]) / (axis[upper] - axis[cell]), -0.5, 1.5);
  }

  /// The height at (x, y): along x on the six rows about y, then along y; a table with a single
  /// y row depends on x only (extruded along y).
  double at(double x, double y) const {
    std::size_t i = 0, j = 0;
    double tx = 0.0, ty = 0.0;
    locate(xs, x, i, tx);
    const std::size_t mx = xs.size(), my = ys.size();
    const auto x_at = [&](std::size_t a) { return xs[a]; };
    const auto row = [&](std::size_t b) {
      return limited_hermite(mx, i, tx, x_at, [&](std::size_t a) { return h[a + mx * b]; });
    };
    if (my == 1) return row(0);
    locate(ys, y, j, ty);
    return limited_hermite(my, j, ty, [&](std::size_t b) { return ys[b]; }, row);
  }
};

void ProfileSpec::quadratic_coefficients(double& A, double& B) const {
  switch (type) {
    case ProfileType::sphere:
      A = B = 0.5 / radius;
      return;
    case ProfileType::ellipsoid:
      A = 0.5 / radius_x;
      B = 0.5 / radius_y;
      return;
    case ProfileType::cylinder:
      A = 0.5 / radius;
      B = 0.0;
      return;
    case ProfileType::quadratic:
      A = a;
      B = b;
      return;
    case ProfileType::flat_punch:
    case ProfileType::table:
      break;
  }
  throw InputError("profile.type", std::string("a '") + to_string(type) +
                                       "' profile has no curvature for a Hertz estimate");
}

std::vector<double> profile_heights(const ProfileSpec& profile, const Grid& grid) {
  return profile_heights(profile, grid, 0.0);
}

std::vector<double> profile_heights(const ProfileSpec& profile, const Grid& grid, double heading) {
  std::vector<double> h;
  TurnedProfile(profile, grid).heights(heading, h);
  return h;
}

TurnedProfile::TurnedProfile(const ProfileSpec& profile, const Grid& grid)
    : profile_(profile),
      grid_(grid),
      table_(profile.type == ProfileType::table ? std::make_unique<TableLattice>(profile) : nullptr) {}

TurnedProfile::~TurnedProfile() = default;

void TurnedProfile::heights(double heading, std::vector<double>& h) const {
  const ProfileSpec& profile = profile_;
  const Grid& grid = grid_;
  h.assign(grid.size(), 0.0);
  const bool two_d = grid.dimension == 2;
  // The body's own axes, turned by `heading` about z: (x_b, y_b) = Rz(-heading) (x, y).
  const double c = two_d ? 1.0 : std::cos(heading), s = two_d ? 0.0 : std::sin(heading);
  if (table_) {
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        h[grid.index(i, j)] = table_->at(c * grid.xc(i) + s * grid.yc(j), -s * grid.xc(i) + c * grid.yc(j));
    return;
  }
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const double x = c * grid.xc(i) + s * grid.yc(j), y = -s * grid.xc(i) + c * grid.yc(j);
      double value = 0.0;
      switch (profile.type) {
        case ProfileType::sphere:
          value = (x * x + y * y) / (2.0 * profile.radius);
          break;
        case ProfileType::ellipsoid:
          value = x * x / (2.0 * profile.radius_x) + y * y / (2.0 * profile.radius_y);
          break;
        case ProfileType::cylinder:
          value = x * x / (2.0 * profile.radius);
          if (!two_d && profile.length > 0.0 && std::abs(y) > 0.5 * profile.length) value = kInfinity;
          break;
        case ProfileType::flat_punch:
          value = (x * x + y * y < profile.radius * profile.radius &&
                   x * x + y * y >= profile.inner_radius * profile.inner_radius)
                      ? 0.0
                      : kInfinity;
          break;
        case ProfileType::quadratic:
          value = profile.a * x * x + profile.b * y * y;
          break;
        case ProfileType::table:
          break;
      }
      h[grid.index(i, j)] = value;
    }
  }
}

const char* to_string(ProfileType type) {
  switch (type) {
    case ProfileType::sphere: return "sphere";
    case ProfileType::ellipsoid: return "ellipsoid";
    case ProfileType::cylinder: return "cylinder";
    case ProfileType::flat_punch: return "flat_punch";
    case ProfileType::quadratic: return "quadratic";
    case ProfileType::table: return "table";
  }
  return "unknown";
}

}  // namespace dc
