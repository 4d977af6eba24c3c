// The paper's Section 5 cylinder (dynamics/paper_cylinder): the traction law inverts (5.3)
// (and the printed (5.10) does not), the quasi-static limit derived from (5.3), (5.7), (5.9),
// the orders of BDF1/BDF2, stability of the implicit steps where the slip is stiff
// (eps = 1e-3), the onset of gross sliding, eta = inf (no rotational inertia), bad inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "contact_closed_forms.hpp"
#include "errors.hpp"
#include "paper_cylinder.hpp"

namespace dc {
namespace {

namespace pc = paper_cylinder;

TEST(PaperCylinder, ForceLawInvertsCarterPoritsky53AndThePrinted510DoesNot) {
  for (double F = -0.999; F <= 0.999; F += 0.037) {
    // (5.3): v/(mu eps V) = -[1 - (1 + F/(mu P))^(1/2)] for F <= 0 (mirrored for F > 0).
    const double s = F <= 0.0 ? -(1.0 - std::sqrt(1.0 + F)) : 1.0 - std::sqrt(1.0 - F);
    EXPECT_NEAR(pc::force_ratio(s), F, 1e-14) << "F/(mu P) = " << F;
    // The same law as Carter's creep law in core (creepage xi = s mu a / R, here a/R = 0.01).
    EXPECT_NEAR(std::abs(pc::force_ratio(s)), closed_form::carter_force_ratio(0.01, 1.0, 0.3, s * 0.3 * 0.01), 1e-12);
    // Slope against a central difference.
    const double h = 1e-6;
    if (std::abs(s) < 1.0 - 2 * h) {
      EXPECT_NEAR(pc::force_ratio_slope(s), (pc::force_ratio(s + h) - pc::force_ratio(s - h)) / (2 * h), 1e-6);
    }
  }
  // Printed (5.10): M dV/dt = mu P [(1 + s)^(1/2) - 1] + T, i.e. -F/(mu P) = (1 + s)^(1/2) - 1.
  // At s = -1/2 (a driven cylinder) that gives F/(mu P) = +0.29 (braking) instead of -0.75.
  const double s = -0.5, printed = -(std::sqrt(1.0 + s) - 1.0);
  EXPECT_NEAR(pc::force_ratio(s), -0.75, 1e-15);
  EXPECT_GT(std::abs(printed - pc::force_ratio(s)), 1.0);
  // Saturation: gross sliding carries mu P.
  EXPECT_EQ(pc::force_ratio(-3.0), -1.0);
  EXPECT_EQ(pc::force_ratio_slope(-3.0), 0.0);
}

pc::Parameters figure_parameters(double eta, double epsilon) {
  pc::Parameters p;
  p.gamma_bar = 0.5;
  p.M0_bar = 0.2;
  p.eta = eta;
  p.epsilon = epsilon;
  p.t_bar_end = 1.0;
  // Start on the quasi-static slip of M0 (no initial layer).
  p.v_bar0 = pc::quasi_static(p, 0.0).v_bar;
  return p;
}

TEST(PaperCylinder, SmallEpsilonFollowsTheDerivedQuasiStaticLimit) {
  // eps = 1e-4: the slip lags the quasi-static one by O(eps) (relaxation time eps/(2(1+eta))),
  // BDF2 with dt = 1e-3 adds O(dt^2): F^, u, l^ within 10 eps = 1e-3, v^ within 1e-3 relative.
  const pc::Parameters p = figure_parameters(2.0, 1e-4);
  const pc::Run run = pc::simulate(p, 1e-3, pc::Scheme::bdf2);
  ASSERT_TRUE(run.ok) << run.message;
  for (std::size_t k = 100; k < run.samples.size(); k += 100) {
    const pc::Sample& s = run.samples[k];
    const pc::Sample q = pc::quasi_static(p, s.t_bar);
    EXPECT_NEAR(s.F_bar, q.F_bar, 1e-3) << "t = " << s.t_bar;
    EXPECT_NEAR(s.u, q.u, 1e-3) << "t = " << s.t_bar;
    EXPECT_NEAR(s.l_bar, q.l_bar, 1e-3) << "t = " << s.t_bar;
    EXPECT_NEAR(s.v_bar / q.v_bar, 1.0, 1e-3) << "t = " << s.t_bar;
  }
  const pc::Sample& last = run.samples.back();
  std::printf("[ quasi-static ] t = %.3f: F %.6f (%.6f), u %.6f (%.6f), v %.6f (%.6f)\n", last.t_bar, last.F_bar,
              pc::quasi_static(p, last.t_bar).F_bar, last.u, pc::quasi_static(p, last.t_bar).u, last.v_bar,
              pc::quasi_static(p, last.t_bar).v_bar);
}

TEST(PaperCylinder, Bdf1IsFirstOrderAndBdf2SecondOrder) {
  // A non-stiff case (eps = 0.5) against a fine BDF2 reference: halving dt divides the error at
  // t^ = 1 by ~2 (BDF1) and ~4 (BDF2).
  pc::Parameters p = figure_parameters(2.0, 0.5);
  p.v_bar0 = 0.0;  // away from the slow manifold: both unknowns move
  const pc::Sample ref = pc::simulate(p, 1e-4, pc::Scheme::bdf2).samples.back();
  auto error = [&](double dt, pc::Scheme scheme) {
    const pc::Sample s = pc::simulate(p, dt, scheme).samples.back();
    return std::hypot(s.u - ref.u, s.w - ref.w);
  };
  const double r1 = error(0.02, pc::Scheme::bdf1) / error(0.01, pc::Scheme::bdf1);
  const double r2 = error(0.02, pc::Scheme::bdf2) / error(0.01, pc::Scheme::bdf2);
  std::printf("[ orders ] error ratios for dt 0.02 -> 0.01: BDF1 %.3f, BDF2 %.3f\n", r1, r2);
  EXPECT_NEAR(r1, 2.0, 0.2);
  EXPECT_NEAR(r2, 4.0, 0.5);
}

TEST(PaperCylinder, ImplicitStepsStayStableWhereTheSlipIsStiff) {
  // eps = 1e-3, eta = 2: the slip relaxes in eps/(2(1 + eta)) ~ 1.7e-4; dt = 0.02 is 120 times
  // that. The implicit steps stay on the slow manifold (F^ increasing with the moment, within
  // 0.01 of the quasi-static limit: O(dt) for BDF1); an explicit step of the slip equation with
  // the same dt multiplies a slip error by |1 - dt phi'/(c eps u)| ~ 120 and blows up.
  const pc::Parameters p = figure_parameters(2.0, 1e-3);
  const double dt = 0.02;
  for (pc::Scheme scheme : {pc::Scheme::bdf1, pc::Scheme::bdf2}) {
    const pc::Run run = pc::simulate(p, dt, scheme);
    ASSERT_TRUE(run.ok) << run.message;
    for (std::size_t k = 1; k < run.samples.size(); ++k) {
      EXPECT_GT(run.samples[k].F_bar, run.samples[k - 1].F_bar);
      EXPECT_NEAR(run.samples[k].F_bar, pc::quasi_static(p, run.samples[k].t_bar).F_bar, 0.01);
    }
  }
  // Explicit Euler on the same equations and dt.
  const double c = 1.0 / (1.0 + p.eta);
  double u = 1.0, w = -p.v_bar0;
  bool blew_up = false;
  for (int n = 0; n < 50 && !blew_up; ++n) {
    const double t = n * dt, phi = pc::force_ratio(w / u);
    const double du = -phi, dw = (-phi - (1.0 - c) * (p.M0_bar + p.gamma_bar * t)) / (c * p.epsilon);
    u += dt * du;
    w += dt * dw;
    blew_up = !(u > 0.0) || std::abs(w / u) > 10.0;
  }
  EXPECT_TRUE(blew_up);
}

TEST(PaperCylinder, GrossSlidingStartsWhereTheFrictionForceReachesMuP) {
  // Quasi-statically F^ = eta/(1+eta) M^(t) reaches 1 at t* = ((1+eta)/eta - M0^)/gamma^ = 1;
  // from then on F^ = 1, du/dt^ = 1 (the friction force alone accelerates the axis) and the
  // slip grows (the cylinder spins up).
  pc::Parameters p;
  p.eta = 2.0;
  p.epsilon = 1e-4;
  p.gamma_bar = 1.0;
  p.M0_bar = 0.5;
  p.v_bar0 = pc::quasi_static(p, 0.0).v_bar;
  p.t_bar_end = 1.5;
  const double dt = 1e-3, t_star = ((1.0 + p.eta) / p.eta - p.M0_bar) / p.gamma_bar;
  const pc::Run run = pc::simulate(p, dt, pc::Scheme::bdf2);
  ASSERT_TRUE(run.ok) << run.message;
  double onset = -1.0;
  for (const pc::Sample& s : run.samples)
    if (s.sliding) {
      onset = s.t_bar;
      break;
    }
  std::printf("[ gross sliding ] onset t = %.4f (quasi-static %.4f)\n", onset, t_star);
  EXPECT_NEAR(onset, t_star, 0.01);
  for (std::size_t k = 1; k < run.samples.size(); ++k) {
    const pc::Sample &a = run.samples[k - 1], &b = run.samples[k];
    if (!a.sliding || b.t_bar < t_star + 0.05) continue;
    EXPECT_EQ(b.F_bar, 1.0);
    EXPECT_EQ(b.l_bar, 0.0);
    EXPECT_NEAR((b.u - a.u) / dt, 1.0, 1e-9);
    EXPECT_GT(b.v_bar, a.v_bar);
  }
}

TEST(PaperCylinder, MassDistributionOrdersTheFrictionForceAndEtaInfinityIsAlgebraic) {
  // Fig. 6: at the same time F^ grows with eta (ring 1 < solid 2 < mass on the axis inf); for
  // eta = inf (I = 0) (5.8) makes F^ = M^ exactly at every step, and the run stops with a
  // message when M^ reaches 1 (nothing resists the spin-up).
  double previous = 0.0;
  for (double eta : {1.0, 2.0, std::numeric_limits<double>::infinity()}) {
    const pc::Parameters p = figure_parameters(eta, 1e-3);
    const pc::Run run = pc::simulate(p, 1e-2, pc::Scheme::bdf2);
    ASSERT_TRUE(run.ok) << run.message;
    EXPECT_GT(run.samples.back().F_bar, previous) << "eta = " << eta;
    previous = run.samples.back().F_bar;
    if (std::isinf(eta)) {
      for (const pc::Sample& s : run.samples) EXPECT_NEAR(s.F_bar, p.M0_bar + p.gamma_bar * s.t_bar, 1e-12);
    }
  }
  pc::Parameters p = figure_parameters(std::numeric_limits<double>::infinity(), 1e-3);
  p.t_bar_end = 3.0;  // M^ = 0.2 + 0.5 t reaches 1 at t = 1.6
  const pc::Run run = pc::simulate(p, 1e-2, pc::Scheme::bdf1);
  EXPECT_FALSE(run.ok);
  EXPECT_NE(run.message.find("spins freely"), std::string::npos) << run.message;
  EXPECT_NEAR(run.samples.back().t_bar, 1.6, 0.011);
}

TEST(PaperCylinder, BadParametersNameTheKey) {
  auto expect_key = [](pc::Parameters p, const std::string& key) {
    try {
      pc::simulate(p, 1e-2, pc::Scheme::bdf1);
      ADD_FAILURE() << "no error for " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  pc::Parameters p;
  p.eta = 0.0;
  expect_key(p, "dimensionless.eta");
  p = {};
  p.epsilon = -1e-3;
  expect_key(p, "dimensionless.epsilon");
  p = {};
  p.v_bar0 = -0.1;
  expect_key(p, "dimensionless.v_bar0");
  p = {};
  p.t_bar_end = 0.0;
  expect_key(p, "dimensionless.t_bar_end");
}

}  // namespace
}  // namespace dc
