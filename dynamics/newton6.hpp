#pragma once
// Newton's method on a small fixed-size system (the 6 rigid unknowns of one implicit step) with
// a forward finite-difference Jacobian and a backtracking (Armijo) line search on |r|.
// Fixed-size Eigen types only: no heap allocation.
#include <Eigen/Core>

namespace dc::dynamics {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// Where a Jacobian came from: not available (forward differences are used, 6 more residuals),
/// computed at x, or kept from an earlier point (a chord Jacobian: its step is checked).
enum class JacobianSource { unavailable, computed, kept };

/// r(x) = 0 with x and r in the same units, so that one norm and one scale serve both.
class System6 {
 public:
  virtual ~System6() = default;
  virtual Vector6d residual(const Vector6d& x) const = 0;
  /// dr/dx at x, right after residual(x) was evaluated there. `fresh`: computed at x; else the
  /// system may return one it kept (JacobianSource::kept) when that is much cheaper.
  virtual JacobianSource jacobian(const Vector6d& x, Matrix6d& J, bool fresh) const {
    (void)x;
    (void)J;
    (void)fresh;
    return JacobianSource::unavailable;
  }
};

struct NewtonOptions {
  double rel_tol = 1e-10;    ///< converged when |r| <= rel_tol * scale + abs_tol
  double abs_tol = 0.0;      ///< (units of r)
  int max_iterations = 30;   ///< Newton updates (each costs 7 residuals + the line search)
  int max_halvings = 12;     ///< line-search step halvings before "stalled"
  /// An x not reached by a Newton update with the Jacobian at its predecessor - the initial
  /// guess, or a chord step - is accepted when |r| <= inexact_share * tolerance. Below 1 for a
  /// guess that only extrapolates, and for chord steps (linear convergence): a Newton update
  /// lands far inside the tolerance (quadratic convergence), and an x accepted at the tolerance
  /// would leave each step's residual in the run's momentum balance.
  double inexact_share = 1.0;
  /// Chord steps: 0 (the default) asks for a Jacobian computed at every iterate. Above 0 a kept
  /// Jacobian may be used (System6::jacobian with fresh = false); its full step is taken when it
  /// reduces |r| by at least this factor, and kept for the next iterate; otherwise the better of
  /// the two points is kept and the Jacobian computed there afresh (a Newton step with the line
  /// search).
  double chord_contraction = 0.0;
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
  int iterations = 0;   ///< Newton updates taken with a Jacobian computed at the iterate
  int chord_steps = 0;  ///< updates with a kept Jacobian (taken or refused)
  double residual = 0;  ///< |r| at the returned x
  int evaluations = 0;  ///< residual evaluations, finite differences included
};

/// Solves r(x) = 0 from the initial guess x (updated in place; on failure x is the last iterate).
/// `scale` is the size of x the tolerance is relative to; it is raised to |r(x0)| (the size of
/// the first correction) and sets the finite-difference steps sqrt(eps) * max(|x_j|, scale).
NewtonResult solve_newton6(const System6& system, Vector6d& x, double scale,
                           const NewtonOptions& options);

}  // namespace dc::dynamics
