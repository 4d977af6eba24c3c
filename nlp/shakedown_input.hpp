#pragma once
// What the shakedown analysis of a moving load takes (nlp/shakedown_problem.hpp): the elastic
// stress history of the unit load, sampled at depths and positions, and the model of the
// admissible residual stress.
//
// The load moves along x over the half-space z > 0 (z into the solid) and is translation-
// invariant: a material point at depth z sees sigma^e(x - V t, z) as the load passes, so the
// positions x_i are the instants of one passage, the same at every depth z_j.
//
// Residual stresses of such a load in the steady state depend on z only: equilibrium
// (d rho_xz/dz = d rho_yz/dz = d rho_zz/dz = 0) and the free surface (rho_iz = 0 at z = 0) leave
// rho_zz = rho_xz = rho_yz = 0 and rho_xx(z), rho_yy(z), rho_xy(z) free (K. L. Johnson, Contact
// Mechanics, Cambridge 1985, chapter 9; for the 2-D line contact rho_xx and rho_yy, rho_xy
// being zero by symmetry). This is the line contact's set, and the depth-only subset of the 3-D
// model, whose residual depends on (y, z) (nlp/shakedown_3d.hpp).
#include <string>
#include <vector>

#include "voigt_stress.hpp"

namespace dc {

/// The elastic stress of the load at unit load factor, sampled on depths x positions.
struct StressHistory {
  std::vector<double> depths;     ///< z_j (into the solid; labels only: the program never uses them)
  std::vector<double> positions;  ///< x_i along the rolling direction (labels only)
  /// sigma^e(x_i, z_j) at index j * positions.size() + i (Voigt, voigt_stress.hpp).
  std::vector<Voigt> stress;

  int n_depths() const { return static_cast<int>(depths.size()); }
  int n_positions() const { return static_cast<int>(positions.size()); }
  const Voigt& at(int depth, int position) const {
    return stress[static_cast<std::size_t>(depth) * positions.size() + static_cast<std::size_t>(position)];
  }
  /// "" when valid (at least one depth and one position, stress sized depths x positions, every
  /// value finite), else "<field>: <reason>".
  std::string validate() const;
};

/// The free components of the residual stress, each a function of depth only.
struct ResidualModel {
  /// Default: the line contact's rho_xx and rho_yy. Only xx, yy and xy are self-equilibrated
  /// (header comment); each at most once; may be empty (no residual stress: first yield).
  std::vector<VoigtComponent> free = {VoigtComponent::xx, VoigtComponent::yy};

  static ResidualModel line_contact() { return {}; }
  static ResidualModel none() { return ResidualModel{{}}; }

  /// "" when valid, else "free: <reason>".
  std::string validate() const;
};

}  // namespace dc
