// Adaptive time steps against fixed ones at equal accuracy (issue 28, item 3): the bundled ball
// impact (steel on steel, R = 10 mm, 1 m/s) on a 24^2 grid. The error of a run is the larger of
// its rebound speed's and its contact time's relative errors, the first against the elastic
// rebound v0 (the grid's force is a function of the approach alone: a conservative force, so
// the rebound's loss is the time stepping's), the second against a fixed-step run with 1500
// steps per contact on the same grid (the grid's own error, 0.03 % against Hertz, is the same for
// every step). For rtol 1e-3 and 1e-4 the adaptive run's rebound must be within 5 rtol, its
// contact time within 6 rtol, and its error fall with rtol; with a flight before or after the contact, the fixed step reaching the same error
// must take more steps than the adaptive run solved (accepted and rejected). The figures are
// printed (docs/dynamics.md "Adaptive time steps").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "impact_measure.hpp"

namespace dc::dynamics {
namespace {

using nlohmann::json;

constexpr int kGrid = 24;

struct Accuracy {
  double error = 0.0, time_error = 0.0, rebound_error = 0.0;
  int solved = 0;  ///< steps solved (accepted and rejected)
  int accepted = 0;
};

double hertz_time() {
  return dc::test::hertz_contact_time(build_case(dc::test::ball_impact(kGrid, 0.0, {{"dt", 1e-6}, {"t_end", 1e-4}})));
}

Accuracy accuracy(double height, const json& time, double reference_time) {
  const dc::test::ImpactMeasure m = dc::test::measure_impact(dc::test::ball_impact(kGrid, height, time));
  EXPECT_TRUE(m.result.completed) << m.result.status;
  Accuracy a;
  a.time_error = std::abs(m.contact_time / reference_time - 1.0);
  a.rebound_error = std::abs(m.rebound - 1.0);
  a.error = std::max(a.time_error, a.rebound_error);
  a.accepted = m.result.time_steps.accepted;
  a.solved = a.accepted + m.result.time_steps.rejected;
  return a;
}

/// The ball from `height` above the half-space (a flight of height / 1 m/s) to t_end:
/// adaptive steps at rtol 1e-3 and 1e-4 against fixed ones; `fewer`: the adaptive run must take
/// fewer steps than the fixed one of the same error.
void compare(double height, double t_end, bool fewer) {
  const double T = hertz_time();
  const json reference_time = {{"dt", T / 1500}, {"t_end", t_end}, {"scheme", "bdf2"}};
  const double T_ref = dc::test::measure_impact(dc::test::ball_impact(kGrid, height, reference_time)).contact_time;
  EXPECT_NEAR(T_ref / T, 1.0, 0.01) << "the grid's contact time against Hertz";
  // Fixed steps from 10 to 640 per contact time, their errors.
  std::vector<std::pair<int, Accuracy>> fixed;
  for (double n = 10; n <= 640; n *= std::sqrt(2.0)) {
    const json time = {{"dt", T / std::round(n)}, {"t_end", t_end}, {"scheme", "bdf2"}, {"allow_coarse_dt", true}};
    fixed.emplace_back(static_cast<int>(std::round(n)), accuracy(height, time, T_ref));
  }
  double last_error = 1.0;
  for (double rtol : {1e-3, 1e-4}) {
    const json time = {{"dt", T / 100}, {"t_end", t_end}, {"scheme", "bdf2"}, {"adaptive", true}, {"rtol", rtol}};
    const Accuracy a = accuracy(height, time, T_ref);
    // The rebound (an amplitude) and the contact time (a phase: the positions' errors per unit
    // step add up over the contact) follow rtol: 1.3-3.1 rtol and 3.5-4.7 rtol seen.
    EXPECT_LE(a.rebound_error, 5.0 * rtol) << "rtol " << rtol;
    EXPECT_LE(a.time_error, 6.0 * rtol) << "rtol " << rtol;
    EXPECT_LT(a.error, last_error) << "the error falls with rtol";
    last_error = a.error;
    // The fewest fixed steps reaching the adaptive run's error.
    const std::pair<int, Accuracy>* match = nullptr;
    for (const auto& f : fixed)
      if (f.second.error <= a.error) {
        match = &f;
        break;
      }
    ASSERT_NE(match, nullptr) << "no fixed step up to 640 per contact reaches " << a.error;
    const Accuracy& f = match->second;
    std::printf("height %g m, rtol %g: adaptive %d accepted + %d rejected steps, error %.2e (contact time %.2e, "
                "rebound %.2e); fixed %d steps per contact: %d steps, error %.2e (%.2e, %.2e)\n",
                height, rtol, a.accepted, a.solved - a.accepted, a.error, a.time_error, a.rebound_error, match->first,
                f.solved, f.error, f.time_error, f.rebound_error);
    if (fewer) {
      EXPECT_LT(a.solved, f.solved) << "rtol " << rtol;
    }
  }
  for (const auto& [n, f] : fixed)
    std::printf("height %g m, fixed %3d steps per contact: %4d steps, error %.2e (contact time %.2e, rebound %.2e)\n",
                height, n, f.solved, f.error, f.time_error, f.rebound_error);
}

// The contact alone (from touching to 1.1 contact times): the impact is smooth, a fixed step of
// the right size is as good, and the adaptive run takes about as many steps for the same error
// (printed, not asserted).
TEST(SlowDynamicAdaptive, TheContactAloneReachesRtol) { compare(0.0, 1.1 * hertz_time(), false); }

// CASES.md's time block (t_end 1 ms): the rebound's flight after the contact.
TEST(SlowDynamicAdaptive, ImpactAndFlightInFewerStepsThanFixedAtEqualAccuracy) { compare(0.0, 1e-3, true); }

// Dropped 0.5 mm above the half-space: the flight before the touch.
TEST(SlowDynamicAdaptive, DropInFewerStepsThanFixedAtEqualAccuracy) {
  compare(5e-4, 5e-4 + 1.1 * hertz_time(), true);
}

}  // namespace
}  // namespace dc::dynamics
