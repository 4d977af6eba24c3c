#pragma once
// The paper's Section 5 example: an elastic cylinder rolling and sliding on a half-plane of the
// same material under a driving moment M_ex(t) = M0 + gamma t and a horizontal force T_ex,
// with the quasi-stationary Carter-Poritsky traction (5.1)-(5.6) and the motion (5.7)-(5.9).
//
// Dimensionless, as in the paper's Figs 4-6: t^ = t mu P/(M V0), u = V/V0,
// w = v/(mu eps V0) with v = V - Omega R the rigid-slip velocity (5.3) (w < 0 when driven),
// F^ = |F|/(mu P), l^ = 1 - d/l (adhesion half-length), v^ = |w|,
// gamma^ = gamma M V0/((mu P)^2 R), M0^ = M0/(mu P R), T^ = T_ex/(mu P), eta = M R^2 / I.
//
// The traction law: (5.3) solved for F (the creepage ratio s = v/(mu eps V) = w/u):
//   F/(mu P) = phi(s) = sgn(s) [1 - (1 - |s|)^2] = 2s - s|s|   for |s| <= 1,
//              phi(s) = sgn(s)                                  beyond (gross sliding).
// NOTE: the printed (5.10)-(5.11) write (1 + v/(mu V eps))^(1/2) - 1 instead; that does not
// invert (5.3) (square root for square, and the sign): we use the inversion above.
// The motion, from (5.7) and (5.9) divided by mu P (c = 1/(1 + eta), c = 0 for eta = inf):
//   du/dt^        = -phi(w/u) + T^
//   c mu eps dw/dt^ = -phi(w/u) + c T^ - (1 - c) M^(t^),   M^(t^) = M0^ + gamma^ t^
// (M dv/dt = mu eps mu P dw/dt^ since v = mu eps V0 w). With mu eps ~ 1e-3 the slip relaxes ~1/(mu eps) faster than the motion: the second equation is stiff
// (for eta = inf it is algebraic, (5.8) with I = 0), so the steps are implicit (backward
// differences, BDF1 as in the paper or BDF2) with Newton on (u, w) in every step.
//
// Quasi-static limit (eps -> 0, T^ = 0): F^ = eta M^(t^)/(1 + eta),
//   u = 1 + eta/(1 + eta) (M0^ t^ + gamma^ t^2/2), l^ = sqrt(1 - F^), v^ = u (1 - l^),
// until F^ reaches 1 at t^* = ((1 + eta)/eta - M0^)/gamma^ (then gross sliding: F^ = 1).
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace dc::paper_cylinder {

/// Carter-Poritsky force law F/(mu P) = phi(s) of the creepage ratio s = v/(mu eps V), and
/// its derivative (0 beyond saturation).
double force_ratio(double s);
double force_ratio_slope(double s);

/// A traction law F/(mu P) of the creepage ratio s with its slope: the closed form above, or a
/// numerical one (the tangential solver's steady rolling).
struct TractionLaw {
  std::function<double(double)> force_ratio = paper_cylinder::force_ratio;
  std::function<double(double)> slope = paper_cylinder::force_ratio_slope;
};

struct Parameters {
  double gamma_bar = 0.0;  ///< rate of the driving moment
  double M0_bar = 0.0;     ///< initial driving moment
  double eta = 2.0;        ///< M R^2 / I (infinity allowed)
  double epsilon = 1e-3;   ///< l / R
  double mu = 1.0;         ///< friction coefficient: the slip relaxes on the scale mu eps
  double v_bar0 = 0.0;     ///< initial |v|/(mu eps V0); the slip starts as a driven one (w = -v_bar0)
  double w0 = std::numeric_limits<double>::quiet_NaN();  ///< signed initial v/(mu eps V0); NaN: -v_bar0
  double T_bar = 0.0;      ///< horizontal force on the axis, T_ex/(mu P)
  double t_bar_end = 1.0;
};

enum class Scheme { bdf1, bdf2 };

struct Sample {
  double t_bar = 0.0, u = 1.0, w = 0.0;
  double F_bar = 0.0;   ///< |F|/(mu P)
  double l_bar = 1.0;   ///< adhesion half-length 1 - d/l = sqrt(1 - F^) (0 when sliding)
  double v_bar = 0.0;   ///< |v|/(mu eps V0)
  bool sliding = false; ///< |s| >= 1: gross sliding (no adhesion zone)
  int newton_iterations = 0;
};

struct Run {
  std::vector<Sample> samples;  ///< the initial state, then every step
  bool ok = true;
  bool interrupted = false;     ///< stopped by an interrupt (core/interrupt.hpp): ok = false
  std::string message;          ///< why the run stopped early (ok = false)
};

/// Throws InputError (key "dimensionless.<name>") for parameters out of range.
void check(const Parameters& p);

/// Integrates from t^ = 0 to t_bar_end with steps dt_bar. Throws InputError (key
/// "dimensionless.<name>") for parameters out of range.
Run simulate(const Parameters& p, double dt_bar, Scheme scheme, const TractionLaw& law = {});

/// The quasi-static limit (eps -> 0, T^ = 0) at t^, before gross sliding.
Sample quasi_static(const Parameters& p, double t_bar);

}  // namespace dc::paper_cylinder
