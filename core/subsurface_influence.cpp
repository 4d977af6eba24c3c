#include "subsurface_influence.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dc {
namespace {
constexpr double kSubsurfacePi = std::numbers::pi;

// ---- 3-D corner functions F_ijk(a, b, d) = d_a^(i-1) d_b^(j-1) d_d^k Omega (antiderivatives for
// i, j = 0; terms of a alone or b alone dropped: they cancel in the corner sum). A leading z
// marks the product d * F where F itself diverges at d = 0 and the product has a limit.
enum CornerFn : int {
  f002, f003, f110, f111, zf112, f101, f011, f102, f012, zf103, zf013, f200, f020,
  f201, f021, f202, f022, f300, f030, zf301, zf031, f210, f120, f211, f121, kCornerFns
};

/// The corner function with the roles of a and b exchanged: F_f(b, a, d) = F_swap(f)(a, b, d),
/// exactly in floating point (rectangle_corner evaluates each pair by mirrored expressions).
constexpr int kCornerSwap[kCornerFns] = {f002,  f003,  f110,  f111,  zf112, f011,  f101, f012, f102,
                                         zf013, zf103, f020,  f200,  f021,  f201,  f022, f202, f030,
                                         f300,  zf031, zf301, f120,  f210,  f121,  f211};

/// x + r for r = sqrt(x^2 + rest), rest >= 0, without cancellation for x < 0.
double sum_with_radius(double x, double r, double rest) { return x >= 0.0 ? x + r : rest / (r - x); }

/// T = atan(b/a) - atan(b d/(a rho)) (the d-derivative's antiderivative of F_201), bounded by
/// pi/2; 0 on the lines a = 0 and b = 0 (for d > 0 exactly; at d = 0 the mean of both sides).
double corner_angle(double a, double b, double d, double rho) {
  if (a == 0.0 || b == 0.0) return 0.0;
  const double a2 = a * a, b2 = b * b;
  return std::atan(a * b * (a2 + b2) / ((rho + d) * (a2 * rho + b2 * d)));
}

/// d * dT/da = d b (rho d - a^2) / (rho (rho + d)(a^2 + d^2)); its limit d -> 0+ at a = 0 is sign(b).
double depth_times_angle_slope(double a, double b, double d, double rho) {
  if (d == 0.0) return a != 0.0 ? 0.0 : (b > 0.0 ? 1.0 : (b < 0.0 ? -1.0 : 0.0));
  return d * b * (rho * d - a * a) / (rho * (rho + d) * (a * a + d * d));
}

/// d^2 / (rho (b + rho)) (d * F_103), with its limits at d = 0 on the line a = 0.
double depth_times_f103(double a, double b, double d, double rho, double b_plus_rho) {
  if (d == 0.0) return a != 0.0 ? 0.0 : (b > 0.0 ? 0.0 : (b < 0.0 ? 2.0 : 1.0));
  return d * d / (rho * b_plus_rho);
}

/// A coordinate whose square underflows is taken as 0 (its limit: it is below any length of the
/// problem by more than 1e150).
double flush_tiny(double x) { return x * x == 0.0 ? 0.0 : x; }

void rectangle_corner(double a, double b, double d, double* v) {
  a = flush_tiny(a), b = flush_tiny(b), d = flush_tiny(d);
  const double a2 = a * a, b2 = b * b, d2 = d * d;
  const double rho = std::sqrt(a2 + b2 + d2);
  const double bpr = sum_with_radius(b, rho, a2 + d2), apr = sum_with_radius(a, rho, b2 + d2), rpd = rho + d;
  // The finite part where a logarithm diverges (d = 0 on an edge line or at a corner).
  const double lbr = bpr > 0.0 ? std::log(bpr) : 0.0, lar = apr > 0.0 ? std::log(apr) : 0.0;
  const double lrd = rpd > 0.0 ? std::log(rpd) : 0.0;
  const double atn = std::atan2(a * b, d * rho);  // atan(ab / (d rho)); +-pi/2 or 0 at d = 0
  const double ta = corner_angle(a, b, d, rho), tb = corner_angle(b, a, d, rho);
  const double zdta = depth_times_angle_slope(a, b, d, rho), zdtb = depth_times_angle_slope(b, a, d, rho);
  v[f002] = a * lbr + b * lar - d * atn;
  v[f003] = -atn;
  v[f110] = d * lrd - rho;
  v[f111] = lrd;
  v[zf112] = d > 0.0 ? d / rho : (rho == 0.0 ? 1.0 : 0.0);
  v[f101] = b * lrd + d * lbr + a * ta;
  v[f011] = a * lrd + d * lar + b * tb;
  v[f102] = lbr;
  v[f012] = lar;
  v[zf103] = depth_times_f103(a, b, d, rho, bpr);
  v[zf013] = depth_times_f103(b, a, d, rho, apr);
  v[f200] = -a * lbr + d * ta;
  v[f020] = -b * lar + d * tb;
  v[f201] = ta;
  v[f021] = tb;
  v[f202] = (a == 0.0 || bpr == 0.0) ? 0.0 : a / (rho * bpr);
  v[f022] = (b == 0.0 || apr == 0.0) ? 0.0 : b / (rho * apr);
  v[f300] = -lbr - ((a == 0.0 || bpr == 0.0) ? 0.0 : a2 / (rho * bpr)) + zdta;
  v[f030] = -lar - ((b == 0.0 || apr == 0.0) ? 0.0 : b2 / (rho * apr)) + zdtb;
  v[zf301] = zdta;
  v[zf031] = zdtb;
  v[f210] = rpd > 0.0 ? -a / rpd : 0.0;
  v[f120] = rpd > 0.0 ? -b / rpd : 0.0;
  v[f211] = rho > 0.0 ? a / (rho * rpd) : 0.0;
  v[f121] = rho > 0.0 ? b / (rho * rpd) : 0.0;
}

// ---- 2-D strip functions of s = x - xi: the antiderivatives along s of the line loads' fields.
enum StripFn : int { g_atn, g_q, g_w, g_lg, g_satn, g_slog, kStripFns };

void strip_corner(double s, double d, double L, double* v) {
  s = flush_tiny(s), d = flush_tiny(d);
  const double r2 = s * s + d * d;
  v[g_atn] = std::atan2(s, d);
  v[g_q] = r2 > 0.0 ? s * d / r2 : 0.0;
  v[g_w] = r2 > 0.0 ? d * d / r2 : 1.0;  // the limit d -> 0+ at s = 0
  v[g_lg] = r2 > 0.0 ? std::log(r2) : 0.0;
  v[g_satn] = s * v[g_atn];
  v[g_slog] = s == 0.0 ? 0.0 : s * std::log(r2 / (L * L)) - 2.0 * s;
}

struct CornerTerm {
  int fn;
  double coeff;
};
struct CornerRecipe {
  CornerTerm terms[3];
  int count = 0;
  void add(int fn, double coeff) { terms[count++] = CornerTerm{fn, coeff}; }
};

/// The half-space-frame component `c` due to unit load `load` as a combination of corner sums.
CornerRecipe recipe_3d(double G, double n, double d, int c, Axis load) {
  const double c1 = 1.0 / (4.0 * kSubsurfacePi * G), c2 = 1.0 / (2.0 * kSubsurfacePi);
  CornerRecipe r;
  if (load == kZ) {
    switch (c) {
      case kUx: r.add(f101, -(1 - 2 * n) * c1), r.add(f102, -d * c1); break;
      case kUy: r.add(f011, -(1 - 2 * n) * c1), r.add(f012, -d * c1); break;
      case kUz: r.add(f002, 2 * (1 - n) * c1), r.add(f003, -d * c1); break;
      case kSxx: r.add(f003, 2 * n * c2), r.add(f202, -d * c2), r.add(f201, -(1 - 2 * n) * c2); break;
      case kSyy: r.add(f003, 2 * n * c2), r.add(f022, -d * c2), r.add(f021, -(1 - 2 * n) * c2); break;
      case kSzz: r.add(f003, c2), r.add(f202, d * c2), r.add(f022, d * c2); break;
      case kSxy: r.add(f111, -(1 - 2 * n) * c2), r.add(zf112, -c2); break;
      case kSxz: r.add(zf103, -c2); break;
      case kSyz: r.add(zf013, -c2); break;
    }
  } else if (load == kX) {
    switch (c) {
      case kUx: r.add(f002, 2 * c1), r.add(f200, 2 * n * c1), r.add(f201, -d * c1); break;
      case kUy: r.add(f110, 2 * n * c1), r.add(f111, -d * c1); break;
      case kUz: r.add(f101, (1 - 2 * n) * c1), r.add(f102, -d * c1); break;
      case kSxx: r.add(f102, 2 * (1 + n) * c2), r.add(f300, 2 * n * c2), r.add(zf301, -c2); break;
      case kSyy: r.add(f102, 2 * n * c2), r.add(f120, 2 * n * c2), r.add(f121, -d * c2); break;
      case kSzz: r.add(zf103, -c2); break;
      case kSxy: r.add(f012, c2), r.add(f210, 2 * n * c2), r.add(f211, -d * c2); break;
      case kSxz: r.add(f003, c2), r.add(f202, -d * c2); break;
      case kSyz: r.add(zf112, -c2); break;
    }
  } else {  // q_y: q_x with x and y exchanged
    switch (c) {
      case kUx: r.add(f110, 2 * n * c1), r.add(f111, -d * c1); break;
      case kUy: r.add(f002, 2 * c1), r.add(f020, 2 * n * c1), r.add(f021, -d * c1); break;
      case kUz: r.add(f011, (1 - 2 * n) * c1), r.add(f012, -d * c1); break;
      case kSxx: r.add(f012, 2 * n * c2), r.add(f210, 2 * n * c2), r.add(f211, -d * c2); break;
      case kSyy: r.add(f012, 2 * (1 + n) * c2), r.add(f030, 2 * n * c2), r.add(zf031, -c2); break;
      case kSzz: r.add(zf013, -c2); break;
      case kSxy: r.add(f102, c2), r.add(f120, 2 * n * c2), r.add(f121, -d * c2); break;
      case kSxz: r.add(zf112, -c2); break;
      case kSyz: r.add(f003, c2), r.add(f022, -d * c2); break;
    }
  }
  return r;
}

CornerRecipe recipe_2d(double G, double n, double d, int c, Axis load) {
  const double k1 = 1.0 / (2.0 * kSubsurfacePi * G), k2 = 1.0 / kSubsurfacePi;
  CornerRecipe r;
  if (load == kZ) {
    switch (c) {
      case kUx: r.add(g_satn, -(1 - 2 * n) * k1), r.add(g_lg, (1 - n) * d * k1); break;
      case kUz: r.add(g_slog, -(1 - n) * k1), r.add(g_atn, -(1 - 2 * n) * d * k1); break;
      case kSxx: r.add(g_atn, -k2), r.add(g_q, k2); break;
      case kSyy: r.add(g_atn, -2 * n * k2); break;
      case kSzz: r.add(g_atn, -k2), r.add(g_q, -k2); break;
      case kSxz: r.add(g_w, k2); break;
      default: break;
    }
  } else if (load == kX) {
    switch (c) {
      case kUx: r.add(g_slog, -(1 - n) * k1), r.add(g_atn, -(3 - 2 * n) * d * k1); break;
      case kUz: r.add(g_satn, (1 - 2 * n) * k1), r.add(g_lg, n * d * k1); break;
      case kSxx: r.add(g_lg, -k2), r.add(g_w, -k2); break;
      case kSyy: r.add(g_lg, -n * k2); break;
      case kSzz: r.add(g_w, k2); break;
      case kSxz: r.add(g_atn, -k2), r.add(g_q, k2); break;
      default: break;
    }
  } else {
    throw std::invalid_argument("subsurface field: 2-D problems have tractions x and z only");
  }
  return r;
}

/// The factor of the body's traction component `load` in the half-space frame's load.
double load_sign(BodySide side, Axis load) { return side == BodySide::base && load != kZ ? -1.0 : 1.0; }

void check_material(const Elastic& m) {
  if (m.rigid || !(m.G > 0.0) || !(m.nu > -1.0 && m.nu < 0.5))
    throw std::invalid_argument("subsurface field: needs an elastic body (G > 0, -1 < nu < 0.5)");
}
void check_depth(double depth) {
  if (!(depth >= 0.0) || !std::isfinite(depth))
    throw std::invalid_argument("subsurface field: depth must be finite and >= 0");
}

FieldValues combine_unit_fields(BodySide side, double tau_x, double tau_y, double p, const UnitFields& u) {
  const double s = side == BodySide::base ? -1.0 : 1.0;
  FieldValues out{};
  for (int c = 0; c < kFieldComponents; ++c)
    out[c] = global_sign(side, c) * (s * tau_x * u.shear_x[c] + s * tau_y * u.shear_y[c] + p * u.pressure[c]);
  return out;
}
}  // namespace

UnitFields rectangle_unit_fields(const Elastic& m, double dx, double dy, double x, double y, double depth) {
  check_material(m);
  check_depth(depth);
  double v[4][kCornerFns];
  rectangle_corner(x + 0.5 * dx, y + 0.5 * dy, depth, v[0]);
  rectangle_corner(x - 0.5 * dx, y + 0.5 * dy, depth, v[1]);
  rectangle_corner(x + 0.5 * dx, y - 0.5 * dy, depth, v[2]);
  rectangle_corner(x - 0.5 * dx, y - 0.5 * dy, depth, v[3]);
  double sum[kCornerFns];
  for (int f = 0; f < kCornerFns; ++f) sum[f] = v[0][f] - v[1][f] - v[2][f] + v[3][f];
  UnitFields u;
  FieldValues* out[3] = {&u.shear_x, &u.shear_y, &u.pressure};
  for (Axis load : {kX, kY, kZ})
    for (int c = 0; c < kFieldComponents; ++c) {
      const CornerRecipe r = recipe_3d(m.G, m.nu, depth, c, load);
      double value = 0.0;
      for (int t = 0; t < r.count; ++t) value += r.terms[t].coeff * sum[r.terms[t].fn];
      (*out[load])[c] = value;
    }
  return u;
}

UnitFields strip_unit_fields(const Elastic& m, double dx, double x, double depth, double reference_length) {
  check_material(m);
  check_depth(depth);
  if (!(reference_length > 0.0)) throw std::invalid_argument("subsurface field: reference length must be > 0");
  double v[2][kStripFns];
  strip_corner(x + 0.5 * dx, depth, reference_length, v[0]);
  strip_corner(x - 0.5 * dx, depth, reference_length, v[1]);
  UnitFields u;
  FieldValues* out[3] = {&u.shear_x, nullptr, &u.pressure};
  for (Axis load : {kX, kZ})
    for (int c = 0; c < kFieldComponents; ++c) {
      const CornerRecipe r = recipe_2d(m.G, m.nu, depth, c, load);
      double value = 0.0;
      for (int t = 0; t < r.count; ++t) value += r.terms[t].coeff * (v[0][r.terms[t].fn] - v[1][r.terms[t].fn]);
      (*out[load])[c] = value;
    }
  return u;
}

FieldValues rectangle_field(const Elastic& m, BodySide side, double dx, double dy, double tau_x, double tau_y,
                            double p, double x, double y, double depth) {
  return combine_unit_fields(side, tau_x, tau_y, p, rectangle_unit_fields(m, dx, dy, x, y, depth));
}

FieldValues strip_field(const Elastic& m, BodySide side, double dx, double tau_x, double p, double x, double depth,
                        double reference_length) {
  return combine_unit_fields(side, tau_x, 0.0, p, strip_unit_fields(m, dx, x, depth, reference_length));
}

SubsurfaceCoefficients::SubsurfaceCoefficients(const Grid& grid, const Elastic& material, BodySide side,
                                               const InfluenceOptions& options)
    : grid_(grid), material_(material), side_(side),
      reference_length_(options.reference_length > 0.0 ? options.reference_length : grid.nx * grid.dx),
      cx_(grid.nx + 1), cy_(grid.dimension == 2 ? 1 : grid.ny + 1) {
  check_material(material);
  if (grid.nx < 1 || grid.ny < 1 || !(grid.dx > 0.0) || !(grid.dy > 0.0) ||
      (grid.dimension != 2 && grid.dimension != 3) || (grid.dimension == 2 && grid.ny != 1))
    throw std::invalid_argument("subsurface field: bad grid");
  const int functions = grid.dimension == 2 ? static_cast<int>(kStripFns) : static_cast<int>(kCornerFns);
  corners_.assign(static_cast<std::size_t>(functions) * cx_ * cy_, 0.0);
}

void SubsurfaceCoefficients::set_depth(double depth) {
  check_depth(depth);
  depth_ = depth;
  const std::size_t plane = static_cast<std::size_t>(cx_) * cy_;
  if (grid_.dimension == 2) {
    double v[kStripFns];
    for (int k = 0; k < cx_; ++k) {
      strip_corner((k - 0.5) * grid_.dx, depth, reference_length_, v);
      for (int f = 0; f < kStripFns; ++f) corners_[f * plane + k] = v[f];
    }
    return;
  }
  // Square elements on a square grid: the corner (l, k) is the corner (k, l) with a and b
  // exchanged (kCornerSwap), so only the corners k <= l are evaluated; the same values.
  const bool mirrored = square_corners();
  double v[kCornerFns];
  for (int l = 0; l < cy_; ++l)
    for (int k = 0; k < (mirrored ? l + 1 : cx_); ++k) {
      rectangle_corner((k - 0.5) * grid_.dx, (l - 0.5) * grid_.dy, depth, v);
      const std::size_t at = k + static_cast<std::size_t>(cx_) * l;
      for (int f = 0; f < kCornerFns; ++f) corners_[f * plane + at] = v[f];
    }
  if (!mirrored) return;
  // The other half, plane by plane in 32 x 32 blocks (a transpose: stored one at a time into 25
  // planes it missed the cache at every store): F_swap(f)(l, k) = F_f(k, l) for k < l.
  constexpr int kBlock = 32;
  const std::size_t cx = static_cast<std::size_t>(cx_);
  for (int f = 0; f < kCornerFns; ++f) {
    const double* from = corners_.data() + f * plane;
    double* to = corners_.data() + kCornerSwap[f] * plane;
    for (int l0 = 0; l0 < cy_; l0 += kBlock)
      for (int k0 = 0; k0 <= l0; k0 += kBlock)
        for (int l = l0; l < std::min(l0 + kBlock, cy_); ++l)
          for (int k = k0; k < std::min({k0 + kBlock, l, cx_}); ++k) to[l + cx * k] = from[k + cx * l];
  }
}

bool SubsurfaceCoefficients::square_corners() const {
  return grid_.dimension == 3 && grid_.nx == grid_.ny && grid_.dx == grid_.dy;
}

void SubsurfaceCoefficients::mirror(int c, Axis load, int& mc, Axis& ml) {
  static constexpr int kSwap[kFieldComponents] = {kUy, kUx, kUz, kSyy, kSxx, kSzz, kSxy, kSyz, kSxz};
  mc = kSwap[c];
  ml = load == kX ? kY : (load == kY ? kX : kZ);
}

int SubsurfaceCoefficients::parity_x(int c, Axis load) {
  const bool odd_c = c == kUx || c == kSxy || c == kSxz;
  return (odd_c != (load == kX)) ? -1 : 1;
}
int SubsurfaceCoefficients::parity_y(int c, Axis load) {
  const bool odd_c = c == kUy || c == kSxy || c == kSyz;
  return (odd_c != (load == kY)) ? -1 : 1;
}

void SubsurfaceCoefficients::fill_quadrant(int c, Axis load, double* out, int stride) const {
  if (depth_ < 0.0) throw std::logic_error("subsurface coefficients: set_depth first");
  const int nx = grid_.nx, ny = grid_.ny;
  const bool two_d = grid_.dimension == 2;
  const CornerRecipe r = two_d ? recipe_2d(material_.G, material_.nu, depth_, c, load)
                               : recipe_3d(material_.G, material_.nu, depth_, c, load);
  const double sign = global_sign(side_, c) * load_sign(side_, load);
  const std::size_t plane = static_cast<std::size_t>(cx_) * cy_;
  for (int dj = 0; dj < ny; ++dj) {
    double* row = out + static_cast<std::size_t>(stride) * dj;
    for (int di = 0; di < nx; ++di) row[di] = 0.0;
    for (int t = 0; t < r.count; ++t) {
      const double* F = corners_.data() + r.terms[t].fn * plane;
      const double w = sign * r.terms[t].coeff;
      if (two_d) {
        for (int di = 0; di < nx; ++di) row[di] += w * (F[di + 1] - F[di]);
      } else {
        const double* top = F + static_cast<std::size_t>(cx_) * (dj + 1);
        const double* bottom = F + static_cast<std::size_t>(cx_) * dj;
        for (int di = 0; di < nx; ++di) row[di] += w * (top[di + 1] - top[di] - bottom[di + 1] + bottom[di]);
      }
    }
  }
}

void SubsurfaceCoefficients::fill(int c, Axis load, KernelTable& table) const {
  const int nx = grid_.nx, ny = grid_.ny;
  table.nx = nx;
  table.ny = ny;
  table.values.resize(static_cast<std::size_t>(2 * nx - 1) * static_cast<std::size_t>(2 * ny - 1));
  // The quadrant straight into its place (offsets di, dj >= 0), then mirrored by parity.
  fill_quadrant(c, load, &table.at(0, 0), 2 * nx - 1);
  const double px = parity_x(c, load), py = parity_y(c, load);
  for (int dj = 0; dj < ny; ++dj)
    for (int di = 0; di < nx; ++di) {
      const double value = table.at(di, dj);
      if (di > 0) table.at(-di, dj) = px * value;
      if (dj > 0) table.at(di, -dj) = py * value;
      if (di > 0 && dj > 0) table.at(-di, -dj) = px * py * value;
    }
}

}  // namespace dc
