#pragma once
// The shakedown program's data in the yield function's own space (core/yield_criterion.hpp:
// f(sigma) = |L sigma|): per sample u_ij = L sigma^e(x_i, z_j), and the residual's columns
// W = k L B (B the free components, k the shear yield: the residual unknowns are rho / k, of
// order 1). The yield condition of sample (i, j) at load factor lambda and residual rho_j reads
//   |lambda u_ij + W rho_j / k| <= 1.
// Shared by the Ipopt program (shakedown_problem.cpp) and the per-depth cross-check
// (shakedown_by_depth.cpp).
#include <vector>

#include <Eigen/Core>

#include "shakedown_input.hpp"
#include "yield_criterion.hpp"

namespace dc {

struct ShakedownSamples {
  int depths = 0, positions = 0;
  Eigen::MatrixXd u;  ///< q x (depths * positions): column j * positions + i is L sigma^e(x_i, z_j)
  Eigen::MatrixXd w;  ///< q x p: k L e_c for the kept residual components c
  /// The kept residual components: the free ones that enter the yield function, an independent
  /// subset (a component whose column W is zero or a combination of earlier ones adds nothing:
  /// e.g. rho_yy under Tresca in the x-z plane). The others are reported as zero.
  std::vector<VoigtComponent> components;
  double residual_scale = 1.0;  ///< k: rho = k * (the program's unknown)

  int p() const { return static_cast<int>(components.size()); }
  Eigen::Ref<const Eigen::VectorXd> sample(int depth, int position) const {
    return u.col(static_cast<Eigen::Index>(depth) * positions + position);
  }
  /// The residual stress (Voigt) of the program's unknowns y (size p): rho = k sum_c y_c e_c.
  Voigt residual(const double* y) const;
};

/// 1 / max_k criterion.exact_ratio(stress[k]) (+inf when no sample is stressed), `worst` its k: the
/// elastic limit of the criterion itself where the program's cone is an inner approximation
/// (tresca_inscribed: Tresca's own first yield, from the principal stresses).
double exact_elastic_limit(const std::vector<Voigt>& stress, const YieldCriterion& criterion, std::size_t& worst);

/// Throws std::invalid_argument when the history, the criterion or the model is invalid.
ShakedownSamples shakedown_samples(const StressHistory& history, const YieldCriterion& criterion,
                                   const ResidualModel& model);

}  // namespace dc
