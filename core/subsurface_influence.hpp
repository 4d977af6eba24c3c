#pragma once
// The linear elastic field INSIDE a homogeneous isotropic half-space (shear modulus G, Poisson
// nu) due to a uniform surface traction on one grid element: displacements and the six stresses
// in closed form, exact for the piecewise-constant tractions of the grid.
//
// Half-space frame (Johnson, Contact Mechanics, 3.2): the solid fills depth d >= 0, the load
// acts on its surface d = 0: pressure p (> 0 pushes into the solid) and shears q_x, q_y (the
// force per area on the solid's surface along +x, +y). Stresses tension positive, u_d positive
// into the solid; on the loaded surface sigma_dd = -p, sigma_xd = -q_x, sigma_yd = -q_y.
//
// 3-D (rectangle dx x dy centred at the origin): Boussinesq-Cerruti potentials ([J] 3.7, 3.10)
// with Omega = d ln(rho + d) - rho over the rectangle, Phi = integral of Omega. Pressure:
// chi = Phi_d, psi = chi_d,
//   4 pi G u_x = -(1-2nu) chi_x - d psi_x,   4 pi G u_d = 2(1-nu) psi - d psi_d,
//   2 pi sigma_xx = 2 nu psi_d - d psi_xx - (1-2nu) chi_xx,   2 pi sigma_dd = psi_d - d psi_dd,
//   2 pi sigma_xy = -(1-2nu) chi_xy - d psi_xy,   2 pi sigma_xd = -d psi_xd   (Love 1929);
// shear q_x: chi = Phi_d, psi = Phi_xd,
//   4 pi G u_x = 2 chi_d + 2 nu Phi_xx - d psi_x,   4 pi G u_y = 2 nu Phi_xy - d psi_y,
//   4 pi G u_d = (1-2nu) psi - d psi_d,   2 pi sigma_xx = 2(1+nu) psi_d + 2 nu Phi_xxx - d psi_xx,
//   2 pi sigma_yy = 2 nu psi_d + 2 nu Phi_xyy - d psi_yy,   2 pi sigma_dd = -d psi_dd,
//   2 pi sigma_xy = chi_yd + 2 nu Phi_xxy - d psi_xy,   2 pi sigma_xd = chi_dd - d psi_xd,
//   2 pi sigma_yd = -d psi_yd   (Cerruti);   q_y by exchanging x and y.
// Every derivative with i x- and j y-derivatives is a corner sum F(a1,b1) - F(a2,b1) - F(a1,b2)
// + F(a2,b2) (a = x - xi, b = y - eta at the element's corners) of d_a^(i-1) d_b^(j-1) of the
// d-derivatives of Omega (antiderivatives for i or j = 0), written free of cancellation.
// 2-D plane strain (strip of width dx, per unit length): Flamant's line loads integrated over the
// strip ([J] 2.6 and 2.15, 2.19; the theta_1, theta_2 forms): with s = x - xi,
//   normal:     pi sigma_xx = -[atan(s/d) - s d/r^2],   pi sigma_dd = -[atan(s/d) + s d/r^2],
//               pi sigma_xd = d^2/r^2;
//   tangential: pi sigma_xx = -[ln r^2 + d^2/r^2],  pi sigma_dd = d^2/r^2,
//               pi sigma_xd = -[atan(s/d) - s d/r^2],   sigma_yy = nu (sigma_xx + sigma_dd),
// each the difference between s = x + dx/2 and s = x - dx/2; the displacements are those of the
// line loads (u_d of the normal load -(1/(2 pi G)) [(1-nu) ln(r^2/L^2) - d^2/r^2]) integrated,
// their logarithms vanishing at distance L (`reference_length`) as in influence.hpp.
//
// At d = 0 the value is the limit d -> 0+ at fixed (x, y). Components that diverge there
// (logarithmically, only exactly on an element's edge line or corner at d = 0: the in-plane
// stresses under shear, sigma_xy under pressure at a corner) take the finite part: the
// diverging logarithm is dropped. Every value is finite.
//
// In the contact pair (docs/conventions.md): the body (+) lies above z = 0 and carries the
// traction t = (tau_x, tau_y, p) (p > 0 compressive); the base (-) below carries -t. For the
// body, depth d = z, and the field in the global frame is the half-space field with
// (q_x, q_y, p) = (tau_x, tau_y, p); for the base, d = -z, the half-space frame is the global
// one mirrored in z, and (q_x, q_y, p) = (-tau_x, -tau_y, p); mirrored back, u_z, sigma_xz and
// sigma_yz change sign. Both bodies are compressed by p > 0.
#include <array>

#include "influence.hpp"
#include "material.hpp"

namespace dc {

/// Which body of the contact pair a field is in: the body (+, above z = 0) or the base (-).
enum class BodySide : int { body, base };

/// The nine components of the elastic field at a point, in this order.
enum FieldComponent : int { kUx = 0, kUy, kUz, kSxx, kSyy, kSzz, kSxy, kSxz, kSyz };
inline constexpr int kFieldComponents = 9;
using FieldValues = std::array<double, kFieldComponents>;

/// Half-space frame: the fields per unit pressure and per unit shears (q_x, q_y) on one element,
/// at (x, y, depth) relative to its centre; kUz is u_d, kSzz sigma_dd, kSxz sigma_xd.
struct UnitFields {
  FieldValues pressure{}, shear_x{}, shear_y{};
};

/// Rectangle dx x dy centred at the origin (3-D).
UnitFields rectangle_unit_fields(const Elastic& material, double dx, double dy, double x, double y,
                                 double depth);
/// Strip of width dx centred at x = 0 (2-D plane strain, per unit length): shear_y, kUy, kSxy and
/// kSyz are zero. `reference_length` > 0: where the logarithmic displacements vanish.
UnitFields strip_unit_fields(const Elastic& material, double dx, double x, double depth,
                             double reference_length);

/// The field in one body of the contact pair due to the traction t = (tau_x, tau_y, p) on the
/// body (the base carries -t) on an element dx x dy centred at the origin, at (x, y) and `depth`
/// >= 0 into that body, in the global frame (z up), with that body's own material.
FieldValues rectangle_field(const Elastic& material, BodySide side, double dx, double dy, double tau_x,
                            double tau_y, double p, double x, double y, double depth);
/// The same for a 2-D strip (tau_y ignored).
FieldValues strip_field(const Elastic& material, BodySide side, double dx, double tau_x, double p, double x,
                        double depth, double reference_length);

/// The sign a component takes when the half-space frame is mirrored to the global one (base):
/// -1 for u_z, sigma_xz, sigma_yz.
inline double global_sign(BodySide side, int component) {
  return side == BodySide::base && (component == kUz || component == kSxz || component == kSyz) ? -1.0 : 1.0;
}

/// Influence coefficients of one grid, material and body at one depth at a time: the field at
/// element (i, j)'s centre due to a unit traction component on element (i - di, j - dj), as
/// KernelTables of influence.hpp (the global frame, the body's traction convention). The corner
/// functions are evaluated once per depth for all 27 (2-D: 12) tables, on one quadrant of the
/// offsets (each table is even or odd in di and in dj). Buffers are made by the constructor.
class SubsurfaceCoefficients {
 public:
  SubsurfaceCoefficients(const Grid& grid, const Elastic& material, BodySide side,
                         const InfluenceOptions& options = {});
  /// Evaluates the corner functions at `depth` >= 0 (allocates nothing).
  void set_depth(double depth);
  double depth() const { return depth_; }
  /// `table` (sized for the grid: (2nx-1) x (2ny-1)) = component `component` due to unit traction
  /// `load` (kX: tau_x, kY: tau_y, kZ: p) at the current depth. 2-D: loads kX and kZ;
  /// components kUy, kSxy, kSyz are zero.
  void fill(int component, Axis load, KernelTable& table) const;
  /// The quadrant di, dj >= 0 of the same table: out[di + stride * dj], di < nx, dj < ny.
  void fill_quadrant(int component, Axis load, double* out, int stride) const;
  /// The table's parity in di (x) and dj (y): +1 even, -1 odd (an odd number of x indices among
  /// the component's and the load's: u_x, sigma_xy, sigma_xz and tau_x are odd in x).
  static int parity_x(int component, Axis load);
  static int parity_y(int component, Axis load);
  const Grid& grid() const { return grid_; }
  /// A square 3-D grid of square elements (nx = ny, dx = dy): the tables of a pair exchanged by
  /// the reflection x <-> y are each other's transposes (mirror()), and set_depth evaluates
  /// half the corners.
  bool square_corners() const;
  /// The table the reflection x <-> y maps (component, load) to: u_x <-> u_y, sigma_xx <->
  /// sigma_yy, sigma_xz <-> sigma_yz, tau_x <-> tau_y; on a square grid K_mirror(di, dj) =
  /// K(dj, di).
  static void mirror(int component, Axis load, int& mirror_component, Axis& mirror_load);

 private:
  Grid grid_;
  Elastic material_;
  BodySide side_;
  double reference_length_;
  double depth_ = -1.0;
  int cx_, cy_;                  ///< corners per row, rows (one quadrant: nx + 1, ny + 1)
  std::vector<double> corners_;  ///< corner functions, function-major: [f * cx * cy + k + cx * l]
};

}  // namespace dc
