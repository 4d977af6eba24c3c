#include "newton6.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace dc::dynamics {

const char* to_string(NewtonStatus status) {
  switch (status) {
    case NewtonStatus::converged: return "converged";
    case NewtonStatus::max_iterations: return "max_iterations";
    case NewtonStatus::stalled: return "stalled";
    case NewtonStatus::singular_jacobian: return "singular_jacobian";
    case NewtonStatus::non_finite: return "non_finite";
  }
  return "unknown";
}

NewtonResult solve_newton6(const System6& system, Vector6d& x, double scale,
                           const NewtonOptions& options) {
  NewtonResult out;
  Vector6d r = system.residual(x);
  ++out.evaluations;
  double norm = r.norm();
  out.residual = norm;
  if (!std::isfinite(norm)) {
    out.status = NewtonStatus::non_finite;
    return out;
  }
  scale = std::max(scale, norm);
  const double tolerance = options.rel_tol * scale + options.abs_tol;
  const double fd_relative = std::sqrt(std::numeric_limits<double>::epsilon());
  Matrix6d jacobian;
  for (;;) {
    if (norm <= tolerance) {
      out.status = NewtonStatus::converged;
      return out;
    }
    if (out.iterations == options.max_iterations) {
      out.status = NewtonStatus::max_iterations;
      return out;
    }
    if (!system.jacobian(x, jacobian)) {
      for (int j = 0; j < 6; ++j) {  // forward differences, one column per unknown
        Vector6d xp = x;
        const double h = fd_relative * std::max(std::abs(x(j)), scale);
        xp(j) += h;
        jacobian.col(j) = (system.residual(xp) - r) / (xp(j) - x(j));
        ++out.evaluations;
      }
    }
    const Eigen::FullPivLU<Matrix6d> lu(jacobian);
    if (!jacobian.allFinite() || !lu.isInvertible()) {
      out.status = jacobian.allFinite() ? NewtonStatus::singular_jacobian : NewtonStatus::non_finite;
      return out;
    }
    const Vector6d dx = -lu.solve(r);
    ++out.iterations;
    double lambda = 1.0;
    bool accepted = false;
    for (int halving = 0; halving <= options.max_halvings; ++halving, lambda *= 0.5) {
      const Vector6d trial = x + lambda * dx;
      const Vector6d r_trial = system.residual(trial);
      ++out.evaluations;
      const double trial_norm = r_trial.norm();
      if (std::isfinite(trial_norm) && trial_norm <= (1.0 - 1e-4 * lambda) * norm) {
        x = trial;
        r = r_trial;
        norm = trial_norm;
        accepted = true;
        break;
      }
    }
    out.residual = norm;
    if (!accepted) {
      out.status = NewtonStatus::stalled;
      return out;
    }
  }
}

}  // namespace dc::dynamics
