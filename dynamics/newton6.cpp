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
  bool exact_update = false;  // x was reached by an update with the Jacobian at its predecessor
  bool may_keep = options.chord_contraction > 0.0;  // a kept Jacobian may still be asked for
  bool kept = false;          // `jacobian` is a kept one, still contracting (chord steps)
  for (;;) {
    if (norm <= (exact_update ? 1.0 : options.inexact_share) * tolerance) {
      out.status = NewtonStatus::converged;
      return out;
    }
    if (out.iterations + out.chord_steps == options.max_iterations) {
      out.status = NewtonStatus::max_iterations;
      return out;
    }
    if (!kept) {
      const JacobianSource source = system.jacobian(x, jacobian, /*fresh=*/!may_keep);
      kept = source == JacobianSource::kept;
      if (source == JacobianSource::unavailable) {
        for (int j = 0; j < 6; ++j) {  // forward differences, one column per unknown
          Vector6d xp = x;
          const double h = fd_relative * std::max(std::abs(x(j)), scale);
          xp(j) += h;
          jacobian.col(j) = (system.residual(xp) - r) / (xp(j) - x(j));
          ++out.evaluations;
        }
      }
    }
    const Eigen::FullPivLU<Matrix6d> lu(jacobian);
    if (!jacobian.allFinite() || !lu.isInvertible()) {
      if (kept) {  // a kept Jacobian that no longer serves: compute one here
        may_keep = kept = false;
        continue;
      }
      out.status = jacobian.allFinite() ? NewtonStatus::singular_jacobian : NewtonStatus::non_finite;
      return out;
    }
    const Vector6d dx = -lu.solve(r);
    if (kept) {
      // Chord step: the full step with the kept Jacobian, taken while it contracts |r| enough.
      ++out.chord_steps;
      const Vector6d trial = x + dx;
      const Vector6d r_trial = system.residual(trial);
      ++out.evaluations;
      const double trial_norm = r_trial.norm();
      const bool better = std::isfinite(trial_norm) && trial_norm < norm;
      const bool contracted = better && trial_norm <= options.chord_contraction * norm;
      if (better) {
        x = trial;
        r = r_trial;
        norm = trial_norm;
        exact_update = false;
      }
      out.residual = norm;
      if (contracted) continue;
      // From here on Jacobians computed at the iterate. When the trial was refused, the
      // system's last evaluation was there: evaluate x again for its Jacobian.
      may_keep = kept = false;
      if (!better) {
        r = system.residual(x);
        ++out.evaluations;
      }
      continue;
    }
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
    exact_update = true;
  }
}

}  // namespace dc::dynamics
