#pragma once
// Yield criteria whose yield function is a norm of a linear image of the stress:
//   f(sigma) = |L sigma| <= 1,  L a q x 6 matrix (Voigt order, voigt_stress.hpp),
// so that the elastic domain is a convex quadratic (second-order cone) set, as the shakedown
// program (nlp/shakedown_problem.hpp) needs.
//
//  - von Mises, uniaxial yield stress Y:  J2 <= Y^2 / 3 = k^2 (k = Y / sqrt 3, the shear yield),
//    L = D / k with D the deviatoric coordinate map (voigt_stress.hpp, |D sigma| = sqrt(J2)); q = 5.
//  - Tresca in the x-z plane, shear yield k (plane strain line contact; K. L. Johnson, Contact
//    Mechanics, Cambridge 1985, chapter 9: the in-plane principal shear
//      ((sigma_xx - sigma_zz) / 2)^2 + sigma_xz^2 <= k^2);
//    L = [ (e_xx - e_zz) / 2 ; e_xz ] / k; q = 2. Only the in-plane shear counts: sigma_yy is
//    taken to be the intermediate principal stress, which this criterion does not check (the
//    classical line-contact analyses make the same assumption).
//
// f(sigma) = 1 on the yield surface; f is positively homogeneous of degree 1 (a load factor
// scales it).
#include <string>

#include <Eigen/Core>

#include "voigt_stress.hpp"

namespace dc {

enum class YieldKind {
  von_mises,        ///< "von_mises": J2 <= Y^2 / 3
  tresca_plane_xz,  ///< "tresca_plane_xz": ((s_xx - s_zz)/2)^2 + s_xz^2 <= k^2
};

const char* to_string(YieldKind kind);

struct YieldCriterion {
  YieldKind kind = YieldKind::von_mises;
  /// von Mises: the uniaxial yield stress Y; Tresca: the shear yield stress k. Pa (or any unit:
  /// the stresses' own). Must be positive and finite.
  double strength = 1.0;

  static YieldCriterion von_mises(double yield_stress) { return {YieldKind::von_mises, yield_stress}; }
  static YieldCriterion tresca_plane_xz(double shear_yield) { return {YieldKind::tresca_plane_xz, shear_yield}; }

  /// The shear yield stress k: Y / sqrt 3 (von Mises) or `strength` (Tresca).
  double shear_yield() const;
  /// The rows of L (q = 5 von Mises, 2 Tresca).
  int rows() const { return kind == YieldKind::von_mises ? 5 : 2; }
  /// L (rows() x 6): f(sigma) = |L sigma|.
  Eigen::MatrixXd factor() const;
  /// f(sigma): 1 on the yield surface, < 1 inside.
  double ratio(const Voigt& sigma) const;

  /// "" when valid, else "<field>: <reason>".
  std::string validate() const;
};

}  // namespace dc
