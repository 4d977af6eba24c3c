#pragma once
// Newton's method on a small fixed-size system (the 6 rigid unknowns of one implicit step) with
// a forward finite-difference Jacobian and a backtracking (Armijo) line search on |r|.
// Fixed-size Eigen types only: no heap allocation.
#include <Eigen/Core>

namespace dc::dynamics {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// r(x) = 0 with x and r in the same units, so that one norm and one scale serve both.
class System6 {
 public:
  virtual ~System6() = default;
  virtual Vector6d residual(const Vector6d& x) const = 0;
  /// dr/dx at x, right after residual(x) was evaluated there; false: not available (forward
  /// differences are used, 6 more residuals).
  virtual bool jacobian(const Vector6d& x, Matrix6d& J) const {
    (void)x;
    (void)J;
    return false;
  }
};

struct NewtonOptions {
  double rel_tol = 1e-10;    ///< converged when |r| <= rel_tol * scale + abs_tol
  double abs_tol = 0.0;      ///< (units of r)
  int max_iterations = 30;   ///< Newton updates (each costs 7 residuals + the line search)
  int max_halvings = 12;     ///< line-search step halvings before "stalled"
};

enum class NewtonStatus {
  converged,          ///< |r| within tolerance
  max_iterations,     ///< tolerance not met within max_iterations
  stalled,            ///< the line search found no decrease of |r| along the Newton direction
  singular_jacobian,  ///< the finite-difference Jacobian is not invertible
  non_finite          ///< the residual (the callback) returned NaN or infinity
};

const char* to_string(NewtonStatus status);

struct NewtonResult {
  NewtonStatus status = NewtonStatus::max_iterations;
  int iterations = 0;   ///< Newton updates taken
  double residual = 0;  ///< |r| at the returned x
  int evaluations = 0;  ///< residual evaluations, finite differences included
};

/// Solves r(x) = 0 from the initial guess x (updated in place; on failure x is the last iterate).
/// `scale` is the size of x the tolerance is relative to; it is raised to |r(x0)| (the size of
/// the first correction) and sets the finite-difference steps sqrt(eps) * max(|x_j|, scale).
NewtonResult solve_newton6(const System6& system, Vector6d& x, double scale,
                           const NewtonOptions& options);

}  // namespace dc::dynamics
