#pragma once
// Boussinesq-Cerruti influence coefficients of a uniform traction on one grid element,
// for the relative surface displacement w = u+ - u- of body (+, above) and substrate (-).
//
// Conventions (docs/conventions.md): traction on the body t = (tau_x, tau_y, p), p > 0
// compressive; the substrate carries -t. w_z > 0 opens the gap ((2.6)); w_x, w_y are the
// tangential relative displacements of (4.2). The work t.w is the elastic energy, so the
// full 3x3-block operator is symmetric positive semi-definite (Betti).
//   zz: B31 with 1/(pi E*) (Love);   xx, xy, yy: B22 with sum (1-nu)/G and sum nu/G (Cerruti);
//   xz (w_x due to p) and zx (w_z due to tau_x): the cross terms carrying the paper's kappa (4.3).
// 2-D plane strain: strips of width dx, per unit length; the logarithmic kernels are fixed
// to vanish at distance `reference_length` (default: the grid length nx*dx).
#include <vector>

#include "grid.hpp"
#include "material.hpp"

namespace dc {

enum Axis : int { kX = 0, kY = 1, kZ = 2 };

/// Influence values of one (out, in) component pair for every element offset.
/// at(di, dj) = w_out at element (i, j) due to unit uniform traction t_in on element
/// (i - di, j - dj); di in [-(nx-1), nx-1], dj in [-(ny-1), ny-1].
struct KernelTable {
  int nx = 0, ny = 0;
  std::vector<double> values;  ///< (2nx-1) * (2ny-1), di fastest

  double at(int di, int dj) const {
    return values[static_cast<std::size_t>(di + nx - 1) +
                  static_cast<std::size_t>(2 * nx - 1) * static_cast<std::size_t>(dj + ny - 1)];
  }
  double& at(int di, int dj) {
    return values[static_cast<std::size_t>(di + nx - 1) +
                  static_cast<std::size_t>(2 * nx - 1) * static_cast<std::size_t>(dj + ny - 1)];
  }
};

struct InfluenceOptions {
  double reference_length = 0.0;  ///< 2-D only; <= 0 means nx * dx
};

/// Table for w_out due to t_in (out, in in {kX, kY, kZ}); 2-D accepts kX and kZ only.
KernelTable influence_table(const Grid& grid, const MaterialPair& materials, Axis out, Axis in,
                            const InfluenceOptions& options = {});

/// Point-load (3-D) / line-load (2-D) far-field kernel of the same pair at offset (x, y):
/// what influence_table approaches per unit force far from the element. For tests.
double point_load_kernel(int dimension, const MaterialPair& materials, Axis out, Axis in, double x,
                         double y, double reference_length);

}  // namespace dc
