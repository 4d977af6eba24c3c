#include "time_stepper.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "errors.hpp"
#include "rotation.hpp"

namespace dc::dynamics {

const char* to_string(Scheme scheme) { return scheme == Scheme::bdf1 ? "bdf1" : "bdf2"; }

namespace {

/// y_{K+1} = a0 y_K - a1 y_{K-1} + b dt f_{K+1}. bdf1 (3.1): {1, 0, 1}. bdf2 with
/// w = dt_K / dt_{K-1}: a0 = (1+w)^2/(1+2w), a1 = w^2/(1+2w), b = (1+w)/(1+2w) ({4/3, 1/3, 2/3}).
struct Bdf {
  double a0, a1, b;
};

Bdf bdf2(double ratio) {
  const double d = 1.0 + 2.0 * ratio;
  return {(1.0 + ratio) * (1.0 + ratio) / d, ratio * ratio / d, (1.0 + ratio) / d};
}

/// The residual of one step in the unknowns x = (V_{K+1}, rho Omega_{K+1}), in m/s.
class StepResidual final : public System6 {
 public:
  StepResidual(const RigidBody& body, const WrenchFunction& wrench, const WrenchJacobianFunction* jacobian,
               const RigidBodyState& now, const RigidBodyState* before, const Bdf& c, double dt)
      : body_(body), wrench_(wrench), wrench_jacobian_(jacobian), beta_(c.b * dt), time_(now.time + dt),
        rho_(body.gyration_radius()), q_now_(now.orientation),
        scale_inverse_inertia_(rho_ * body.inertia_world(now.orientation).inverse()) {
    position_history_ = c.a0 * now.position;
    velocity_history_ = c.a0 * now.velocity;
    momentum_history_ = c.a0 * angular_momentum(body, now);
    rotation_history_.setZero();  // theta_K = 0 in the chart at q_K
    if (before) {
      position_history_ -= c.a1 * before->position;
      velocity_history_ -= c.a1 * before->velocity;
      momentum_history_ -= c.a1 * angular_momentum(body, *before);
      // theta_{K-1} = log(q_{K-1} q_K^-1): q_{K-1} in the chart q = exp(theta) q_K.
      rotation_history_ = -c.a1 * log_map(before->orientation * now.orientation.conjugate());
    }
  }

  double rho() const { return rho_; }

  StepKinematics kinematics(const Vector6d& x) const {
    StepKinematics k;
    k.velocity = x.head<3>();
    k.omega = x.tail<3>() / rho_;
    k.time = time_;
    // (3.9): R_{K+1} from the backward difference of dR/dt = V.
    k.position = position_history_ + beta_ * k.velocity;
    // (3.10), orientation: backward difference in the chart q = exp(theta) q_K of
    // theta' = dexp^-1_theta(Omega) = Omega - theta x Omega / 2 + ...; theta is parallel to
    // Omega up to O(dt^2), so the correction adds O(dt^3) per step, below bdf2's own truncation
    // error, and is left out (a test with it gave the same observed order 2.0).
    k.orientation = (exp_map(rotation_history_ + beta_ * k.omega) * q_now_).normalized();
    return k;
  }

  Vector6d residual(const Vector6d& x) const override {
    const StepKinematics k = kinematics(x);
    const Wrench w = wrench_(k);
    Vector6d r;
    // (3.9): m (V_{K+1} - history) = b dt F_{K+1}, divided by m.
    r.head<3>() = k.velocity - velocity_history_ - (beta_ / body_.mass()) * w.force;
    // (3.10): I_world(q_{K+1}) Omega_{K+1} - history = b dt M_{K+1}, times rho I_world(q_K)^-1.
    const Eigen::Vector3d momentum = body_.inertia_world(k.orientation) * k.omega;
    r.tail<3>() = scale_inverse_inertia_ * (momentum - momentum_history_ - beta_ * w.moment);
    return r;
  }

  /// dr/dx from the wrench's sensitivity: R = history + beta V, Omega = x_tail / rho, and
  /// q = exp(theta_hist + beta Omega) q_K turns by beta dOmega (the exponential's differential
  /// taken as the identity: O(theta) relative). The orientation's share of d(I_world Omega)
  /// (O(beta Omega) relative) is left out.
  JacobianSource jacobian(const Vector6d& x, Matrix6d& J, bool fresh) const override {
    if (!wrench_jacobian_ || !*wrench_jacobian_) return JacobianSource::unavailable;
    const StepKinematics k = kinematics(x);
    const WrenchJacobian d = (*wrench_jacobian_)(k, fresh);
    if (!d.valid) return JacobianSource::unavailable;
    const Eigen::Matrix<double, 6, 3> dV = beta_ * d.position + d.velocity;  // d(F, M)/dV
    const Eigen::Matrix<double, 6, 3> dW = (d.omega + beta_ * d.orientation) / rho_;  // d(F, M)/d(rho Omega)
    const double beta_m = beta_ / body_.mass();
    J.block<3, 3>(0, 0) = Eigen::Matrix3d::Identity() - beta_m * dV.topRows<3>();
    J.block<3, 3>(0, 3) = -beta_m * dW.topRows<3>();
    J.block<3, 3>(3, 0) = -beta_ * scale_inverse_inertia_ * dV.bottomRows<3>();
    J.block<3, 3>(3, 3) =
        scale_inverse_inertia_ * (body_.inertia_world(k.orientation) / rho_ - beta_ * dW.bottomRows<3>());
    if (!J.allFinite()) return JacobianSource::unavailable;
    return d.kept ? JacobianSource::kept : JacobianSource::computed;
  }

 private:
  const RigidBody& body_;
  const WrenchFunction& wrench_;
  const WrenchJacobianFunction* wrench_jacobian_;
  double beta_, time_, rho_;
  Eigen::Quaterniond q_now_;
  Eigen::Matrix3d scale_inverse_inertia_;
  Eigen::Vector3d position_history_, velocity_history_, momentum_history_, rotation_history_;
};

bool same_state(const RigidBodyState& a, const RigidBodyState& b) {
  return a.time == b.time && a.position == b.position &&
         a.orientation.coeffs() == b.orientation.coeffs() && a.velocity == b.velocity &&
         a.omega == b.omega;
}

}  // namespace

RigidBodyStepper::RigidBodyStepper(RigidBody body, StepperOptions options)
    : body_(std::move(body)), options_(options) {}

bool RigidBodyStepper::continues_history(const RigidBodyState& state) const {
  return history_.has_history && same_state(state, history_.last);
}

bool RigidBodyStepper::predict(double dt, Vector6d& x) const {
  // x = (V, Omega) at t_K + dt extrapolated by the polynomial through the accepted states:
  // quadratic through t_{K-2}, t_{K-1}, t_K when there are three, else linear.
  const double t = history_.last.time + dt;
  if (history_.has_older) {
    const double t0 = history_.older.time, t1 = history_.previous.time, t2 = history_.last.time;
    const double l0 = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
    const double l1 = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
    const double l2 = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
    x.head<3>() = l0 * history_.older.velocity + l1 * history_.previous.velocity + l2 * history_.last.velocity;
    x.tail<3>() = l0 * history_.older.omega + l1 * history_.previous.omega + l2 * history_.last.omega;
  } else {
    const double w = dt / (history_.last.time - history_.previous.time);
    x.head<3>() = history_.last.velocity + w * (history_.last.velocity - history_.previous.velocity);
    x.tail<3>() = history_.last.omega + w * (history_.last.omega - history_.previous.omega);
  }
  return x.allFinite();
}

StepReport RigidBodyStepper::step(RigidBodyState& state, double dt, const WrenchFunction& wrench) {
  return step(state, dt, wrench, WrenchJacobianFunction());
}

StepReport RigidBodyStepper::step(RigidBodyState& state, double dt, const WrenchFunction& wrench,
                                  const WrenchJacobianFunction& jacobian) {
  if (!(std::isfinite(dt) && dt > 0.0)) throw InputError("dt", "must be a positive finite step");
  if (!(std::abs(state.orientation.norm() - 1.0) <= 1e-9))
    throw InputError("state.orientation", "must be a unit quaternion");

  StepReport report;
  const bool multistep = options_.scheme == Scheme::bdf2 && continues_history(state);
  report.scheme_used = multistep ? Scheme::bdf2 : Scheme::bdf1;
  const Bdf c = multistep ? bdf2(dt / (history_.last.time - history_.previous.time)) : Bdf{1.0, 0.0, 1.0};
  const StepResidual system(body_, wrench, &jacobian, state, multistep ? &history_.previous : nullptr, c, dt);

  Vector6d x;
  x << state.velocity, system.rho() * state.omega;
  const Vector6d start = x;
  const double scale = std::max(state.velocity.norm(), system.rho() * state.omega.norm());
  // Newton's start: the velocities extrapolated through the accepted states when the last
  // step's answer was too far from its start-of-step velocities to accept them as they were,
  // and nearer the extrapolation (a motion with a trend: a body accelerating); else the
  // start-of-step velocities (a steady motion, whose ripple extrapolation would amplify).
  Vector6d guess = x;
  const bool have_guess = options_.predicted_start_share > 0.0 && continues_history(state) && predict(dt, guess);
  if (have_guess) guess.tail<3>() *= system.rho();
  // The start-of-step velocities as long as they would have been accepted as they were.
  const double hold_accepted = options_.newton.inexact_share * (options_.newton.rel_tol * scale + options_.newton.abs_tol);
  const bool extrapolated =
      have_guess && history_.hold_miss > hold_accepted && history_.extrapolation_miss < history_.hold_miss;
  NewtonOptions newton_options = options_.newton;
  if (extrapolated) {
    x = guess;
    newton_options.inexact_share = std::min(newton_options.inexact_share, options_.predicted_start_share);
  }
  NewtonResult newton = solve_newton6(system, x, scale, newton_options);
  if (extrapolated && newton.status != NewtonStatus::converged) {
    // The extrapolation missed (a contact event within the step): Newton from the start again.
    const NewtonResult missed = newton;
    x = start;
    newton = solve_newton6(system, x, scale, options_.newton);
    newton.evaluations += missed.evaluations;
    newton.iterations += missed.iterations;
    newton.chord_steps += missed.chord_steps;
  }
  report.status = newton.status;
  report.iterations = newton.iterations;
  report.chord_steps = newton.chord_steps;
  report.residual = newton.residual;
  report.wrench_evaluations = newton.evaluations;
  if (!report.converged()) return report;

  const StepKinematics k = system.kinematics(x);
  before_ = history_;
  const double never = std::numeric_limits<double>::infinity();
  history_.extrapolation_miss = have_guess ? (x - guess).norm() : never;
  history_.hold_miss = have_guess ? (x - start).norm() : never;
  history_.has_older = continues_history(state);
  history_.older = history_.previous;
  history_.previous = state;
  state.position = k.position;
  state.orientation = k.orientation;
  state.velocity = k.velocity;
  state.omega = k.omega;
  state.time = k.time;
  history_.last = state;
  history_.has_history = true;
  return report;
}

}  // namespace dc::dynamics
