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
//  - Tresca in 3-D, shear yield k: (sigma_1 - sigma_3) / 2 <= k is no single cone in the stress
//    components (it is the spectral condition |sigma - t I| <= k for some t). Its conic inner
//    approximation here is the von Mises cylinder inscribed in Tresca's hexagon, sqrt(J2) <= k:
//    with s1 >= s2 >= s3, tau = (s1 - s3)/2, J2 = (a^2 + b^2 + (a + b)^2) / 6 (a = s1 - s2,
//    b = s2 - s3, a + b = 2 tau), so tau <= sqrt(J2) <= 2 tau / sqrt 3 (R. Hill, The Mathematical
//    Theory of Plasticity, Oxford 1950, chapter II.3: the two criteria agree in pure shear and
//    differ most, by 2/sqrt 3, in uniaxial stress). Hence
//      {sqrt(J2) <= k} (inside) Tresca(k) (inside) {sqrt(J2) <= 2k/sqrt 3}:
//    a load factor safe for the inscribed cone is safe for Tresca, and (homogeneity) Tresca's
//    limit is at most 2/sqrt 3 times the inscribed cone's (outer_factor()). L = D / k, q = 5, as
//    von Mises with Y = sqrt 3 k; ratio() is the cone's, tresca_ratio() Tresca's own.
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
  tresca_inscribed,  ///< "tresca_inscribed": sqrt(J2) <= k, the cone inside 3-D Tresca (header)
};

const char* to_string(YieldKind kind);

struct YieldCriterion {
  YieldKind kind = YieldKind::von_mises;
  /// von Mises: the uniaxial yield stress Y; Tresca: the shear yield stress k. Pa (or any unit:
  /// the stresses' own). Must be positive and finite.
  double strength = 1.0;

  static YieldCriterion von_mises(double yield_stress) { return {YieldKind::von_mises, yield_stress}; }
  static YieldCriterion tresca_plane_xz(double shear_yield) { return {YieldKind::tresca_plane_xz, shear_yield}; }
  static YieldCriterion tresca_inscribed(double shear_yield) { return {YieldKind::tresca_inscribed, shear_yield}; }

  /// The shear yield stress k: Y / sqrt 3 (von Mises) or `strength` (Tresca).
  double shear_yield() const;
  /// The rows of L (q = 5 von Mises and the inscribed cone, 2 Tresca in the x-z plane).
  int rows() const { return kind == YieldKind::tresca_plane_xz ? 2 : 5; }
  /// L (rows() x 6): f(sigma) = |L sigma|.
  Eigen::MatrixXd factor() const;
  /// f(sigma): 1 on the yield surface, < 1 inside.
  double ratio(const Voigt& sigma) const;
  /// The criterion the cone stands for: tresca_inscribed, Tresca's own (s1 - s3) / (2k); else ratio().
  double exact_ratio(const Voigt& sigma) const;
  /// The factor by which the cone's shakedown limit bounds the criterion's own from above: 2/sqrt 3
  /// for tresca_inscribed (header), 1 for the others (the cone is the criterion).
  double outer_factor() const;

  /// "" when valid, else "<field>: <reason>".
  std::string validate() const;
};

}  // namespace dc
