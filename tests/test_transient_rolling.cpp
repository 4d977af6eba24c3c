// Transient rolling with memory (TangentialProblem::roll): a plane-strain cylinder under a
// tangential force F = -mu P/2 on the body, first without travel (Cattaneo, 2-D closed form),
// then rolling in +x at that force until Carter's steady state ((5.1)-(5.6), closed forms in
// core/contact_closed_forms). Rolling is in +x, so material enters the contact at x = +a (the
// leading edge; CarterSteadyRolling2d in test_tangential_validation.cpp puts Carter's stick zone
// at [a - 2a', a]). A 3-D sphere checks that the march runs and ends at steady_rolling()'s creepage.
//
// Grid: 100 strips over +-1.2 a (dx = a/41.7), the grid of CarterForceControlled2d, whose
// tolerances (creepage within 2 %, stick length within 2 dx) are used for the steady state here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "contact_closed_forms.hpp"
#include "errors.hpp"
#include "hertz.hpp"
#include "tangential_problem.hpp"
#include "tangential_support.hpp"

namespace dc {
namespace {

namespace cf = closed_form;

using test::amplitude;
using test::expect_certified;
using test::resultant;


/// Steel cylinder on steel, plane strain: R = 50 mm, P = 100 kN/m, mu = 0.3.
struct Cylinder {
  MaterialPair m{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)};
  double R = 0.05, P = 1e5, mu = 0.3, ratio = -0.5;  // F / (mu P), force on the body
  hertz::CylinderSolution hz = hertz::cylinder2d(R, P, m.E_star());
  double a = hz.a, mu_p0 = mu * hz.p0;
  Grid g = Grid::make(2, 100, 1, -1.2 * a, 1.2 * a, 0, 0);

  TangentialProblem problem() const { return test::round_body_problem(g, m, R, mu); }
  /// Force control: F = ratio mu P on the body.
  RollingLoad load() const {
    RollingLoad l;
    l.normal = {Control::force, P};
    l.modes = {resultant(ratio * mu * P), amplitude(0.0), amplitude(0.0)};
    return l;
  }
  /// RMS over the contact of tau - exact(x), relative to mu p0.
  template <class Exact>
  double rms(const TangentialSolution& s, Exact exact) const {
    double sq = 0.0;
    int count = 0;
    for (int i = 0; i < g.nx; ++i) {
      if (std::abs(g.xc(i)) >= a) continue;
      const double e = s.tx[i] - exact(g.xc(i));
      sq += e * e;
      ++count;
    }
    return std::sqrt(sq / count) / mu_p0;
  }
  double cattaneo_rms(const TangentialSolution& s) const {
    return rms(s, [&](double x) { return cf::cattaneo_2d_traction(x, a, hz.p0, mu, ratio); });
  }
  double carter_rms(const TangentialSolution& s) const {
    return rms(s, [&](double x) { return cf::carter_traction(x, a, hz.p0, mu, ratio); });
  }
};

/// The stick zone [lo, hi] (element edges); it must be one interval.
struct StickZone {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  double centre() const { return 0.5 * (lo + hi); }
};

StickZone stick_zone(const TangentialSolution& s, const Grid& g) {
  StickZone z;
  for (int i = 0; i < g.nx; ++i)
    if (s.state[i] == 1) {
      z.lo = std::min(z.lo, g.xc(i) - 0.5 * g.dx);
      z.hi = std::max(z.hi, g.xc(i) + 0.5 * g.dx);
    }
  EXPECT_NEAR(s.stick_area, z.hi - z.lo, 1e-9 * (z.hi - z.lo)) << "the stick zone is not one interval";
  return z;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

TEST(TransientRolling, FirstStepWithoutTravelIsCattaneo2d) {
  const Cylinder cyl;
  const Grid& g = cyl.g;
  TangentialProblem problem = cyl.problem();
  const TangentialSolution s = problem.roll(cyl.load(), 0.0, test::native_tangential_solver());
  expect_certified(s);
  EXPECT_EQ(s.marching_steps, 0);
  EXPECT_EQ(s.distance, 0.0);
  EXPECT_NEAR(s.resultants[0], cyl.ratio * cyl.mu * cyl.P, 1e-7 * cyl.mu * cyl.P);
  EXPECT_GT(s.amplitudes[0], 0.0);  // a braking force on the body: the body shifted towards +x

  // Cattaneo: a centred stick zone |x| < c = a sqrt(1 - |F|/(mu P)). The zone is a whole number of
  // elements on a grid symmetric about 0: centred to round-off, each end within one element of c.
  const double c = cf::cattaneo_2d_stick_half_width(cyl.a, cyl.ratio);
  const StickZone z = stick_zone(s, g);
  const double rms = cyl.cattaneo_rms(s);
  std::printf("[ Cattaneo 2-D ] stick [%.4f, %.4f] a (c/a = %.4f), traction RMS %.4f mu p0\n", z.lo / cyl.a,
              z.hi / cyl.a, c / cyl.a, rms);
  EXPECT_NEAR(z.centre(), 0.0, 1e-9 * cyl.a);
  EXPECT_NEAR(z.hi, c, g.dx);
  // Traction within 1 % of mu p0 (RMS), the bound CarterSteadyRolling2d sets for the steady march.
  EXPECT_LT(rms, 0.01);
  // And it is the quasi-static step of the same force: the same program as step().
  TangentialProblem quasi_static = cyl.problem();
  TangentialLoad shift;
  shift.normal = cyl.load().normal;
  shift.modes = cyl.load().modes;
  const TangentialSolution q = quasi_static.step(shift, test::native_tangential_solver());
  EXPECT_LT(max_abs_diff(q.tx, s.tx), 1e-9 * cyl.mu_p0);
  EXPECT_NEAR(q.amplitudes[0], s.amplitudes[0], 1e-9 * s.amplitudes[0]);
}

TEST(TransientRolling, DistanceRulesAndCreepageControlWithoutTravel) {
  const Cylinder cyl;
  TangentialProblem problem = cyl.problem();
  RollingLoad load = cyl.load();
  EXPECT_THROW(problem.roll(load, -1e-6, test::native_tangential_solver()), InputError);
  EXPECT_THROW(problem.roll(load, std::numeric_limits<double>::quiet_NaN(), test::native_tangential_solver()), InputError);
  // A creepage over zero distance is no rigid slip: from rest, no traction at all.
  load.modes[0] = amplitude(cf::carter_creepage(cyl.a, cyl.R, cyl.mu, cyl.ratio));
  const TangentialSolution rest = problem.roll(load, 0.0, test::native_tangential_solver());
  EXPECT_EQ(rest.marching_steps, 0);
  for (double t : rest.tx) EXPECT_EQ(t, 0.0);
  EXPECT_EQ(rest.amplitudes[0], 0.0);
  // A positive distance rolls the nearest whole number of elements, at least one.
  const TangentialSolution one = problem.roll(load, 0.1 * cyl.g.dx, test::native_tangential_solver());
  EXPECT_EQ(one.marching_steps, 1);
  EXPECT_DOUBLE_EQ(one.distance, cyl.g.dx);
  EXPECT_DOUBLE_EQ(one.amplitudes[0], load.modes[0].value);  // reported as the creepage
  const TangentialSolution three = problem.roll(load, 3.4 * cyl.g.dx, test::native_tangential_solver());
  EXPECT_EQ(three.marching_steps, 3);
  EXPECT_LT(three.resultants[0], one.resultants[0]);  // the braking force builds up as it rolls
}

TEST(TransientRolling, MemoryIsKeptBetweenRolls) {
  const Cylinder cyl;
  const double half = 0.5 * cyl.a;  // 20.8 dx: 21 steps; 1a: 41.7 dx -> 42 steps
  TangentialProblem split = cyl.problem(), whole = cyl.problem(), from_rest = cyl.problem();
  split.roll(cyl.load(), 0.0, test::native_tangential_solver());
  const TangentialSolution first = split.roll(cyl.load(), half, test::native_tangential_solver());
  const TangentialSolution s2 = split.roll(cyl.load(), half, test::native_tangential_solver());
  whole.roll(cyl.load(), 0.0, test::native_tangential_solver());
  const TangentialSolution s1 = whole.roll(cyl.load(), 2 * half, test::native_tangential_solver());
  EXPECT_EQ(s1.marching_steps, 42);
  EXPECT_EQ(s2.marching_steps, 21);
  // Two rolls of 21 steps are the 42 steps of one (the same programs in the same order).
  EXPECT_LT(max_abs_diff(s1.tx, s2.tx), 1e-9 * cyl.mu_p0);
  EXPECT_NEAR(s1.amplitudes[0], s2.amplitudes[0], 1e-9 * std::abs(s1.amplitudes[0]));
  // The frictional work of a roll is that of all its marching steps: the two halves' add up to
  // the whole's, and a half's is far above its last step's (each step slips at the trailing edge).
  const double half_work = first.marched_frictional_work, whole_work = s1.marched_frictional_work;
  EXPECT_GT(half_work, 0.0);
  EXPECT_NEAR(half_work + s2.marched_frictional_work, whole_work, 1e-9 * whole_work);
  EXPECT_GT(s2.marched_frictional_work, 10.0 * frictional_work(s2, cyl.g.area()));
  // Starting from rest instead of Cattaneo's state changes the answer: the state is the memory.
  const TangentialSolution r = from_rest.roll(cyl.load(), 2 * half, test::native_tangential_solver());
  EXPECT_GT(max_abs_diff(r.tx, s1.tx), 0.05 * cyl.mu_p0);
}

TEST(TransientRolling, StickZoneMovesTowardsTheLeadingEdge) {
  const Cylinder cyl;
  const Grid& g = cyl.g;
  TangentialProblem problem = cyl.problem();
  problem.roll(cyl.load(), 0.0, test::native_tangential_solver());
  const TangentialSolution s = problem.roll(cyl.load(), 0.5 * cyl.a, test::native_tangential_solver());
  expect_certified(s);
  const double ap = cf::carter_stick_half_width(cyl.a, cyl.ratio);
  const double carter_centre = cyl.a - ap;  // Carter: [a - 2a', a]; Cattaneo: centred on 0
  const StickZone z = stick_zone(s, g);
  const double xi_carter = cf::carter_creepage(cyl.a, cyl.R, cyl.mu, cyl.ratio);
  std::printf("[ after 0.5a ] stick [%.4f, %.4f] a, centre %.4f a (Cattaneo 0, Carter %.4f); RMS from Cattaneo "
              "%.4f, from Carter %.4f mu p0; creepage / Carter %.4f\n",
              z.lo / cyl.a, z.hi / cyl.a, z.centre() / cyl.a, carter_centre / cyl.a, cyl.cattaneo_rms(s),
              cyl.carter_rms(s), s.amplitudes[0] / xi_carter);
  // Neither Cattaneo's nor Carter's: the centre lies between theirs, more than 3 elements from
  // each (the zone's ends are resolved to one element), moved towards the leading edge +x.
  EXPECT_GT(z.centre(), 3 * g.dx);
  EXPECT_LT(z.centre(), carter_centre - 3 * g.dx);
  // It already reaches the leading edge, where the newly entered material sticks.
  EXPECT_NEAR(z.hi, cyl.a, g.dx);
  // The traction is far (5 x the 1 % discretisation bound) from both closed forms, and the
  // creepage outside the 2 % band of Carter's.
  EXPECT_GT(cyl.cattaneo_rms(s), 0.05);
  EXPECT_GT(cyl.carter_rms(s), 0.05);
  EXPECT_GT(std::abs(s.amplitudes[0] / xi_carter - 1.0), 0.02);
}

TEST(TransientRolling, CattaneoThenRollingReachesCarter) {
  const Cylinder cyl;
  const Grid& g = cyl.g;
  const double a = cyl.a;
  TangentialProblem problem = cyl.problem();
  // The bundled example's history: no travel, then 0.5a, 0.5a, 1a, 1a (3a in all, 125 steps).
  double rolled = 0.0;
  TangentialSolution s = problem.roll(cyl.load(), 0.0, test::native_tangential_solver());
  for (double d : {0.5 * a, 0.5 * a, a, a}) {
    s = problem.roll(cyl.load(), d, test::native_tangential_solver());
    expect_certified(s);
    EXPECT_NEAR(s.resultants[0], cyl.ratio * cyl.mu * cyl.P, 1e-7 * cyl.mu * cyl.P);
    rolled += s.distance;
  }
  EXPECT_NEAR(rolled, 3 * a, 2 * g.dx);
  const double xi = cf::carter_creepage(a, cyl.R, cyl.mu, cyl.ratio);
  const double ap = cf::carter_stick_half_width(a, cyl.ratio);
  const StickZone z = stick_zone(s, g);
  std::printf("[ after 3a ] creepage / Carter %.4f, stick [%.4f, %.4f] a (Carter [%.4f, 1]), traction RMS %.4f mu "
              "p0\n",
              s.amplitudes[0] / xi, z.lo / a, z.hi / a, (a - 2 * ap) / a, cyl.carter_rms(s));
  // Carter's state within CarterForceControlled2d's tolerances on this grid: creepage within 2 %,
  // stick length within 2 dx; the stick zone at the leading edge within 2 dx at each end
  // (CarterSteadyRolling2d); the traction within 1 % of mu p0 (RMS), as for the first step.
  EXPECT_NEAR(s.amplitudes[0] / xi, 1.0, 0.02);
  EXPECT_NEAR(s.stick_area, 2 * ap, 2 * g.dx);
  EXPECT_NEAR(z.hi, a, 2 * g.dx);
  EXPECT_NEAR(z.lo, a - 2 * ap, 2 * g.dx);
  EXPECT_LT(cyl.carter_rms(s), 0.01);

  // The same discrete scheme as steady_rolling(), which marches from rest to its fixed point:
  // the transient decays (oscillating, about a decade per contact width rolled), so after 10a
  // both agree to 1e-4 (relative creepage, traction over mu p0), closer than after 3a.
  TangentialProblem steady_problem = cyl.problem();
  const TangentialSolution steady = steady_problem.steady_rolling(cyl.load(), test::native_tangential_solver());
  ASSERT_EQ(steady.report.status, SolveStatus::converged) << steady.report.message;
  const double creep_3a = std::abs(s.amplitudes[0] / steady.amplitudes[0] - 1.0);
  const double tau_3a = max_abs_diff(s.tx, steady.tx) / cyl.mu_p0;
  s = problem.roll(cyl.load(), 7 * a, test::native_tangential_solver());
  const double creep_10a = std::abs(s.amplitudes[0] / steady.amplitudes[0] - 1.0);
  const double tau_10a = max_abs_diff(s.tx, steady.tx) / cyl.mu_p0;
  std::printf("[ vs steady_rolling ] after 3a: creepage %.2e, traction %.2e mu p0; after 10a: %.2e, %.2e\n", creep_3a,
              tau_3a, creep_10a, tau_10a);
  EXPECT_LT(creep_10a, 1e-4);
  EXPECT_LT(tau_10a, 1e-4);
  EXPECT_LT(creep_10a, creep_3a);
  EXPECT_LT(tau_10a, tau_3a);
}

TEST(TransientRolling, SphereRollingHistoryReachesSteadyCreepage) {
  // 3-D smoke check: steel sphere R = 10 mm, 100 N, mu = 0.3, 16 x 16 over +-1.2 a (dx = 0.15 a),
  // F = (-mu P/2, 0) on the body; Cattaneo-Mindlin step, then 2a + 2a of rolling.
  const MaterialPair m{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)};
  const double R = 0.01, P = 100.0, mu = 0.3;
  const auto hz = hertz::sphere(R, P, m.E_star());
  const double a = hz.a, L = 1.2 * a;
  TangentialProblem problem = test::round_body_problem(Grid::make(3, 16, 16, -L, L, -L, L), m, R, mu);
  RollingLoad load;
  load.normal = {Control::force, P};
  load.modes = {resultant(-0.5 * mu * P), resultant(0.0), amplitude(0.0)};
  const TangentialSolution first = problem.roll(load, 0.0, test::native_tangential_solver());
  expect_certified(first);
  EXPECT_GT(first.amplitudes[0], 0.0);  // Cattaneo-Mindlin shift, towards +x
  TangentialSolution s;
  for (int k = 0; k < 2; ++k) {
    s = problem.roll(load, 2 * a, test::native_tangential_solver());
    expect_certified(s);
  }
  EXPECT_EQ(s.marching_steps, 13);  // 2a / 0.15a = 13.3
  const TangentialSolution steady = problem.steady_rolling(load, test::native_tangential_solver());
  ASSERT_EQ(steady.report.status, SolveStatus::converged) << steady.report.message;
  std::printf("[ sphere ] creepage after 4a / steady %.5f\n", s.amplitudes[0] / steady.amplitudes[0]);
  // After 4a the transient is well below 1 % (it decays by about a decade per contact width).
  EXPECT_NEAR(s.amplitudes[0] / steady.amplitudes[0], 1.0, 0.01);
  EXPECT_GT(s.amplitudes[0], 0.0);
  EXPECT_NEAR(s.amplitudes[1], 0.0, 1e-9 * s.amplitudes[0]);  // no lateral creepage by symmetry
  EXPECT_NEAR(s.resultants[0], -0.5 * mu * P, 1e-7 * mu * P);
}

}  // namespace
}  // namespace dc
