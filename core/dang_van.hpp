#pragma once
// The Dang Van multiaxial high-cycle fatigue criterion for a periodic stress path at one
// material point (K. Dang Van, B. Griveau, O. Message, "On a new multiaxial fatigue limit
// criterion: theory and application", in Biaxial and Multiaxial Fatigue, EGF 3, 1989, 479-496;
// the mesoscopic approach: K. Dang Van, I. V. Papadopoulos (eds.), High-Cycle Metal Fatigue,
// CISM 392, Springer 1999).
//
// Below the fatigue limit the grains shake down elastically (Melan at the mesoscopic scale) with
// a stabilised residual deviatoric stress s*, taken (the min-max construction of Dang Van and
// Papadopoulos) as the centre of the smallest ball enclosing the deviatoric stress path s(t) in
// the 5-D deviatoric space (core/enclosing_ball.hpp; the norm sqrt(J2), voigt_stress.hpp). Then
// at each instant
//   tau(t) = Tresca shear of (s(t) - s*)         (the mesoscopic shear, half the largest
//                                                  difference of principal stresses),
//   p_h(t) = tr sigma(t) / 3                      (the hydrostatic stress, the same at both scales),
// and the criterion reads  tau(t) + alpha p_h(t) <= beta  at every instant; its index
//   I_DV = max_t (tau(t) + alpha p_h(t)) / beta                                          (1)
// exceeds 1 when a fatigue crack is predicted. alpha and beta come from two fatigue limits
// (fully reversed torsion t_-1 and bending f_-1: beta = t_-1, alpha = 3 (t_-1 / f_-1 - 1/2)).
#include <string>
#include <vector>

#include "enclosing_ball.hpp"
#include "voigt_stress.hpp"

namespace dc {

struct DangVanParameters {
  /// The hydrostatic-stress sensitivity alpha (dimensionless). Default 0.3; finite.
  double alpha = 0.3;
  /// The shear fatigue limit beta (the stresses' unit). Default 1; positive and finite.
  double beta = 1.0;

  /// From the fully reversed torsion and bending fatigue limits (both positive):
  /// beta = t_-1, alpha = 3 (t_-1 / f_-1 - 1/2).
  static DangVanParameters from_fatigue_limits(double torsion_limit, double bending_limit);

  /// "" when valid, else "<field>: <reason>".
  std::string validate() const;
};

struct DangVanResult {
  Voigt residual_deviator{};  ///< s*, the centre of the path's smallest enclosing deviatoric ball
  double radius = 0.0;        ///< that ball's radius, sqrt(J2) units (the deviatoric amplitude)
  std::vector<double> mesoscopic_shear;  ///< tau(t), one per instant
  std::vector<double> hydrostatic;       ///< p_h(t)
  double index = 0.0;                    ///< I_DV of (1)
  int critical_instant = 0;              ///< the instant where (1) is largest
  EnclosingBall ball;                    ///< the enclosing ball and its certificate (5-D coordinates)

  bool fatigue() const { return index > 1.0; }
};

/// The criterion along `path` (at least one instant, every component finite). Throws
/// std::invalid_argument for an empty or non-finite path or invalid parameters.
DangVanResult dang_van(const std::vector<Voigt>& path, const DangVanParameters& parameters);

}  // namespace dc
