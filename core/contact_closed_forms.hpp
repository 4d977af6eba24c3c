#pragma once
// Closed-form frictional contact solutions used to validate the tangential solver
// (shared spec VALIDATION.md). Each function names its source. Conventions (docs/conventions.md):
// tractions and forces are those ON THE BODY; Kalker's F_x = -G c^2 C11 xi.
//
// Sources:
//  [J]  K. L. Johnson, Contact Mechanics, Cambridge University Press (1985).
//  [CM] C. Cattaneo (1938); R. D. Mindlin, J. Appl. Mech. 16 (1949) 259-268.
//  [MD] R. D. Mindlin, H. Deresiewicz, J. Appl. Mech. 20 (1953) 327-344 (unloading).
//  [C]  F. W. Carter, Proc. R. Soc. Lond. A 112 (1926) 151-157; [J] section 8.3;
//       the paper's (5.1)-(5.6).
//  [L]  J. L. Lubkin, J. Appl. Mech. 18 (1951) 183-187; [J] section 7.3.
//  [K]  J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling Contact, Kluwer (1990),
//       table of the linear creep coefficients (from his 1967 thesis); reproduced in [J] Table 8.1.
//  [S]  D. A. Spence, J. Elasticity 5 (1975) 297-319; [J] section 5.4.
#include "material.hpp"

namespace dc::closed_form {

// ---------------------------------------------------------------------------------------------
// Cattaneo-Mindlin: a sphere under constant P, then a monotonic tangential force Q <= mu P
// ([CM]; [J] section 7.2). Mindlin's solution: exact for nu = 0; for nu > 0 it neglects the
// small non-uniformity (order nu) of the displacement its traction gives in the stick zone, and
// for dissimilar materials the normal-tangential coupling. `ratio` = |Q| / (mu P) in [0, 1].
// ---------------------------------------------------------------------------------------------

/// Stick radius c = a (1 - Q/(mu P))^(1/3).
double mindlin_stick_radius(double a, double ratio);

/// Magnitude of the tangential traction at radius r (directed along Q):
/// q(r) = mu p0 [sqrt(1 - r^2/a^2) - (c/a) sqrt(1 - r^2/c^2)], the second term only for r < c;
/// 0 outside the contact. `mu_p0` = mu times the Hertz peak pressure.
double mindlin_traction(double r, double a, double mu_p0, double ratio);

/// Rigid tangential shift (far-field relative displacement) along Q:
/// delta = 3 mu P / (16 a) * compliance * [1 - (1 - Q/(mu P))^(2/3)],
/// compliance = sum (2 - nu)/G over both bodies (MaterialPair::mindlin_compliance()).
double mindlin_shift(double mu, double P, double a, double compliance, double ratio);

/// Unloading from Q* (ratio_max = Q*/(mu P)) back to Q (ratio = Q/(mu P), Q* >= Q >= -Q*),
/// Mindlin-Deresiewicz ([MD]; [J] section 7.2): the state is the loading state at Q* minus
/// twice the loading state at (Q* - Q)/2 (superposition of a reversed-slip annulus):
/// delta = delta(Q*) - 2 delta((Q* - Q)/2).
double mindlin_unloading_shift(double mu, double P, double a, double compliance, double ratio_max,
                               double ratio);
/// Traction on unloading (directed along Q*): q(Q*; r) - 2 q((Q* - Q)/2; r).
double mindlin_unloading_traction(double r, double a, double mu_p0, double ratio_max, double ratio);

// ---------------------------------------------------------------------------------------------
// Cattaneo in 2-D: identical cylinders (plane strain) under constant P, then a monotonic
// tangential force Q per unit length with |Q| <= mu P, no rolling ([CM]; [J] section 7.2). Exact
// in plane strain for identical materials (no normal-tangential coupling): the difference of two
// elliptical tractions gives a uniform tangential displacement on the stick zone, which is
// centred. The same stick half-length as Carter's rolling contact at the same force, but
// centred on x = 0 instead of at the leading edge. `force_ratio` = Q / (mu P) in [-1, 1] (signed).
// ---------------------------------------------------------------------------------------------

/// Half-length of the (centred) stick zone c = a sqrt(1 - |Q|/(mu P)).
double cattaneo_2d_stick_half_width(double a, double force_ratio);

/// Signed traction on the body at x (sign of Q), p0 the Hertz peak pressure:
/// tau(x) = sgn(Q) mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)], the second term on
/// |x| < c only; 0 outside |x| < a.
double cattaneo_2d_traction(double x, double a, double p0, double mu, double force_ratio);

// ---------------------------------------------------------------------------------------------
// Carter: 2-D steady rolling of identical cylinders (plane strain), Coulomb mu, tangential
// force F per unit length with |F| <= mu P ([C]; [J] section 8.3; the paper's (5.1)-(5.6)).
// Rolling direction +x: the contact moves towards +x, material enters it at the LEADING edge
// x = +a with no traction, so the stick zone is adjacent to x = +a: [a - 2a', a].
// Note on the paper's (5.1): its stick term sqrt(1 - ((x1 + d)/(l - d))^2) is centred at -d,
// i.e. on [-l, l - 2d], which contradicts its own stick interval l_a = 2d - l <= x1 <= l (5.6);
// the interval is the correct one (stick at the leading edge, [J] section 8.3), so the centre is
// +d = a - a' and the term reads sqrt(1 - ((x - d)/a')^2). The paper's F and tau_13 carry the
// opposite sign to ours (its F < 0 drives the cylinder forwards, (5.7)); here F is the force on
// the body, and the creepage xi (rigid slip velocity / V) has the opposite sign: F = -sgn(xi)|F|.
// `force_ratio` = F / (mu P) in [-1, 1] (signed).
// ---------------------------------------------------------------------------------------------

/// Half-length of the stick zone a' = a sqrt(1 - |F|/(mu P)).
double carter_stick_half_width(double a, double force_ratio);

/// Magnitude of the creepage: |xi| = (mu a / R)(1 - sqrt(1 - |F|/(mu P))), R the relative
/// radius of curvature (h = x^2/(2R)).
double carter_creepage(double a, double R, double mu, double force_ratio);

/// Inverse of carter_creepage: |F|/(mu P) = 1 - (1 - |xi| R/(mu a))^2, saturating at 1
/// (gross sliding) for |xi| >= mu a / R.
double carter_force_ratio(double a, double R, double mu, double creepage);

/// Signed traction on the body at x (sign of F), p0 the Hertz peak pressure:
/// tau(x) = sgn(F) mu p0 [sqrt(1 - x^2/a^2) - (a'/a) sqrt(1 - (x - d)^2/a'^2)], d = a - a',
/// the second term on the stick zone |x - d| < a' only; 0 outside |x| < a.
double carter_traction(double x, double a, double p0, double mu, double force_ratio);

// ---------------------------------------------------------------------------------------------
// Torsion of a Hertz contact (Lubkin [L]; [J] section 7.3).
// ---------------------------------------------------------------------------------------------

/// Full-stick torsional stiffness of a bonded circle of radius a between two half-spaces:
/// M / phi = (16/3) a^3 / (1/G1 + 1/G2) (a rigid body contributes 0 to the sum).
double lubkin_stick_stiffness(double a, const MaterialPair& materials);

/// Full-slip (limiting) twisting moment of a Hertz contact: M = 3 pi mu P a / 16.
double lubkin_slip_moment(double mu, double P, double a);

// ---------------------------------------------------------------------------------------------
// Kalker's linear rolling theory ([K]; [J] section 8.4, Table 8.1), circular contact a = b:
// F_x = -G c^2 C11 xi, F_y = -G c^2 C22 eta - G c^3 C23 phi, c = sqrt(a b), identical
// materials of shear modulus G and Poisson ratio nu.
// Tabulated (a/b = 1): nu = 0, 0.25, 0.5:  C11 = 3.40, 4.12, 5.20;  C22 = 3.40, 3.67, 3.98;
// C23 = 1.33, 1.47, 1.63. Values at other nu: linear interpolation between the tabulated ones.
// ---------------------------------------------------------------------------------------------

struct KalkerCoefficients {
  double c11 = 0.0, c22 = 0.0, c23 = 0.0;
};

/// Creep coefficients of a circular contact for nu in [0, 0.5] (throws std::domain_error outside).
KalkerCoefficients kalker_circular(double nu);

struct CreepForces {
  double fx = 0.0, fy = 0.0;  ///< N, on the body
};

/// Linear-theory creep forces for longitudinal creepage xi, lateral eta (-) and spin phi (1/m).
CreepForces kalker_linear_forces(double G, double c, const KalkerCoefficients& k, double xi, double eta,
                                 double phi);

// ---------------------------------------------------------------------------------------------
// Frictional indentation of dissimilar half-spaces by a sphere, monotonic loading (Spence [S];
// [J] section 5.4): the central stick zone r < c grows in proportion to the contact, c/a depends on
// |beta|/mu only. With the Hertz pressure (the shear's effect on the pressure neglected) the
// self-similar incremental problem gives (derivation in the .cpp)
//     |beta| / mu = (c/a) K'(c/a) / artanh(c/a) = 2 (c/a) K'(c/a) / ln[(1 + c/a)/(1 - c/a)],
// K'(k) = K(sqrt(1 - k^2)) the complementary complete elliptic integral of the first kind.
// ---------------------------------------------------------------------------------------------

/// Dundurs' second parameter beta = [(1-2nu1)/G1 - (1-2nu2)/G2] / (2[(1-nu1)/G1 + (1-nu2)/G2]),
/// body = 1, substrate = 2 (kappa / (2 sum (1-nu)/G), with the paper's kappa (4.3)).
double dundurs_beta(const MaterialPair& materials);

/// |beta| / mu for a given stick ratio t = c/a in (0, 1): t K'(t) / artanh(t).
double spence_beta_over_mu(double stick_ratio);

/// The stick ratio c/a for a given |beta| / mu >= 0 (solves the relation above; 1 at 0, -> 0 as
/// |beta|/mu -> infinity, c/a ~ 4 exp(-|beta|/mu) there).
double spence_stick_ratio(double beta_over_mu);

}  // namespace dc::closed_form
