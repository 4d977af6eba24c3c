#pragma once
// Melan's shakedown program (nlp/shakedown_problem.hpp) for a 3-D load moving along x over the
// half-space z > 0: the elastic stress is sampled at depths z_k, lines y_j and positions x_i, and
// the residual stress, time-independent in the frame of the moving load, depends on (y, z) only.
//
// Admissible residual stresses rho(y, z). With no x-derivative, equilibrium and the free surface are
//   d rho_xy/dy + d rho_xz/dz = 0,  d rho_yy/dy + d rho_yz/dz = 0,  d rho_yz/dy + d rho_zz/dz = 0,
//   rho_xz = rho_yz = rho_zz = 0 on z = 0,                                                   (3)
// rho_xx(y, z) entering neither: it is free. The two plane systems are solved exactly by stress
// functions (the Airy function of the y-z plane, and the Prandtl-type function of the anti-plane
// pair; S. P. Timoshenko, J. N. Goodier, Theory of Elasticity, 3rd ed., McGraw-Hill 1970,
// sections 17 and 101):
//   rho_yy = phi_zz,  rho_zz = phi_yy,  rho_yz = -phi_yz,     rho_xy = psi_z,  rho_xz = -psi_y,   (4)
// which satisfy (3) identically for any phi in H^2 and psi in H^1 (in the distributional sense: a
// C^1 phi and a C^0 psi that are piecewise smooth), and the free surface when
// phi = phi_z = 0 and psi = 0 on z = 0.
//
// The residual set used here (ResidualModel3d::vary_across, the default) is
//   rho = rho^d(z) + rho^s(y, z) + rho_xx(y, z) e_xx:
//  - rho^d: the depth-only model of the line contact (rho_yy(z), rho_xy(z) one value per sampled
//    depth, any function of z: (3) holds, the surface condition too), everywhere in the half-space;
//  - rho^s from (4) with phi and psi tensor-product clamped cubic B-splines (core/cubic_bspline.hpp)
//    on the box B = [y_-1, y_J] x [0, z_K]: breakpoints at the sampled lines and depths, the box
//    reaching one line spacing beyond the outer lines and one depth step below the deepest depth
//    (0 added when the first depth is below the surface). Only the B-splines with phi = grad phi
//    = 0 and psi = 0 on the whole boundary of B are kept (the first and last two in each direction
//    for phi, the first and last one for psi: cubic_bspline.hpp), so rho^s and the tractions it
//    puts on the boundary of B vanish and rho^s extended by zero outside B is self-equilibrated in
//    the whole half-space and traction-free on z = 0: exact, not a finite-difference
//    approximation (phi is C^2, psi C^2, rho^s continuous).
//  - rho_xx: one free value per station (y_j, z_k), any interpolation between them.
// Every member of this set is an admissible residual stress field of the half-space, so the
// program's limit is Melan's lower bound of the sampled history (the yield conditions, as in 2-D,
// are imposed at the samples only: the limit approaches the continuum's from above as the
// sampling refines, and from below as the residual set grows). With vary_across = false the set
// is the depth-only model rho_xx(z), rho_yy(z), rho_xy(z) (shakedown_input.hpp), exactly the 2-D
// program's set applied to the samples of every line at once.
//
// The program is (1') of nlp/shakedown_stations.hpp with a station per (y_j, z_k) (per depth when
// vary_across is false), and its certificate (2) with the coupled inner least squares derived
// there. Yield: von Mises, or Tresca through its inscribed cone (YieldKind::tresca_inscribed):
// the limit reported is the cone's, a safe value for Tresca; the elastic limit is Tresca's own
// (principal stresses), and limit_upper_bound = (2/sqrt 3) times the cone's dual bound bounds
// Tresca's limit from above. tresca_plane_xz ignores the out-of-plane shears and is rejected.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cubic_bspline.hpp"
#include "shakedown_options.hpp"
#include "shakedown_result.hpp"
#include "voigt_stress.hpp"
#include "yield_criterion.hpp"

namespace dc {

/// The elastic stress of the load at unit load factor, sampled on depths x lines x positions.
struct StressHistory3d {
  std::vector<double> depths;     ///< z_k >= 0, strictly increasing (the stress functions' breakpoints)
  std::vector<double> lines;      ///< y_j, strictly increasing
  std::vector<double> positions;  ///< x_i along the rolling direction (labels only)
  /// sigma^e(x_i, y_j, z_k) at (k * lines.size() + j) * positions.size() + i (Voigt).
  std::vector<Voigt> stress;

  int n_depths() const { return static_cast<int>(depths.size()); }
  int n_lines() const { return static_cast<int>(lines.size()); }
  int n_positions() const { return static_cast<int>(positions.size()); }
  const Voigt& at(int depth, int line, int position) const {
    return stress[(static_cast<std::size_t>(depth) * lines.size() + static_cast<std::size_t>(line)) * positions.size() +
                  static_cast<std::size_t>(position)];
  }
  /// "" when valid, else "<field>: <reason>".
  std::string validate() const;
};

struct ResidualModel3d {
  /// Default true: the residual varies across y (rho_xx(y, z) and the stress functions of the
  /// header); false: the depth-only model rho_xx(z), rho_yy(z), rho_xy(z).
  bool vary_across = true;
};

/// The residual's discretisation (header): the unknowns theta (the residual over k, each
/// scaled so that its largest stress at a station is 1) and, per node (depth k, line j), the
/// residual stress of each unknown acting there, rho(y_j, z_k) / k = A_kj theta[I_kj].
class ResidualBasis3d {
 public:
  /// Throws std::invalid_argument for depths or lines that are empty, negative or not increasing.
  ResidualBasis3d(const std::vector<double>& depths, const std::vector<double>& lines, const ResidualModel3d& model);

  int unknowns() const { return unknowns_; }
  int n_depths() const { return depths_; }
  int n_lines() const { return lines_; }
  /// The unknowns acting at node (k, j), ascending, and their stresses (6 x |I|, Voigt rows).
  const std::vector<int>& index(int k, int j) const { return index_[node(k, j)]; }
  const Eigen::Matrix<double, 6, Eigen::Dynamic>& columns(int k, int j) const { return columns_[node(k, j)]; }
  /// rho / k at node (k, j) for the unknowns theta.
  Voigt at_node(const std::vector<double>& theta, int k, int j) const;
  /// The stress-function part rho^s / k (header) at any (y, z): zero outside the box.
  Voigt stress_function_part(const std::vector<double>& theta, double y, double z) const;
  /// The number of stress-function unknowns (phi's and psi's B-spline coefficients).
  int stress_function_unknowns() const { return phi_count_ + psi_count_; }

 private:
  std::size_t node(int k, int j) const { return static_cast<std::size_t>(k) * static_cast<std::size_t>(lines_) + static_cast<std::size_t>(j); }
  /// Unscaled stresses of the stress-function unknowns at (y, z), appended to (ids, cols).
  void stress_function_columns(double y, double z, std::vector<int>& ids, std::vector<Voigt>& cols) const;

  int depths_ = 0, lines_ = 0, unknowns_ = 0;
  bool splines_ = false;
  std::vector<CubicBSplineBasis> y_basis_, z_basis_;  ///< one each when splines_
  int phi_first_ = 0, phi_count_ = 0, phi_nb_ = 0;     ///< phi's ids: phi_first_ + (a - 2) * phi_nb_ + (b - 2)
  int psi_first_ = 0, psi_count_ = 0, psi_nb_ = 0;     ///< psi's ids: psi_first_ + (a - 1) * psi_nb_ + (b - 1)
  std::vector<double> scale_;                          ///< per unknown: its stress is scale_ * the B-spline's
  std::vector<std::vector<int>> index_;
  std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic>> columns_;
};

/// The shakedown analysis of `history` under `criterion` (von_mises or tresca_inscribed) with the
/// residual set of `model`. Throws std::invalid_argument for invalid input; solver trouble is
/// reported in the result's status. residual: one per node, k * lines + j.
ShakedownResult solve_shakedown_3d(const StressHistory3d& history, const YieldCriterion& criterion,
                                   const ResidualModel3d& model = {}, const ShakedownOptions& options = {});

}  // namespace dc
