#pragma once
// Native specialist solvers on matrix-free (FFT) operators: the fast path for large grids.
#include <vector>

#include "normal_preconditioner.hpp"
#include "quadratic_program.hpp"

namespace dc {

/// Polonsky & Keer (Wear 231, 1999) projected conjugate gradient for the normal problem
/// (4.7) in QP form: bounds 0 <= x <= upper (upper is +inf or 0 for elements that cannot
/// touch), at most one equality sum a x = b with equal weights a on the free elements
/// (force control). Stops when the relative change of x falls below options.tol.
SolveOutcome solve_normal_native(const QuadraticProgram& qp, const SolveOptions& options);

/// The same program solved by preconditioned projected conjugate gradients
/// (nlp/preconditioned_normal.cpp): the preconditioner is built for the unscaled compliance C,
/// and Q = C / scale. Iterations nearly independent of the grid; same stopping rule.
SolveOutcome solve_normal_preconditioned(const QuadraticProgram& qp, const SolveOptions& options,
                                         const NormalPreconditioner& preconditioner, double scale);

/// The normal program's structure, checked: which elements may carry load, force control and
/// its total sum x (the equality's weights a0 are equal on the free elements).
struct NormalQpForm {
  std::vector<char> free;
  std::size_t n_free = 0;
  bool force_control = false;
  double a0 = 0.0, total = 0.0;
};
NormalQpForm read_normal_qp(const QuadraticProgram& qp);
/// Starting point: qp.x0 projected on the bounds (or 0); under force control scaled to the
/// total, uniform on the free elements when it carries nothing.
std::vector<double> normal_start(const QuadraticProgram& qp, const NormalQpForm& form);

}  // namespace dc
