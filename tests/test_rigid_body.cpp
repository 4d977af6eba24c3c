// The rigid-body stepper (dynamics/): Newton-Euler (2.20)-(2.21) by backward differences
// (3.9)-(3.10), against closed forms. Tolerances follow from the schemes' orders (bdf1: O(dt),
// bdf2: O(dt^2)), from the creep law's regularisation time tau, and from the Newton tolerance
// (rel_tol per step, so at most steps * rel_tol accumulated on a conserved quantity).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "errors.hpp"
#include "rigid_body.hpp"
#include "rotation.hpp"
#include "time_stepper.hpp"

namespace dc::dynamics {
namespace {

using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

/// Steps n times; every step must converge (the report is checked, never ignored).
template <class Observer>
RigidBodyState simulate(RigidBodyStepper& stepper, RigidBodyState state, double dt, int n,
                        const WrenchFunction& wrench, Observer&& observe) {
  for (int i = 0; i < n; ++i) {
    const StepReport report = stepper.step(state, dt, wrench);
    EXPECT_TRUE(report.converged()) << "step " << i << ": " << to_string(report.status)
                                    << ", residual " << report.residual;
    if (!report.converged()) break;
    observe(state, report);
  }
  return state;
}

RigidBodyState simulate(RigidBodyStepper& stepper, const RigidBodyState& state, double dt, int n,
                        const WrenchFunction& wrench) {
  return simulate(stepper, state, dt, n, wrench, [](const RigidBodyState&, const StepReport&) {});
}

double observed_order(double error_dt, double error_half_dt) {
  return std::log2(error_dt / error_half_dt);
}

std::string scheme_name(const ::testing::TestParamInfo<Scheme>& p) { return to_string(p.param); }

}  // namespace

// How GoogleTest (and so ctest's test names) prints the parameters: words, not raw bytes.
void PrintTo(Scheme s, std::ostream* os) { *os << to_string(s); }

namespace {

StepperOptions with_scheme(Scheme scheme) {
  StepperOptions options;
  options.scheme = scheme;
  return options;
}

// ---------------------------------------------------------------------------------------------
// Free flight under gravity: R(t) = R0 + V0 t + g t^2/2, V(t) = V0 + g t.

class FreeFlight : public ::testing::TestWithParam<Scheme> {
 protected:
  const RigidBody body = RigidBody::principal(2.0, 0.1, 0.2, 0.25);
  const Vector3d g{0.0, 0.0, -9.81};
  const Vector3d r0{0.1, 0.2, 0.3}, v0{3.0, 1.0, 5.0};
  static constexpr double T = 1.0;

  /// Position and velocity errors at T with n steps.
  std::pair<double, double> errors(int n) const {
    RigidBodyStepper stepper(body, with_scheme(GetParam()));
    RigidBodyState s;
    s.position = r0;
    s.velocity = v0;
    s.omega = Vector3d(0.0, 0.0, 4.0);  // a spin about a principal axis must not matter
    const double m = body.mass();
    const Vector3d gravity = m * g;
    const RigidBodyState end = simulate(stepper, s, T / n, n, [&](const StepKinematics&) {
      return Wrench{gravity, Vector3d::Zero()};
    });
    EXPECT_NEAR(end.time, T, 1e-12);
    return {(end.position - (r0 + v0 * T + 0.5 * g * T * T)).norm(),
            (end.velocity - (v0 + g * T)).norm()};
  }
};

TEST_P(FreeFlight, ParabolaWithTheSchemesOrder) {
  const int n = 100;
  const double dt = T / n;
  const auto [e1, ev1] = errors(n);
  const auto [e2, ev2] = errors(2 * n);
  // V is linear in t: both backward differences reproduce it up to the Newton tolerance per step
  // (rel_tol * |V|), at most n * rel_tol * |V| in all.
  const double v_bound = n * StepperOptions{}.newton.rel_tol * (v0.norm() + g.norm() * T);
  EXPECT_LE(ev1, v_bound);
  EXPECT_LE(ev2, 2 * v_bound);
  if (GetParam() == Scheme::bdf1) {
    // R_n = R0 + dt sum V_k: error exactly |g| T dt / 2 (the O(dt) error of (3.1)).
    EXPECT_NEAR(e1, 0.5 * g.norm() * T * dt, 1e-6 * e1);
    EXPECT_NEAR(observed_order(e1, e2), 1.0, 0.02);
  } else {
    // The bdf1 start step errs by |g| dt^2/2; bdf2 carries it as e_K = 4/3 e_{K-1} - 1/3 e_{K-2}
    // towards 3/2 of it: |error| <= 3/4 |g| dt^2.
    EXPECT_LE(e1, 0.75 * g.norm() * dt * dt * (1.0 + 1e-6));
    EXPECT_NEAR(observed_order(e1, e2), 2.0, 0.05);
  }
}

INSTANTIATE_TEST_SUITE_P(Schemes, FreeFlight, ::testing::Values(Scheme::bdf1, Scheme::bdf2),
                         scheme_name);

// ---------------------------------------------------------------------------------------------
// Torque-free symmetric top, I1 = I2: in body axes Omega = (a cos(wp t), a sin(wp t), w3) with
// the precession rate wp = (I3 - I1)/I1 w3 (Euler's equations); L_world is constant.

class SymmetricTop : public ::testing::TestWithParam<Scheme> {
 protected:
  static constexpr double I1 = 0.5, I3 = 0.8, w3 = 2.0 * kPi, a = 0.3 * w3;
  static constexpr double wp = (I3 - I1) / I1 * w3;
  const RigidBody body = RigidBody::principal(1.0, I1, I1, I3);
  const double T = 3.0 * 2.0 * kPi / wp;  // three precession periods
  const Eigen::Quaterniond q0 =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vector3d(1.0, -2.0, 0.5).normalized()));

  struct Result {
    double phase_error;     ///< |Omega_body(T) - closed form| / |Omega|
    double momentum_drift;  ///< max |L(t) - L(0)| / |L(0)|
    double energy_change;   ///< (E(T) - E(0)) / E(0)
    double energy_rise;     ///< max step-to-step increase of E, / E(0)
  };

  Result run(int n) const {
    RigidBodyStepper stepper(body, with_scheme(GetParam()));
    RigidBodyState s;
    s.orientation = q0;
    s.omega = q0 * Vector3d(a, 0.0, w3);  // world frame
    const Vector3d L0 = angular_momentum(body, s);
    const double E0 = kinetic_energy(body, s);
    Result r{0.0, 0.0, 0.0, 0.0};
    double e_prev = E0;
    const RigidBodyState end =
        simulate(stepper, s, T / n, n, [](const StepKinematics&) { return Wrench{}; },
                 [&](const RigidBodyState& st, const StepReport&) {
                   r.momentum_drift = std::max(
                       r.momentum_drift, (angular_momentum(body, st) - L0).norm() / L0.norm());
                   const double e = kinetic_energy(body, st);
                   r.energy_rise = std::max(r.energy_rise, (e - e_prev) / E0);
                   e_prev = e;
                 });
    const Vector3d exact(a * std::cos(wp * end.time), a * std::sin(wp * end.time), w3);
    r.phase_error = (end.omega_body() - exact).norm() / exact.norm();
    r.energy_change = (kinetic_energy(body, end) - E0) / E0;
    return r;
  }
};

TEST_P(SymmetricTop, MomentumConservedAndPrecessionAtTheClosedFormRate) {
  // bdf1's O(dt) terms carry large O(dt^2) companions: it is asymptotic (orders within 0.1 of 1)
  // from ~2000 steps per precession period; bdf2 from ~500.
  const int n = GetParam() == Scheme::bdf1 ? 6000 : 1500;
  const Result coarse = run(n), fine = run(2 * n);
  // (3.10) is written for L_world, so with M = 0 it holds L fixed up to the Newton tolerance:
  // at most steps * rel_tol.
  const double rel_tol = StepperOptions{}.newton.rel_tol;
  EXPECT_LE(coarse.momentum_drift, n * rel_tol);
  EXPECT_LE(fine.momentum_drift, 2 * n * rel_tol);
  const double expected_order = GetParam() == Scheme::bdf1 ? 1.0 : 2.0;
  EXPECT_NEAR(observed_order(coarse.phase_error, fine.phase_error), expected_order, 0.1);
  if (GetParam() == Scheme::bdf1) {
    // Backward Euler dissipates: E never rises (beyond round-off) and the loss is O(dt).
    EXPECT_LE(coarse.energy_rise, 1e-12);
    EXPECT_LT(coarse.energy_change, 0.0);
    EXPECT_NEAR(observed_order(-coarse.energy_change, -fine.energy_change), 1.0, 0.1);
    EXPECT_LT(fine.phase_error, 0.02);
  } else {
    EXPECT_NEAR(observed_order(std::abs(coarse.energy_change), std::abs(fine.energy_change)), 2.0,
                0.3);
    EXPECT_LT(fine.phase_error, 1e-3);
  }
}

INSTANTIATE_TEST_SUITE_P(Schemes, SymmetricTop, ::testing::Values(Scheme::bdf1, Scheme::bdf2),
                         scheme_name);

// ---------------------------------------------------------------------------------------------
// Free rotation about a principal axis of I = diag(2, 3, 4): stable about the minor and major
// axes, unstable about the intermediate one (growth rate w sqrt((I2-I1)(I3-I2)/(I1 I3)) = 0.35 w).

double max_axis_deviation(int axis, Scheme scheme) {
  const RigidBody body = RigidBody::principal(1.0, 2.0, 3.0, 4.0);
  RigidBodyStepper stepper(body, with_scheme(scheme));
  const double w = 2.0 * kPi;
  RigidBodyState s;
  s.omega = Vector3d::Constant(1e-6 * w);  // perturbation 1e-6 off the axis
  s.omega(axis) = w;
  double deviation = 0.0;
  const int steps_per_turn = 200, turns = 10;
  simulate(stepper, s, 1.0 / steps_per_turn, steps_per_turn * turns,
           [](const StepKinematics&) { return Wrench{}; },
           [&](const RigidBodyState& st, const StepReport&) {
             const Vector3d wb = st.omega_body();
             deviation = std::max(deviation, std::acos(std::min(1.0, std::abs(wb(axis)) / wb.norm())));
           });
  return deviation;
}

TEST(TennisRacket, IntermediateAxisUnstableMajorAndMinorStable) {
  // Stable: the perturbation stays within a factor 100 (bounded by sqrt of inertia ratios ~ 2);
  // unstable: exp(0.35 * 2 pi * 10) ~ 4e9 growth saturates at an O(1) angle (> 0.5 rad).
  EXPECT_LT(max_axis_deviation(0, Scheme::bdf2), 1e-4);
  EXPECT_LT(max_axis_deviation(2, Scheme::bdf2), 1e-4);
  EXPECT_GT(max_axis_deviation(1, Scheme::bdf2), 0.5);
}

// ---------------------------------------------------------------------------------------------
// A sphere (radius r, I = 2/5 m r^2) on a rigid floor, launched sliding at v0 without spin.
// Friction at the contact point c = (0, 0, -r) from the COM: the creep law F_t = -k s on the slip
// s = V + Omega x c, capped at mu N (a regularised Coulomb law). The slip relaxes with
// tau = 2m / (7k) (ds/dt = -k s (1/m + r^2/I)). Rigid closed form (VALIDATION.md): rolling
// from t* = 2 v0 / (7 mu g) at 5 v0 / 7.

struct SphereOnFloor {
  double m = 1.0, r = 0.05, mu = 0.3, g = 9.81, v0 = 2.0;
  double k = 0.0;       ///< creep stiffness (N s/m)
  bool capped = true;   ///< cap |F_t| at mu m g (Coulomb); uncapped: the linear creep law
  RigidBody body() const { return RigidBody::principal(m, 0.4 * m * r * r, 0.4 * m * r * r, 0.4 * m * r * r); }
  double tau() const { return 2.0 * m / (7.0 * k); }
  double t_star() const { return 2.0 * v0 / (7.0 * mu * g); }
  /// The creep stiffness that makes tau the given fraction of t*.
  static SphereOnFloor with_tau(double tau_over_t_star, bool capped) {
    SphereOnFloor s;
    s.capped = capped;
    s.k = 2.0 * s.m / (7.0 * tau_over_t_star * s.t_star());
    return s;
  }
  Vector3d contact() const { return Vector3d(0.0, 0.0, -r); }
  Vector3d slip(const Vector3d& v, const Vector3d& omega) const { return v + omega.cross(contact()); }
  Wrench wrench(const Vector3d& v, const Vector3d& omega) const {
    const Vector3d s = slip(v, omega);
    Vector3d friction = -k * s;
    const double limit = mu * m * g;
    if (capped && friction.norm() > limit) friction *= limit / friction.norm();
    // gravity + floor reaction (N = m g) + friction; moment of the friction about the COM
    return Wrench{friction, contact().cross(friction)};
  }
  RigidBodyState launch() const {
    RigidBodyState s;
    s.position = Vector3d(0.0, 0.0, r);
    s.velocity = Vector3d(v0, 0.0, 0.0);
    return s;
  }
};

struct SlidingCase {
  Scheme scheme;
  double tau_over_tstar;
  double dt_over_tau;
};

void PrintTo(const SlidingCase& c, std::ostream* os) {
  *os << to_string(c.scheme) << ", tau/t* " << c.tau_over_tstar << ", dt/tau " << c.dt_over_tau;
}

class SlidingSphere : public ::testing::TestWithParam<SlidingCase> {};

TEST_P(SlidingSphere, RollsFromTwoSeventhsAtFiveSevenths) {
  const SlidingCase c = GetParam();
  const SphereOnFloor sphere = SphereOnFloor::with_tau(c.tau_over_tstar, true);
  const double ts = sphere.t_star(), tau = sphere.tau(), dt = c.dt_over_tau * tau;
  const double mu_g = sphere.mu * sphere.g, v0 = sphere.v0;
  RigidBodyStepper stepper(sphere.body(), with_scheme(c.scheme));
  const int n = static_cast<int>(std::ceil(2.0 * ts / dt));
  double max_v_error = 0.0, max_slip_error = 0.0, t_onset = -1.0;
  int max_iterations = 0, total_iterations = 0;
  const RigidBodyState end = simulate(
      stepper, sphere.launch(), dt, n,
      [&](const StepKinematics& k) { return sphere.wrench(k.velocity, k.omega); },
      [&](const RigidBodyState& st, const StepReport& report) {
        max_iterations = std::max(max_iterations, report.iterations);
        total_iterations += report.iterations;
        const double t = st.time;
        const double v_rigid = t < ts ? v0 - mu_g * t : 5.0 * v0 / 7.0;
        const double s_rigid = t < ts ? v0 - 3.5 * mu_g * t : 0.0;
        max_v_error = std::max(max_v_error, std::abs(st.velocity.x() - v_rigid));
        max_slip_error = std::max(max_slip_error,
                                  (sphere.slip(st.velocity, st.omega) - Vector3d(s_rigid, 0, 0)).norm());
        const double friction = sphere.wrench(st.velocity, st.omega).force.norm();
        if (t_onset < 0.0 && friction < sphere.mu * sphere.m * sphere.g * (1.0 - 1e-9)) t_onset = t;
      });
  // While sliding the force is constant, so V and Omega are exact (linear in t) for both schemes;
  // the slip reaches the end of the cap, s_c = mu m g / k = 7/2 mu g tau, at t* - tau, and the
  // first step end past it is where the friction drops below mu m g.
  EXPECT_GE(t_onset, ts - tau - 1e-12 * ts);
  EXPECT_LE(t_onset, ts - tau + dt * (1.0 + 1e-9));
  // Afterwards V - 5v0/7 = 2/7 s with |s| <= s_c (the implicit creep phase only relaxes the
  // slip), so |V - V_rigid| <= 2/7 s_c = mu g tau and |s - s_rigid| <= s_c, whatever dt / tau.
  EXPECT_LE(max_v_error, mu_g * tau * (1.0 + 1e-9));
  EXPECT_LE(max_slip_error, 3.5 * mu_g * tau * (1.0 + 1e-9));
  // V r + (2/5) r^2 Omega_y (angular momentum about the contact point / m) is conserved exactly by
  // the linear schemes; by t = 2t* the slip has relaxed (exp(-t*/tau)), so V = 5 v0/7 up to the
  // Newton tolerance accumulated over the steps.
  EXPECT_NEAR(end.velocity.x(), 5.0 * v0 / 7.0, n * StepperOptions{}.newton.rel_tol * v0 + 1e-6 * v0 * std::exp(-(end.time - ts) / tau));
  EXPECT_NEAR(end.omega.y() * sphere.r, 5.0 * v0 / 7.0, n * StepperOptions{}.newton.rel_tol * v0 + 1e-6 * v0 * std::exp(-(end.time - ts) / tau));
  // Within one regime of the law (capped, or linear) the residual is linear in the unknowns: one
  // Newton update (two with the finite-difference Jacobian's error); only the steps that cross
  // the cap's kink need more.
  EXPECT_LE(double(total_iterations) / n, 2.0);
  RecordProperty("mean_newton_iterations", std::to_string(double(total_iterations) / n));
  RecordProperty("max_newton_iterations", std::to_string(max_iterations));
  RecordProperty("max_v_error_over_mu_g_tau", std::to_string(max_v_error / (mu_g * tau)));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SlidingSphere,
    ::testing::Values(SlidingCase{Scheme::bdf1, 1e-2, 0.5}, SlidingCase{Scheme::bdf2, 1e-2, 0.5},
                      SlidingCase{Scheme::bdf1, 1e-3, 100.0}, SlidingCase{Scheme::bdf2, 1e-3, 100.0}),
    [](const ::testing::TestParamInfo<SlidingCase>& p) {
      return std::string(to_string(p.param.scheme)) +
             (p.param.dt_over_tau > 1.0 ? "_stiff_dt100tau" : "_resolved_tau");
    });

// ---------------------------------------------------------------------------------------------
// Stiffness: the uncapped linear creep law with tau = 1e-3 of the motion time t*, dt = 100 tau.
// Implicit: the slip is damped (bdf1 by 1/(1 + dt/tau) per step). Explicit staggering (the wrench
// from the start-of-step kinematics) multiplies the slip by (1 - dt/tau) = -99 per step.

TEST(Stiffness, ImplicitStableWhereExplicitStaggeringBlowsUp) {
  const SphereOnFloor sphere = SphereOnFloor::with_tau(1e-3, false);
  const double tau = sphere.tau(), dt = 100.0 * tau, v0 = sphere.v0;
  const int n = 20;
  const auto wrench = [&](const StepKinematics& k) { return sphere.wrench(k.velocity, k.omega); };
  for (Scheme scheme : {Scheme::bdf1, Scheme::bdf2}) {
    RigidBodyStepper stepper(sphere.body(), with_scheme(scheme));
    double max_slip = 0.0;
    const RigidBodyState end = simulate(stepper, sphere.launch(), dt, n, wrench,
                                        [&](const RigidBodyState& st, const StepReport&) {
                                          max_slip = std::max(max_slip, sphere.slip(st.velocity, st.omega).norm());
                                        });
    // bdf1: |s_1| = v0/101; bdf2 (after its bdf1 start): roots of modulus ~0.07. Either way
    // bounded by the first step and relaxed to round-off after 20 steps.
    EXPECT_LE(max_slip, v0 / 100.0) << to_string(scheme);
    EXPECT_LE(sphere.slip(end.velocity, end.omega).norm(), 1e-9 * v0) << to_string(scheme);
    EXPECT_NEAR(end.velocity.x(), 5.0 * v0 / 7.0, 1e-8 * v0) << to_string(scheme);
  }
  // The explicit staggered update with the same dt.
  RigidBodyState s = sphere.launch();
  const RigidBody body = sphere.body();
  int blow_up_step = -1;
  for (int i = 0; i < n && blow_up_step < 0; ++i) {
    const Wrench w = sphere.wrench(s.velocity, s.omega);  // start-of-step kinematics
    s.velocity += dt / body.mass() * w.force;
    s.omega += dt * (body.inverse_inertia_body() * w.moment);  // sphere: I_world = I_body
    s.position += dt * s.velocity;
    if (!(sphere.slip(s.velocity, s.omega).norm() < 1e6 * v0)) blow_up_step = i;
  }
  // |s_K| = 99^K v0 exceeds 1e6 v0 at K = 4 (index 3).
  EXPECT_EQ(blow_up_step, 3);
}

// ---------------------------------------------------------------------------------------------
// Non-convergence is reported and leaves the state alone.

TEST(StepReport, NonConvergenceIsReportedAndTheStateKept) {
  const RigidBody body = RigidBody::principal(1.0, 1.0, 1.0, 1.0);
  RigidBodyState s;
  s.velocity = Vector3d(1.0, 0.0, 0.0);
  const RigidBodyState before = s;
  {
    RigidBodyStepper stepper(body);
    const StepReport r = stepper.step(s, 0.1, [](const StepKinematics&) {
      return Wrench{Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()), Vector3d::Zero()};
    });
    EXPECT_EQ(r.status, NewtonStatus::non_finite);
    EXPECT_EQ(s.time, before.time);
    EXPECT_EQ(s.velocity, before.velocity);
  }
  {
    StepperOptions options;
    options.newton.max_iterations = 0;
    RigidBodyStepper stepper(body, options);
    const StepReport r = stepper.step(s, 0.1, [](const StepKinematics& k) {
      return Wrench{-k.velocity, Vector3d::Zero()};  // needs one Newton update
    });
    EXPECT_EQ(r.status, NewtonStatus::max_iterations);
    EXPECT_GT(r.residual, 0.0);
    EXPECT_EQ(s.velocity, before.velocity);
  }
}

// ---------------------------------------------------------------------------------------------

TEST(Rotation, ExpLogRoundTrip) {
  for (const Vector3d& phi : {Vector3d(0.3, -1.2, 2.0), Vector3d(1e-9, 2e-9, -1e-9),
                              Vector3d(0.0, 0.0, 3.1), Vector3d::Zero().eval()}) {
    EXPECT_LE((log_map(exp_map(phi)) - phi).norm(), 1e-14 * (1.0 + phi.norm())) << phi.transpose();
    const Eigen::AngleAxisd reference(phi.norm(), phi.norm() > 0 ? phi.normalized() : Vector3d::UnitX().eval());
    EXPECT_LE((exp_map(phi).toRotationMatrix() - reference.toRotationMatrix()).norm(), 1e-15);
  }
}

// ---------------------------------------------------------------------------------------------

std::string thrown_key(auto&& make) {
  try {
    make();
  } catch (const InputError& e) {
    return e.key();
  }
  return "(nothing thrown)";
}

TEST(RigidBodyInput, BadMassOrInertiaNamesTheKey) {
  EXPECT_EQ(thrown_key([] { RigidBody::principal(0.0, 1, 1, 1); }), "body.mass");
  EXPECT_EQ(thrown_key([] { RigidBody::principal(-2.0, 1, 1, 1); }), "body.mass");
  EXPECT_EQ(thrown_key([] { RigidBody::principal(std::nan(""), 1, 1, 1); }), "body.mass");
  EXPECT_EQ(thrown_key([] { RigidBody::principal(1.0, 1, 1, 1, "bodies.wheel"); }),
            "(nothing thrown)");
  EXPECT_EQ(thrown_key([] { RigidBody::principal(0.0, 1, 1, 1, "bodies.wheel"); }),
            "bodies.wheel.mass");
  EXPECT_EQ(thrown_key([] { RigidBody::principal(1.0, 1, 1, -0.5); }), "body.inertia");
  EXPECT_EQ(thrown_key([] { RigidBody::principal(1.0, 1, 1, 0.0); }), "body.inertia");
  EXPECT_EQ(thrown_key([] { RigidBody::principal(1.0, 1, 1, 3.0); }), "body.inertia");  // 1+1 < 3
  EXPECT_EQ(thrown_key([] { RigidBody::principal(1.0, 1, 1, 2.0); }), "(nothing thrown)");  // lamina
  Eigen::Matrix3d indefinite;  // symmetric, eigenvalues 3, 1, -1
  indefinite << 1, 2, 0, 2, 1, 0, 0, 0, 1;
  EXPECT_EQ(thrown_key([&] { RigidBody(1.0, indefinite); }), "body.inertia");
  Eigen::Matrix3d unsymmetric = Eigen::Matrix3d::Identity();
  unsymmetric(0, 1) = 0.1;
  EXPECT_EQ(thrown_key([&] { RigidBody(1.0, unsymmetric); }), "body.inertia");

  RigidBodyStepper stepper(RigidBody::principal(1.0, 1, 1, 1));
  RigidBodyState s;
  const WrenchFunction none = [](const StepKinematics&) { return Wrench{}; };
  EXPECT_EQ(thrown_key([&] { (void)stepper.step(s, 0.0, none); }), "dt");
  s.orientation.coeffs() *= 2.0;
  EXPECT_EQ(thrown_key([&] { (void)stepper.step(s, 0.1, none); }), "state.orientation");
}

}  // namespace
}  // namespace dc::dynamics
