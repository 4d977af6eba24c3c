#pragma once
// Error-controlled time steps of a dynamic run (time.adaptive; docs/dynamics.md "Adaptive time
// steps"): the local error of a BDF1 or BDF2 step from its difference to an explicit predictor
// of the same order (Milne's device), its weighted RMS norm with time.rtol and time.atol, and the
// step-size proposal with the usual safety factor and growth and shrink limits (Hairer & Wanner
// II, IV.8; SUNDIALS CVODE). The state of the error is y = (R, V, rho Omega): rho the gyration
// radius turns the angular velocity into a speed, as in the step's Newton tolerance.
#include <Eigen/Core>

#include "rigid_body.hpp"
#include "time_stepper.hpp"
#include "wrench.hpp"

namespace dc::dynamics {

/// A point of the accepted trajectory with its time derivative y' = (V, a, rho alpha).
struct TrajectoryPoint {
  double time = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero(), velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d rho_omega = Eigen::Vector3d::Zero();  ///< rho Omega (m/s)
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  ///< F / m (m/s^2)
  Eigen::Vector3d rho_alpha = Eigen::Vector3d::Zero();     ///< rho dOmega/dt (m/s^2)
};

/// The point of `state` under the total wrench `w` (applied + contact): a = F / m and
/// dOmega/dt = I_w^-1 (M - Omega x I_w Omega), from d(I_w Omega)/dt = M (2.21).
TrajectoryPoint trajectory_point(const RigidBody& body, const RigidBodyState& state, const Wrench& w);

struct StepSizeOptions {
  double rtol = 1e-4, atol = 1e-9;    ///< time.rtol, time.atol
  double dt_min = 0.0, dt_max = 0.0;  ///< time.dt_min, time.dt_max (s)
  double safety = 0.9;                ///< on the step that would meet the tolerance exactly
  double max_growth = 5.0;            ///< largest factor from one step to the next
  double max_shrink = 0.2;            ///< smallest factor after a rejection
};

/// The local error of the next step from the last two accepted points: restart() at the start
/// and after an event (where the stepper restarts with bdf1), accept() after every accepted step.
/// The weights: velocities atol + rtol v_ref, positions (atol + rtol v_ref) h (a position's error
/// per unit step, as a speed: so that a contact's phase, e.g. an impact's duration, errs by a few
/// rtol whatever the origin of the coordinates), v_ref the largest speed max(|V|, rho |Omega|) of
/// the run so far; atol is a speed (m/s).
class LocalErrorEstimate {
 public:
  explicit LocalErrorEstimate(double gyration_radius) : rho_(gyration_radius) {}
  void restart(const TrajectoryPoint& p);
  void accept(const TrajectoryPoint& p);

  /// The weighted RMS norm of the local error of the step from the last point to `end` taken by
  /// `scheme` (bdf1, or bdf2 over the last two points): 1 meets the tolerance.
  double error(const RigidBodyState& end, Scheme scheme, const StepSizeOptions& o) const;
  /// The order of accuracy of such a step (1: bdf1, 2: bdf2).
  static int order(Scheme scheme) { return scheme == Scheme::bdf2 ? 2 : 1; }

 private:
  double rho_;
  void note_speed(const TrajectoryPoint& p);
  TrajectoryPoint last_, previous_;
  bool has_previous_ = false;
  double speed_ref_ = 0.0;  ///< v_ref (m/s)
};

/// The next step after one of length h with error norm `err` of order p:
/// h (safety err^(-1/(p+1))) bounded by the growth and shrink limits (no growth right after a
/// rejection), and by dt_min and dt_max.
double propose_step(double h, double err, int order, bool after_rejection, const StepSizeOptions& o);

/// Where a step crossed an event (a contact beginning or ending): the share theta in (0, 1) of
/// the step at which the event function g, linear between g_start and g_end, is zero; 0.5
/// (bisection) when they are not finite or of one sign.
double event_share(double g_start, double g_end);

}  // namespace dc::dynamics
