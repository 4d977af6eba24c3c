// time.adaptive (docs/dynamics.md "Adaptive time steps"): the keys read and their bad values
// named; the local error estimate of a step against a motion whose third derivative is known;
// a first touch located within the event tolerance of the analytic touch time, and the end of
// a bowling ball's gross sliding; rejections
// counted; a tolerance that cannot be met at time.dt_min stopping the run; and a coarse adaptive
// impact within the grid's budget of Hertz. slow_dynamic_adaptive.cpp compares step counts
// with fixed steps at equal accuracy.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"
#include "errors.hpp"
#include "impact_measure.hpp"
#include "step_size_control.hpp"

namespace dc::dynamics {
namespace {

using nlohmann::json;

json adaptive_time(double dt, double t_end, double rtol) {
  return {{"dt", dt}, {"t_end", t_end}, {"scheme", "bdf2"}, {"adaptive", true}, {"rtol", rtol}};
}

TEST(DynamicAdaptive, ReadsTheKeysAndTheirDefaults) {
  json doc = dc::test::ball_impact(12, 0.0, {{"dt", 1e-6}, {"t_end", 8e-5}, {"adaptive", true}});
  const Case c = build_case(doc);
  ASSERT_TRUE(c.dynamic->adaptive);
  EXPECT_EQ(c.dynamic->rtol, 1e-4);
  EXPECT_EQ(c.dynamic->atol, 1e-9);
  EXPECT_DOUBLE_EQ(c.dynamic->dt_min, 1e-12);  // 1e-6 dt
  EXPECT_DOUBLE_EQ(c.dynamic->dt_max, 8e-6);   // t_end / 10
  doc["time"] = {{"dt", 1e-5}, {"t_end", 1e-3}, {"scheme", "bdf2"}, {"adaptive", true},
                 {"rtol", 1e-3}, {"atol", 1e-8}, {"dt_min", 1e-9}, {"dt_max", 1e-4}};
  const Case d = build_case(doc);
  EXPECT_EQ(d.dynamic->rtol, 1e-3);
  EXPECT_EQ(d.dynamic->atol, 1e-8);  // m/s
  EXPECT_EQ(d.dynamic->dt_min, 1e-9);
  EXPECT_EQ(d.dynamic->dt_max, 1e-4);
  doc["time"] = {{"dt", 1e-6}, {"t_end", 8e-5}};
  EXPECT_FALSE(build_case(doc).dynamic->adaptive);
}

TEST(DynamicAdaptive, BadTimeKeysAreInputErrorsNamingTheKey) {
  const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
      {[](json& t) { t["rtol"] = 0.0; }, "time.rtol"},
      {[](json& t) { t["rtol"] = -1e-3; }, "time.rtol"},
      {[](json& t) { t["rtol"] = 0.5; }, "time.rtol"},
      {[](json& t) { t["rtol"] = "tight"; }, "time.rtol"},
      {[](json& t) { t["atol"] = 0.0; }, "time.atol"},
      {[](json& t) { t["atol"] = -1.0; }, "time.atol"},
      {[](json& t) { t["dt_min"] = 0.0; }, "time.dt_min"},
      {[](json& t) { t["dt_min"] = 2e-6; }, "time.dt_min"},  // above the first step
      {[](json& t) { t["dt_min"] = 1e-20; }, "time.dt_min"},  // below the time's resolution
      {[](json& t) { t["dt_max"] = 5e-7; }, "time.dt_max"},  // below the first step
      {[](json& t) { t["adaptive"] = "yes"; }, "time.adaptive"},
      {[](json& t) { t["adaptive"] = false; }, "time.rtol"},  // a tolerance without adaptive steps
      {[](json& t) { t["adaptive_steps"] = true; }, "time.adaptive_steps"},
  };
  for (const auto& [edit, key] : cases) {
    json doc = dc::test::ball_impact(12, 0.0, adaptive_time(1e-6, 8e-5, 1e-3));
    edit(doc["time"]);
    try {
      (void)build_case(doc);
      ADD_FAILURE() << "accepted " << doc["time"].dump();
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
    }
  }
}

TEST(DynamicAdaptive, ErrorEstimateMatchesTheSchemesTruncationError) {
  // x(t) = t^3 (V = 3 t^2, a = 6 t): bdf1 errs by h^2/2 y'' per step, the estimate
  // 1/2 (y_c - y_p) to leading order; bdf2 (constant step) by 2/9 h^3 x''', and (2/5)(y_c - y_p)
  // is exact for a cubic. The "solution" is the scheme's own answer from exact history.
  const RigidBody body = RigidBody::principal(1.0, 1.0, 1.0, 1.0);
  StepSizeOptions o;
  o.rtol = 0.0;
  o.atol = 1.0;  // the norm: sqrt(((e_R / h)^2 + e_V^2) / 9), positions per unit step
  const double h = 0.01, t0 = 1.0;
  auto point = [&](double t) {
    RigidBodyState s;
    s.time = t;
    s.position.x() = t * t * t;
    s.velocity.x() = 3 * t * t;
    Wrench w;
    w.force.x() = 6 * t;
    return trajectory_point(body, s, w);
  };
  LocalErrorEstimate estimate(body.gyration_radius());
  estimate.restart(point(t0));
  // bdf1 (3.1): V1 = V0 + h a(t1), x1 = x0 + h V1; its true errors against the estimate's
  // (first order: equal to O(h) relative, 0.3 % at h = 0.01).
  RigidBodyState end;
  end.time = t0 + h;
  const double t1 = end.time;
  end.velocity.x() = 3 * t0 * t0 + h * 6 * t1;
  end.position.x() = t0 * t0 * t0 + h * end.velocity.x();
  const double e_x = end.position.x() - t1 * t1 * t1, e_v = end.velocity.x() - 3 * t1 * t1;
  EXPECT_NEAR(estimate.error(end, Scheme::bdf1, o) / std::sqrt((e_x * e_x / (h * h) + e_v * e_v) / 9.0), 1.0, 0.01);
  // bdf2 at a constant step: x2 = 4/3 x1 - 1/3 x0 + 2/3 h V2.
  estimate.accept(point(t1));
  RigidBodyState end2;
  end2.time = t1 + h;
  const double t2 = end2.time;
  end2.position.x() = 4.0 / 3.0 * t1 * t1 * t1 - 1.0 / 3.0 * t0 * t0 * t0 + 2.0 / 3.0 * h * 3 * t2 * t2;
  end2.velocity.x() = 3 * t2 * t2;  // its quadratic motion: predicted exactly, estimate 0
  const double e2 = end2.position.x() - t2 * t2 * t2;
  EXPECT_NEAR(e2, 2.0 / 9.0 * h * h * h * 6.0, 1e-15);  // (2/9) h^3 x'''
  EXPECT_NEAR(estimate.error(end2, Scheme::bdf2, o) / (std::abs(e2) / h / 3.0), 1.0, 1e-6);
  // Variable step, w = h / h_prev = 2: a0 = (1+w)^2/(1+2w), a1 = w^2/(1+2w), b = (1+w)/(1+2w);
  // the error K x''' with K = h^3 (1+w)^2 / (6 w (1+2w)), estimated exactly for a cubic.
  const double w = 2.0, h3 = w * h, t3 = t2 + h3;
  estimate.accept(point(t2));
  RigidBodyState end3;
  end3.time = t3;
  end3.position.x() = (1 + w) * (1 + w) / (1 + 2 * w) * t2 * t2 * t2 - w * w / (1 + 2 * w) * t1 * t1 * t1 +
                      (1 + w) / (1 + 2 * w) * h3 * 3 * t3 * t3;
  end3.velocity.x() = 3 * t3 * t3;
  const double e3 = end3.position.x() - t3 * t3 * t3;
  EXPECT_NEAR(e3 / (h3 * h3 * h3 * (1 + w) * (1 + w) / (6 * w * (1 + 2 * w)) * 6.0), 1.0, 1e-9);
  EXPECT_NEAR(estimate.error(end3, Scheme::bdf2, o) / (std::abs(e3) / h3 / 3.0), 1.0, 1e-6);
}

TEST(DynamicAdaptive, ProposesStepsWithinTheLimits) {
  StepSizeOptions o;
  o.dt_min = 1e-9;
  o.dt_max = 1e-3;
  EXPECT_DOUBLE_EQ(propose_step(1e-5, 1.0, 2, false, o), 0.9e-5);  // err = 1: the safety factor
  EXPECT_DOUBLE_EQ(propose_step(1e-5, 0.0, 2, false, o), 5e-5);    // growth limit
  EXPECT_DOUBLE_EQ(propose_step(1e-5, 0.0, 2, true, o), 1e-5);     // no growth after a rejection
  EXPECT_DOUBLE_EQ(propose_step(1e-5, 1e6, 2, true, o), 2e-6);     // shrink limit
  EXPECT_NEAR(propose_step(1e-5, 8.0, 2, true, o), 0.9e-5 / 2.0, 1e-18);  // err^(-1/3)
  EXPECT_DOUBLE_EQ(propose_step(1e-3, 0.0, 1, false, o), 1e-3);    // dt_max
  EXPECT_DOUBLE_EQ(propose_step(2e-9, 1e6, 1, true, o), 1e-9);     // dt_min
  EXPECT_DOUBLE_EQ(event_share(1.0, -3.0), 0.25);
  EXPECT_DOUBLE_EQ(event_share(1.0, 2.0), 0.5);  // no sign change: bisection
}

TEST(DynamicAdaptive, LocatesTheFirstTouchOfADroppedBall) {
  // 0.1 mm above the half-space at 1 m/s: free flight (zero error, the step grows to dt_max),
  // the touch at t = 1e-4 s plus the time to close the gap under the grid's nearest element
  // centre (dx/2, dy/2): g = (dx^2 + dy^2) / (8 R). The step ending in contact must end within
  // the event tolerance (max(dt_min, 0.01 dt)) after that.
  const double dt = 1e-6;
  json doc = dc::test::ball_impact(12, 1e-4, adaptive_time(dt, 1.2e-4, 1e-3));
  doc["time"]["dt_max"] = 2e-5;
  const Case c = build_case(doc);
  const double dx = c.grid.dx, dy = c.grid.dy, R = c.profile.radius;
  const double g = (dx * dx + dy * dy) / (8.0 * R);
  const double touch = 1e-4 + g / 1.0;
  const dc::test::ImpactMeasure m = dc::test::measure_impact(doc);
  ASSERT_TRUE(m.result.completed) << m.result.status;
  ASSERT_GT(m.first_contact, 0.0);
  EXPECT_LT(m.last_free, touch);
  EXPECT_GE(m.first_contact, touch * (1 - 1e-6)) << "touch " << touch;
  EXPECT_LE(m.first_contact - touch, 0.01 * dt + 1e-3 * g) << "touch " << touch;
  const TimeStepCounts& ts = m.result.time_steps;
  EXPECT_EQ(ts.events, 1);
  EXPECT_GE(ts.event_rejections, 1);
  EXPECT_DOUBLE_EQ(ts.dt_max, 2e-5);  // the free flight
  EXPECT_LT(ts.accepted, 40) << "free flight in a few steps";
  EXPECT_EQ(ts.rejected, m.result.rejected_steps);
  EXPECT_EQ(ts.accepted, m.result.steps);
  std::printf("first touch: step ending at %.9g s, analytic %.9g s (%d accepted, %d rejected)\n", m.first_contact,
              touch, ts.accepted, ts.rejected);
}

TEST(DynamicAdaptive, CountsRejectionsAndResolvesACoarseImpact) {
  // From touching at 1 m/s, a first step of 1e-5 s (a seventh of the contact time): rejected for
  // its error; the impact within the 12^2 grid's budget of Hertz (4 % on the contact time: the
  // static force-approach law on 12 elements across; 0.3 % seen) and the rebound, the time
  // stepping's error alone, within 5 rtol (1.9 rtol seen); the touch and the release located.
  const json doc = dc::test::ball_impact(12, 0.0, adaptive_time(1e-5, 9e-5, 1e-3));
  const Case c = build_case(doc);
  const dc::test::ImpactMeasure m = dc::test::measure_impact(doc);
  ASSERT_TRUE(m.result.completed) << m.result.status;
  const TimeStepCounts& ts = m.result.time_steps;
  EXPECT_GE(ts.error_rejections, 1);
  EXPECT_EQ(ts.rejected, ts.error_rejections + ts.event_rejections);  // no failed solves here
  EXPECT_EQ(ts.events, 2);  // the touch (the ball starts touching, no element pressed) and the release
  EXPECT_LT(ts.dt_min, ts.dt_max);
  const double T = dc::test::hertz_contact_time(c);
  EXPECT_NEAR(m.contact_time / T, 1.0, 0.04) << m.contact_time << " vs Hertz " << T;
  EXPECT_NEAR(m.rebound, 1.0, 5 * 1e-3);
  std::printf("coarse adaptive impact: contact time %.6g s (Hertz %.6g), rebound %.6f m/s, %d accepted, %d rejected, "
              "dt %.3g..%.3g s\n",
              m.contact_time, T, m.rebound, ts.accepted, ts.rejected, ts.dt_min, ts.dt_max);
}

TEST(DynamicAdaptive, LocatesTheEndOfGrossSliding) {
  // examples/bowling-ball (launched sliding at 3 m/s, mu = 0.2): friction spins it up until it
  // rolls at t = 2 v0 / (7 mu g) = 0.437 s at 5/7 v0. The end of gross sliding (the first step
  // with an element sticking) is an event located by bisection: the step crossing it at most
  // 2 x 0.01 dt long. The rolling start within 1 % of the rigid-body time (the contact's creep
  // starts the stick a little earlier: 0.16 % seen), the final speed within 0.1 % of 5/7 v0
  // (0.03 % seen), in a tenth of the fixed run's 300 steps.
  json doc = dc::test::example_json("bowling-ball");
  const double dt = doc["time"]["dt"].get<double>();
  doc["time"]["adaptive"] = true;
  doc["time"]["rtol"] = 1e-4;
  const Case c = build_case(doc);
  DynamicSimulation sim(c);
  double last_sliding = 0.0, first_stick = -1.0;
  const DynamicResult r = sim.run([&](const DynamicSample& s) {
    if (first_stick < 0.0 && s.contact_state.n_stick > 0) first_stick = s.state.time;
    if (first_stick < 0.0) last_sliding = s.state.time;
  });
  ASSERT_TRUE(r.completed) << r.status;
  const double g = 9.81, v0 = 3.0, mu = 0.2;
  EXPECT_NEAR(first_stick / (2 * v0 / (7 * mu * g)), 1.0, 0.01) << first_stick;
  EXPECT_LE(first_stick - last_sliding, 2 * 0.01 * dt * (1 + 1e-9));
  EXPECT_EQ(r.time_steps.events, 1);
  EXPECT_NEAR(r.final.velocity.x() / (5.0 / 7.0 * v0), 1.0, 1e-3);
  EXPECT_LT(r.time_steps.accepted + r.time_steps.rejected, 60);
  std::printf("bowling ball: stick from %.6g s (rigid %.6g s), final %.6f m/s, %d accepted, %d rejected\n",
              first_stick, 2 * v0 / (7 * mu * g), r.final.velocity.x(), r.time_steps.accepted,
              r.time_steps.rejected);
}

TEST(DynamicAdaptive, StopsWhenTheToleranceCannotBeMetAtDtMin) {
  json doc = dc::test::ball_impact(12, 0.0, adaptive_time(1e-6, 8e-5, 1e-8));
  doc["time"]["dt_min"] = 1e-6;
  const Case c = build_case(doc);
  DynamicSimulation sim(c);
  const DynamicResult r = sim.run({});
  EXPECT_FALSE(r.completed);
  EXPECT_NE(r.status.find("time.dt_min"), std::string::npos) << r.status;
  EXPECT_GE(r.rejected_steps, 1);
}

TEST(DynamicAdaptive, AbsentIsTheFixedStepRun) {
  // adaptive: false and no adaptive key take the same fixed steps (and report them).
  json doc = dc::test::ball_impact(12, 0.0, {{"dt", 2e-6}, {"t_end", 2e-5}});
  const Case ca = build_case(doc);
  DynamicSimulation a(ca);
  std::vector<double> za;
  const DynamicResult ra = a.run([&](const DynamicSample& s) { za.push_back(s.state.position.z()); });
  doc["time"]["adaptive"] = false;
  const Case cb = build_case(doc);
  DynamicSimulation b(cb);
  std::vector<double> zb;
  const DynamicResult rb = b.run([&](const DynamicSample& s) { zb.push_back(s.state.position.z()); });
  EXPECT_EQ(za, zb);
  EXPECT_FALSE(ra.adaptive);
  EXPECT_EQ(ra.time_steps.accepted, 10);
  EXPECT_EQ(ra.time_steps.rejected, 0);
  EXPECT_NEAR(ra.time_steps.dt_min, 2e-6, 1e-18);
  EXPECT_NEAR(ra.time_steps.dt_max, 2e-6, 1e-18);
}

}  // namespace
}  // namespace dc::dynamics
