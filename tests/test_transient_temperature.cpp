// The time-stepped flash temperature (core/transient_heat, core/transient_flash_temperature):
// a stationary uniform circle switched on at t = 0 against Carslaw & Jaeger's centre
// temperature, a moving circle run to its steady state against the quasi-steady Jaeger tables
// (core/flash_temperature), the short-time 1-D penetration of a high-Peclet band, and the
// partition of each step's heat between two surfaces. Tolerances are stated with the grid, the
// box and the steps they hold on; measured errors are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "errors.hpp"
#include "flash_temperature.hpp"
#include "thermal_closed_forms.hpp"
#include "transient_flash_temperature.hpp"
#include "transient_heat.hpp"

namespace transient_temperature_tests {
using dc::Grid;
using dc::ThermalProperties;
using dc::TransientHeat;
using dc::TransientHeatOptions;

/// The uniform unit flux on the disc r <= a (3-D) or the band |x| <= a (2-D) of the grid.
std::vector<double> uniform_source(const Grid& g, double a) {
  std::vector<double> q(g.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      q[g.index(i, j)] = (g.dimension == 3 ? std::hypot(g.xc(i), g.yc(j)) : std::abs(g.xc(i))) <= a ? 1.0 : 0.0;
  return q;
}

TEST(TransientTemperature, StationaryCircleFollowsCarslawJaeger) {
  // (T2) at the centre (the mean of the four central elements), 32 x 32 elements over
  // [-1.25 a, 1.25 a]^2, box padding 3, 200 steps to t = 2 a^2/kappa (sqrt(kappa t) = 1.41 a,
  // 80 % of the steady rise): within backward Euler's 1/(8n) after n steps plus 0.5 % (the disc's
  // staircase; measured -9.4e-3 at n = 20, +2.9e-3 at most after, +1.7e-3 at n = 200).
  const double a = 1e-3, K = 40.0, kappa = 1.2e-5, q0 = 2e7;
  const int n = 32, steps = 200;
  const Grid g = Grid::make(3, n, n, -1.25 * a, 1.25 * a, -1.25 * a, 1.25 * a);
  std::vector<double> q = uniform_source(g, a);
  for (double& v : q) v *= q0;
  const double t_end = 2.0 * a * a / kappa, h = t_end / steps;
  TransientHeatOptions o;
  o.padding = 3;
  TransientHeat heat(g, {K, kappa}, h, t_end, o);
  std::vector<double> T(g.size());
  double previous = 0.0;
  for (int s = 1; s <= steps; ++s) {
    heat.step(h, 0.0, q.data(), T.data());
    const double centre = 0.25 * (T[g.index(n / 2, n / 2)] + T[g.index(n / 2 - 1, n / 2)] +
                                  T[g.index(n / 2, n / 2 - 1)] + T[g.index(n / 2 - 1, n / 2 - 1)]);
    EXPECT_GT(centre, previous) << "step " << s;  // a source switched on heats monotonically
    previous = centre;
    if (s == 1 || s == 5) {
      // The heat put in is in the half-space (the scheme conserves it) until the spreading heat
      // reaches the fringe: within 1e-8 after one step, 1e-6 after five (measured 7.5e-10,
      // 1.7e-7; the fringe has taken 2e-4 of it by step 20, t = 0.2 a^2/kappa).
      double put_in = 0.0;
      for (double v : q) put_in += v * g.area() * s * h;
      std::printf("  heat in the half-space %.10g J, put in %.10g J\n", heat.heat_content(), put_in);
      EXPECT_NEAR(heat.heat_content() / put_in, 1.0, s == 1 ? 1e-8 : 1e-6);
    }
    if (s % 20 == 0) {
      const double exact = dc::thermal::circle_centre_transient(std::sqrt(kappa * s * h) / a) * q0 * a / K;
      std::printf("  circle t = %.3g a^2/kappa: centre %.6g K, (T2) %.6g K, relative %.2e\n", s * h * kappa / (a * a),
                  centre, exact, centre / exact - 1.0);
      EXPECT_NEAR(centre / exact, 1.0, 1.0 / (8.0 * s) + 5e-3) << "t = " << s * h;
    }
  }
  // (T2)'s limits: (T1) at short times, (C1)'s q a / K at long times.
  EXPECT_NEAR(dc::thermal::circle_centre_transient(0.05), dc::thermal::one_dimensional_transient(0.05), 1e-12);
  EXPECT_NEAR(dc::thermal::circle_centre_transient(1e4), dc::thermal::circle_centre_stationary(), 1e-4);
}

/// A stretch of a run at one Peclet number: its length in transits 2a/V and its steps.
struct Stretch {
  double peclet, transits;
  int steps;
};

/// The transient map after the stretches against the quasi-steady one at the last stretch's
/// speed (both with the same element fluxes): the relative difference of the maxima and the
/// largest difference over the grid relative to the maximum. Returns the last step's sub-steps.
int expect_reaches_quasi_steady(const std::vector<Stretch>& run, int padding, double max_tol, double map_tol) {
  const double a = 1e-3, K = 50.0, kappa = 1.4e-5, q0 = 1e8;
  const auto speed = [&](const Stretch& r) { return 2.0 * r.peclet * kappa / a; };
  double duration = 0.0, shortest = 1e300;
  for (const Stretch& r : run) {
    const double t = r.transits * 2.0 * a / speed(r);
    duration += t;
    shortest = std::min(shortest, t / r.steps);
  }
  const Grid g = Grid::make(3, 32, 32, -1.25 * a, 1.25 * a, -1.25 * a, 1.25 * a);
  std::vector<double> q = uniform_source(g, a);
  for (double& v : q) v *= q0;
  TransientHeatOptions o;
  o.padding = padding;
  TransientHeat heat(g, {K, kappa}, shortest, duration, o);
  std::vector<double> T(g.size());
  for (const Stretch& r : run) {
    const double V = speed(r), h = r.transits * 2.0 * a / V / r.steps;
    for (int s = 0; s < r.steps; ++s) heat.step(h, V, q.data(), T.data());
  }
  const dc::ThermalSurface surface{ThermalProperties::make(K, kappa, "s"), speed(run.back())};
  const dc::FlashTemperature flash(g, surface, surface);
  const std::vector<double> steady = flash.surface_temperature(dc::BodySide::base, q);
  const double steady_max = *std::max_element(steady.begin(), steady.end());
  const double transient_max = *std::max_element(T.begin(), T.end());
  double worst = 0.0;
  for (std::size_t e = 0; e < T.size(); ++e) worst = std::max(worst, std::abs(T[e] - steady[e]));
  std::printf("  Pe %.3g after %.3g transits (%zu stretches, box padding %d, %d steps last): max %.6g K vs "
              "quasi-steady %.6g K (%.2e), map %.2e of the max\n",
              run.back().peclet, run.back().transits, run.size(), padding, run.back().steps, transient_max,
              steady_max, transient_max / steady_max - 1.0, worst / steady_max);
  EXPECT_NEAR(transient_max / steady_max, 1.0, max_tol);
  EXPECT_LT(worst / steady_max, map_tol);
  return heat.last_substeps();
}

TEST(TransientTemperature, MovingCircleReachesQuasiSteadyMap) {
  // 32 x 32 over [-1.25 a, 1.25 a]^2. Pe = 5, padding 2, 5 transits 2a/V in 200 steps: the
  // maximum within 0.1 % and the map within 0.5 % of it (measured -5.6e-4 and 3.9e-3; the
  // scheme's steady state is the semi-discrete one whatever the step). Pe = 1, padding 4, 6
  // transits in 60 steps: 0.5 % and 1 % (measured 1.9e-3, 3.6e-3: the box's fringe, a cold
  // boundary about 2 a beyond the grid).
  EXPECT_EQ(expect_reaches_quasi_steady({{5.0, 5.0, 200}}, 2, 1e-3, 5e-3), 1);
  EXPECT_EQ(expect_reaches_quasi_steady({{1.0, 6.0, 60}}, 4, 5e-3, 1e-2), 1);
  // Steps of 8 elements (16 steps for the 5 transits): two sub-steps of 4 elements each (an
  // eighth of the padding's 32), the fringe between them. 0.5 % and 1 % (measured +2.5e-3,
  // 7.6e-3: the heat in transit through the fringe within a step).
  EXPECT_EQ(expect_reaches_quasi_steady({{5.0, 5.0, 16}}, 2, 5e-3, 1e-2), 2);
}

TEST(TransientTemperature, SpeedChangeReachesTheNewQuasiSteadyMap) {
  // Pe 5 for 5 transits (100 steps), then Pe 2 for 6 of its transits (100 steps): the map
  // forgets the first speed and is the quasi-steady one at Pe 2, 32^2, padding 2: the maximum
  // within 0.5 %, the map within 1 % (measured -1.7e-3 and 8.0e-3, most of it the fringe's cold
  // boundary 0.6 a beyond the grid at this Peclet number).
  expect_reaches_quasi_steady({{5.0, 5.0, 100}, {2.0, 6.0, 100}}, 2, 5e-3, 1e-2);
}

TEST(TransientTemperature, HighPecletShortTimeIsOneDimensional) {
  // A band |x| <= b moving at Pe = V b/(2 kappa) = 100 switched on at t = 0 (2-D, 64 elements
  // over [-1.25 b, 1.25 b]): at its centre, until t = b/(2V), every point was under the source
  // for the whole time, 10 diffusion lengths from the cold material entering: (T1),
  // 2 q sqrt(kappa t/pi)/K, within backward Euler's 1/(8n) after n steps plus 0.1 %
  // (100 steps; measured -6.5e-3 at n = 20, -2.0e-3 at n = 100).
  const double b = 1e-3, K = 20.0, kappa = 5e-6, q0 = 3e8, peclet = 100.0;
  const double V = 2.0 * peclet * kappa / b, t_end = 0.5 * b / V;
  const int steps = 100;
  const double h = t_end / steps;
  const Grid g = Grid::make(2, 64, 1, -1.25 * b, 1.25 * b, 0.0, 1.0);
  std::vector<double> q = uniform_source(g, b);
  for (double& v : q) v *= q0;
  // The same with the speed varying as V (1 + sin(2 pi t/t_end)/2) (the centre's material came
  // from at most 0.66 b ahead: still inside the band), the same tolerance.
  for (const bool varying : {false, true}) {
    TransientHeat heat(g, {K, kappa}, h, t_end);
    std::vector<double> T(g.size());
    for (int s = 1; s <= steps; ++s) {
      const double speed = varying ? V * (1.0 + 0.5 * std::sin(2.0 * std::numbers::pi * (s - 0.5) / steps)) : V;
      heat.step(h, speed, q.data(), T.data());
      if (s % 20 == 0) {
        const double exact = dc::thermal::one_dimensional_transient(std::sqrt(kappa * s * h) / b) * q0 * b / K;
        const double centre = T[g.index(32, 0)];
        std::printf("  band Pe 100%s, step %d: centre %.6g K, (T1) %.6g K, relative %.2e\n",
                    varying ? " (varying speed)" : "", s, centre, exact, centre / exact - 1.0);
        EXPECT_NEAR(centre / exact, 1.0, 1.0 / (8.0 * s) + 1e-3) << "step " << s << (varying ? ", varying" : "");
      }
    }
  }
}

TEST(TransientTemperature, PartitionSharesEachStep) {
  // Two surfaces with different constants under a stationary square source (16 x 16): with
  // equal_mean the heated means are equal after every step (to round-off) and the heat into the
  // base is the fraction's; a fixed fraction scales a lone surface's temperature exactly.
  const Grid g = Grid::make(3, 16, 16, -1e-3, 1e-3, -1e-3, 1e-3);
  std::vector<double> q(g.size(), 0.0);
  for (int j = 4; j < 12; ++j)
    for (int i = 4; i < 12; ++i) q[g.index(i, j)] = 1e7;
  const ThermalProperties steel{50.0, 1.4e-5}, ceramic{2.0, 1e-6};
  const double h = 1e-4, t_end = 2e-3;
  dc::HeatPartition mean_rule;
  dc::TransientFlashTemperature model(g, steel, ceramic, mean_rule, h, t_end);
  double f_first = 0.0;
  for (int s = 1; s <= 20; ++s) {
    const dc::FlashTemperatureResult r = model.step(h, 0.3, -0.1, q);
    if (s == 1) f_first = r.base_fraction;
    EXPECT_GT(r.base_fraction, 0.0);
    EXPECT_LT(r.base_fraction, 1.0);
    EXPECT_NEAR(r.base_mean, r.body_mean, 1e-10 * r.base_mean) << "step " << s;
  }
  EXPECT_GT(f_first, 0.5);  // the better conductor takes the larger share

  dc::HeatPartition fixed;
  fixed.rule = dc::HeatPartition::Rule::fixed;
  fixed.base_fraction = 0.3;
  dc::TransientFlashTemperature shared(g, steel, ceramic, fixed, h, t_end);
  TransientHeat alone(g, steel, h, t_end);
  std::vector<double> T(g.size());
  for (int s = 1; s <= 5; ++s) {
    const dc::FlashTemperatureResult r = shared.step(h, 0.3, -0.1, q);
    alone.step(h, 0.3, q.data(), T.data());
    for (std::size_t e = 0; e < T.size(); ++e) EXPECT_NEAR(r.base[e], 0.3 * T[e], 1e-12 * r.base_max);
  }
}

TEST(TransientTemperature, BadInputIsNamed) {
  const Grid g = Grid::make(3, 8, 8, -1e-3, 1e-3, -1e-3, 1e-3);
  dc::HeatPartition pointwise;
  pointwise.rule = dc::HeatPartition::Rule::pointwise;
  try {
    dc::TransientFlashTemperature m(g, {50.0, 1e-5}, {50.0, 1e-5}, pointwise, 1e-4, 1e-3, {}, "b", "d",
                                    "temperature.partition");
    FAIL() << "pointwise accepted";
  } catch (const dc::InputError& e) {
    EXPECT_EQ(e.key(), "temperature.partition");
  }
  try {
    TransientHeat heat(g, {0.0, 1e-5}, 1e-4, 1e-3, {}, "materials.base.thermal");
    FAIL() << "zero conductivity accepted";
  } catch (const dc::InputError& e) {
    EXPECT_EQ(e.key(), "materials.base.thermal.conductivity");
  }
  EXPECT_THROW(TransientHeat(g, {50.0, 1e-5}, 0.0, 1e-3), std::invalid_argument);
  TransientHeat heat(g, {50.0, 1e-5}, 1e-4, 1e-3);
  std::vector<double> q(g.size(), 1.0), T(g.size());
  EXPECT_THROW(heat.step(-1e-4, 0.0, q.data(), T.data()), std::invalid_argument);
  EXPECT_THROW(heat.commit(1.0), std::logic_error);
}

}  // namespace transient_temperature_tests
