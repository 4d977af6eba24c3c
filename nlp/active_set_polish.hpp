#pragma once
// Active-set polish of an approximate solution of a QuadraticProgram (the NLopt fallback stops
// near, not at, the solution). From x and its multipliers the active set is read off
// w = x - (Qx + c - A'lambda): a box variable with w outside its bounds is held at that bound, a
// disk with |w| > r is held on its circle at r w/|w| (slip along -(gradient)); everything else is
// free. On that set the equality-constrained QP
//   min 1/2 x_F'Q_FF x_F + (c + Q x_H)_F'x_F   s.t.  A_F x_F = b - A_H x_H
// is solved exactly (conjugate gradients on Q_FF, one solve per right-hand side and equality
// row, then the small multiplier system). Repeated while the active set changes (a semismooth
// Newton iteration); the best feasible point by kkt_residual() is kept.
#include <string>
#include <vector>

#include "quadratic_program.hpp"

namespace dc {

/// The fixed-point residual of the KKT conditions, relative to the size of x:
/// max(|x - Pi_D(x - (Qx + c - A'lambda))|_inf / max|x|, max_k |a_k'x - b_k| / (|b_k| + sum |a_ki x_i|)),
/// Pi_D the projection on the bounds and disks. 0 at the solution; scale-free.
double kkt_residual(const QuadraticProgram& qp, const std::vector<double>& x, const std::vector<double>& lambda);

struct PolishResult {
  bool improved = false;    ///< x and lambda were replaced by a better point
  double before = 0.0;      ///< kkt_residual of the given point
  double after = 0.0;       ///< of the returned point
  int rounds = 0;           ///< active sets tried
  int applies = 0;          ///< operator applies (conjugate-gradient iterations)
};

/// Polishes x (feasible or nearly) and lambda in place; keeps them when no active set improves
/// on them. `lambda` has one entry per equality row. Stops once the KKT residual is at most
/// `target` (round-off by default; the slip directions on disks converge linearly, a fixed
/// fraction per active set, so a caller whose applies are dear asks for what it needs).
PolishResult polish_on_active_set(const QuadraticProgram& qp, std::vector<double>& x, std::vector<double>& lambda,
                                  double target = 0.0);

/// "active-set polish: KKT residual B -> A (R sets, N applies)", for the backends' messages.
std::string polish_summary(const PolishResult& polish);

}  // namespace dc
