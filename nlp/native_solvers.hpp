#pragma once
// Native specialist solvers on matrix-free (FFT) operators: the fast path for large grids.
#include "quadratic_program.hpp"

namespace dc {

/// Polonsky & Keer (Wear 231, 1999) projected conjugate gradient for the normal problem
/// (4.7) in QP form: bounds 0 <= x <= upper (upper is +inf or 0 for elements that cannot
/// touch), at most one equality sum a x = b with equal weights a on the free elements
/// (force control). Stops when the relative change of x falls below options.tol.
SolveOutcome solve_normal_native(const QuadraticProgram& qp, const SolveOptions& options);

}  // namespace dc
