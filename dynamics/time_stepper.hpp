#pragma once
// Implicit time stepping of the Newton-Euler equations (2.20)-(2.21) in the form of (3.9)-(3.10):
//   m dV/dt = F,   d(I_world Omega)/dt = M   (world frame: the gyroscopic term Omega x I Omega of
//   (2.21) is the rate of change of I_world = Q I_body Q^T),
//   dR/dt = V,     dq/dt: q_{K+1} = exp(theta) q_K on the unit-quaternion manifold,
// with F, M a callback of the END-of-step kinematics. Each step solves for the six unknowns
// (V_{K+1}, Omega_{K+1}) by Newton (newton6.hpp); see docs/dynamics.md.
#include <limits>

#include "newton6.hpp"
#include "rigid_body.hpp"
#include "wrench.hpp"

namespace dc::dynamics {

/// bdf1: the paper's backward differences (3.1)-(3.2), first order, L-stable.
/// bdf2: second-order backward differences (variable step), started by one bdf1 step. Chosen over
///   the implicit midpoint rule because it stays in the paper's family and damps stiff modes
///   (amplification -> 0 as dt/tau -> infinity) where the midpoint rule rings (-> -1): the creep
///   law's slip relaxes ~1000x faster than the motion (DESIGN.md).
enum class Scheme { bdf1, bdf2 };

const char* to_string(Scheme scheme);

struct StepperOptions {
  Scheme scheme = Scheme::bdf2;
  /// Tolerance on the step's residual in velocity units: |(dV, rho dOmega)| with rho the
  /// gyration radius, relative to max(|V|, rho |Omega|, first correction).
  NewtonOptions newton;
  /// Newton starts from (V, Omega) extrapolated through the last accepted states (quadratic
  /// from the third step of a history, linear on the second) when that extrapolation came nearer
  /// the last step's answer than the start-of-step velocities did, else from the start-of-step
  /// velocities; the extrapolated start is accepted without an update when its residual is within
  /// this share of the tolerance (NewtonOptions::inexact_share), and Newton starts again from the
  /// start-of-step velocities if it fails from there. 0: never extrapolated.
  double predicted_start_share = 0.1;
};

struct StepReport {
  NewtonStatus status = NewtonStatus::max_iterations;
  Scheme scheme_used = Scheme::bdf1;  ///< bdf1 on the start step of bdf2
  int iterations = 0;                 ///< Newton updates in this step (Jacobian at the iterate)
  int chord_steps = 0;                ///< updates with a kept Jacobian (NewtonOptions::chord_contraction)
  double residual = 0.0;              ///< final |residual| (m/s)
  int wrench_evaluations = 0;         ///< calls of the callback in this step
  bool converged() const { return status == NewtonStatus::converged; }
};

class RigidBodyStepper {
 public:
  explicit RigidBodyStepper(RigidBody body, StepperOptions options = {});

  /// Advances `state` by dt > 0 ("dt" InputError otherwise). On non-convergence the state is left
  /// unchanged and the report says why. bdf2 uses the state before the last step as its history
  /// when `state` is exactly the one this stepper produced last; otherwise it restarts with bdf1.
  [[nodiscard]] StepReport step(RigidBodyState& state, double dt, const WrenchFunction& wrench);
  /// The same with the wrench's sensitivity for Newton's Jacobian (no finite differences: one
  /// wrench evaluation per Newton iteration and line-search trial).
  [[nodiscard]] StepReport step(RigidBodyState& state, double dt, const WrenchFunction& wrench,
                                const WrenchJacobianFunction& jacobian);

  /// Forgets the history (the next bdf2 step is a bdf1 start step).
  void reset() { history_.has_history = history_.has_older = false; }
  /// Takes back the last converged step: the history as before it (the caller rejected the step
  /// and retries from its start with another dt, adaptive steps). Once per step.
  void retract() { history_ = before_; }

  const RigidBody& body() const { return body_; }
  const StepperOptions& options() const { return options_; }

 private:
  bool continues_history(const RigidBodyState& state) const;
  /// Newton's start (V, Omega) at t_K + dt, extrapolated from the accepted states (false: not finite).
  bool predict(double dt, Vector6d& x) const;

  /// The accepted states the next step continues from.
  struct History {
    bool has_history = false;
    RigidBodyState previous;  ///< state at t_{K-1}
    RigidBodyState last;      ///< state at t_K as this stepper returned it
    RigidBodyState older;     ///< state at t_{K-2} (has_older)
    bool has_older = false;
    /// How far the last step's answer lay from the extrapolated start and from the start-of-step
    /// velocities (|dx|, m/s; infinite when there was no extrapolation).
    double extrapolation_miss = std::numeric_limits<double>::infinity();
    double hold_miss = std::numeric_limits<double>::infinity();
  };

  RigidBody body_;
  StepperOptions options_;
  History history_;
  History before_;  ///< before the last converged step (retract)
};

}  // namespace dc::dynamics
