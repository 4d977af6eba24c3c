// Where a step's Newton iteration starts and which Jacobian it uses (issue: one warm-started
// contact solve per step): the start extrapolated through the last accepted states
// (StepperOptions::predicted_start_share), an x accepted without an exact Newton update only
// within a tenth of the tolerance (NewtonOptions::inexact_share), and chord steps with a kept
// Jacobian checked by the contraction of the residual (NewtonOptions::chord_contraction).
#include <gtest/gtest.h>

#include <cmath>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"
#include "newton6.hpp"
#include "time_stepper.hpp"

namespace dc::dynamics {
namespace {

/// r(x) = A x + 0.1 x.*x - b: mildly nonlinear, its exact Jacobian A + 0.2 diag(x) when asked
/// fresh; a `kept` matrix otherwise (when one is given).
class ChordTestSystem final : public System6 {
 public:
  ChordTestSystem() {
    A_ = Matrix6d::Identity() * 4.0;
    for (int i = 0; i < 5; ++i) A_(i, i + 1) = A_(i + 1, i) = 1.0;
    b_ << 1.0, -2.0, 0.5, 3.0, -1.0, 2.0;
  }
  Vector6d residual(const Vector6d& x) const override {
    ++residuals;
    return A_ * x + 0.1 * x.cwiseProduct(x) - b_;
  }
  JacobianSource jacobian(const Vector6d& x, Matrix6d& J, bool fresh) const override {
    if (!fresh && has_kept) {
      J = kept;
      return JacobianSource::kept;
    }
    ++fresh_jacobians;
    J = A_;
    J.diagonal() += 0.2 * x;
    return JacobianSource::computed;
  }
  Matrix6d exact_at(const Vector6d& x) const {
    Matrix6d J = A_;
    J.diagonal() += 0.2 * x;
    return J;
  }
  Matrix6d kept = Matrix6d::Zero();
  bool has_kept = false;
  mutable int residuals = 0, fresh_jacobians = 0;

 private:
  Matrix6d A_;
  Vector6d b_;
};

/// Solves `system` from x = 0 with chord steps on, accepted (like a start) within a tenth of a
/// tolerance of 1e-12 relative; `tolerance` is that tolerance (Newton's scale: |r(0)|).
NewtonResult solve_with_chords(const ChordTestSystem& system, Vector6d& x, double& tolerance) {
  NewtonOptions options;
  options.rel_tol = 1e-12;
  options.chord_contraction = 0.1;
  options.inexact_share = 0.1;
  tolerance = options.rel_tol * std::max(1.0, system.residual(Vector6d::Zero()).norm());
  x = Vector6d::Zero();
  return solve_newton6(system, x, 1.0, options);
}

TEST(StepStartNewton, ChordStepsWithANearbyJacobianConvergeWithoutAFreshOne) {
  ChordTestSystem system;
  system.kept = system.exact_at(Vector6d::Constant(0.3));  // the Jacobian of another point
  system.has_kept = true;
  Vector6d x;
  double tolerance = 0.0;
  const NewtonResult r = solve_with_chords(system, x, tolerance);
  ASSERT_EQ(r.status, NewtonStatus::converged);
  EXPECT_EQ(system.fresh_jacobians, 0);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_GE(r.chord_steps, 2);
  // Accepted after chord steps only within a tenth of the tolerance.
  EXPECT_LE(system.residual(x).norm(), 0.1 * tolerance);
}

TEST(StepStartNewton, AKeptJacobianThatDoesNotContractIsReplacedByAFreshOne) {
  ChordTestSystem system;
  system.kept = -system.exact_at(Vector6d::Zero());  // the wrong sign: its step grows |r|
  system.has_kept = true;
  Vector6d x;
  double tolerance = 0.0;
  const NewtonResult r = solve_with_chords(system, x, tolerance);
  ASSERT_EQ(r.status, NewtonStatus::converged);
  EXPECT_EQ(r.chord_steps, 1);  // tried once, refused
  EXPECT_GE(system.fresh_jacobians, 1);
  EXPECT_LE(r.iterations, 5);  // then Newton's quadratic convergence
  EXPECT_LE(system.residual(x).norm(), tolerance);
}

TEST(StepStartNewton, AStartWithinTheToleranceButNotItsTenthGetsAnUpdate) {
  ChordTestSystem system;
  Vector6d solution = Vector6d::Zero();
  NewtonOptions tight;
  tight.rel_tol = 1e-15;
  ASSERT_EQ(solve_newton6(system, solution, 1.0, tight).status, NewtonStatus::converged);
  // A start whose residual is half the tolerance (scale 1: tolerance = rel_tol).
  const Vector6d direction = Vector6d::Ones().normalized();
  NewtonOptions options;
  options.rel_tol = 1e-6;
  const Vector6d start =
      solution + 0.5e-6 * system.exact_at(solution).inverse() * direction;
  const double r0 = system.residual(start).norm();
  ASSERT_GT(r0, 0.1e-6);
  ASSERT_LT(r0, 1e-6);
  Vector6d x = start;
  EXPECT_EQ(solve_newton6(system, x, 1.0, options).iterations, 0);  // inexact_share 1: as it is
  options.inexact_share = 0.1;
  x = start;
  const NewtonResult r = solve_newton6(system, x, 1.0, options);
  EXPECT_EQ(r.status, NewtonStatus::converged);
  EXPECT_EQ(r.iterations, 1);
}

// A free body under a constant force: V(t) = V0 + F t / m is linear, which the extrapolation
// (quadratic from the third step) reproduces to round-off, so every later step is accepted at
// its start with one wrench evaluation and no Newton update; without the extrapolation every
// step needs one. Both give the closed form (bdf1 and bdf2 are exact for a linear V).
TEST(StepStartPredictor, ConstantForceStepsAreAcceptedAtTheExtrapolatedStart) {
  const RigidBody body = RigidBody::principal(2.0, 1.0, 1.0, 1.0);
  const Eigen::Vector3d F(3.0, -1.0, -19.6);
  const WrenchFunction wrench = [&](const StepKinematics&) { return Wrench{F, Eigen::Vector3d::Zero()}; };
  for (const double share : {0.1, 0.0}) {
    StepperOptions options;
    options.predicted_start_share = share;
    options.newton.rel_tol = 1e-10;
    RigidBodyStepper stepper(body, options);
    RigidBodyState s;
    s.velocity = Eigen::Vector3d(1.0, 0.5, 2.0);
    const Eigen::Vector3d v0 = s.velocity;
    const double dt = 1e-3;
    int updates_after_start = 0, evaluations_after_start = 0;
    for (int k = 0; k < 50; ++k) {
      const StepReport r = stepper.step(s, dt, wrench);
      ASSERT_TRUE(r.converged()) << k;
      if (k >= 3) {
        updates_after_start += r.iterations;
        evaluations_after_start += r.wrench_evaluations;
      }
    }
    EXPECT_LE((s.velocity - (v0 + F * s.time / body.mass())).norm(), 1e-12 * v0.norm()) << share;
    if (share > 0.0) {
      EXPECT_EQ(updates_after_start, 0);
      EXPECT_EQ(evaluations_after_start, 47);
    } else {
      EXPECT_EQ(updates_after_start, 47);
    }
  }
}

// The rolling ball (kappa != 0, transient contact) on a coarse grid: its steps reuse one
// tangential sensitivity through chord steps, and a steady step costs at most about two
// contact solves (the extrapolated start and one chord step); the physics tests of the same
// ball (test_dynamic_newton, test_dynamic_*) run through the same path.
TEST(StepStartChord, RollingSphereStepsReuseTheSensitivity) {
  nlohmann::json doc = dc::test::example_json("bowling-ball");
  doc["grid"]["nx"] = doc["grid"]["ny"] = 16;
  doc["time"] = {{"dt", 1e-4}, {"t_end", 8e-3}, {"scheme", "bdf2"}};
  doc["contact_model"] = "transient";
  const double V = 3.0, R = doc["body"]["radius"].get<double>();
  doc["body"]["initial"]["velocity"] = {V, 0, 0};
  doc["body"]["initial"]["omega"] = {0, V / R, 0};  // rolling
  const Case c = build_case(doc);
  ASSERT_NE(c.materials.kappa(), 0.0);
  DynamicSimulation sim(c);
  const DynamicResult r = sim.run({});
  ASSERT_TRUE(r.completed) << r.status;
  EXPECT_EQ(r.rejected_steps, 0);
  EXPECT_GT(r.chord_steps, r.steps / 2);
  EXPECT_LE(r.sensitivities, r.steps / 10);
  EXPECT_LE(r.contact_solves, 2.1 * r.steps);
  EXPECT_LE(r.worst_certificate, c.solver.certificate_tol);
}

// The steady model's solve (Newton on the steady equations, steady_rolling_solver) starts from
// the last solve's traction, as a creep-force table's neighbouring point does: the 2-D
// Section 5 cylinder, whose creepage grows slowly with the driving moment, then takes a
// Newton iteration or two per solve where a cold start takes about six.
TEST(StepStartSteady, SteadySolvesStartFromTheLastTraction) {
  nlohmann::json doc = dc::test::example_json("cylinder-dynamic-2d");
  doc["time"]["dt"] = 0.005;
  doc["time"]["t_end"] = 0.5;
  doc["grid"]["nx"] = 200;
  const Case c = build_case(doc);
  DynamicSimulation sim(c);
  int newton = 0, steps = 0;
  const DynamicResult r = sim.run([&](const DynamicSample& s) {
    ASSERT_NE(s.contact_state.fields, nullptr);
    newton += s.contact_state.fields->newton_iterations;  // of the step's last solve
    ++steps;
  });
  ASSERT_TRUE(r.completed) << r.status;
  EXPECT_EQ(r.contact_model, "steady");
  EXPECT_LE(r.worst_certificate, c.solver.certificate_tol);
  EXPECT_LE(newton, 2 * steps);  // 1.4 per step; 7.5 from a cold start
}

}  // namespace
}  // namespace dc::dynamics
