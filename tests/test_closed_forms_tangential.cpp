// The frictional closed forms themselves (core/contact_closed_forms): limits, resultants,
// tabulated values, inverse relations.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "contact_closed_forms.hpp"
#include "hertz.hpp"

namespace dc::closed_form {
namespace {

constexpr double kPi = std::numbers::pi;

/// Composite Simpson on [lo, hi] with n (even) panels.
double simpson(const std::function<double(double)>& f, double lo, double hi, int n = 20000) {
  const double h = (hi - lo) / n;
  double s = f(lo) + f(hi);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(lo + i * h);
  return s * h / 3.0;
}

TEST(MindlinClosedForm, LimitsOfTheStickRadiusTractionAndShift) {
  const double a = 1e-3, mu = 0.3, P = 100.0, comp = 2 * (2 - 0.3) / 8e10;
  const double p0 = 3 * P / (2 * kPi * a * a);
  // Q -> 0: full stick, no traction, no shift.
  EXPECT_DOUBLE_EQ(mindlin_stick_radius(a, 0.0), a);
  for (double r : {0.0, 0.3 * a, 0.9 * a}) EXPECT_NEAR(mindlin_traction(r, a, mu * p0, 0.0), 0.0, 1e-9 * mu * p0);
  EXPECT_DOUBLE_EQ(mindlin_shift(mu, P, a, comp, 0.0), 0.0);
  // Q -> mu P: c -> 0, the traction is mu p (full slip) and the shift its full value.
  EXPECT_DOUBLE_EQ(mindlin_stick_radius(a, 1.0), 0.0);
  for (double r : {0.0, 0.3 * a, 0.9 * a})
    EXPECT_NEAR(mindlin_traction(r, a, mu * p0, 1.0), mu * p0 * std::sqrt(1 - r * r / (a * a)), 1e-12 * p0);
  EXPECT_NEAR(mindlin_shift(mu, P, a, comp, 1.0), 3 * mu * P * comp / (16 * a), 1e-20);
  EXPECT_NEAR(mindlin_stick_radius(a, 0.5), a * std::cbrt(0.5), 1e-18);
  // Small Q: Mindlin's initial compliance delta/Q = sum (2-nu)/G / (8a).
  const double q = 1e-6;
  EXPECT_NEAR(mindlin_shift(mu, P, a, comp, q) / (q * mu * P), comp / (8 * a), 1e-5 * comp / (8 * a));
  EXPECT_EQ(mindlin_traction(1.01 * a, a, mu * p0, 0.5), 0.0);
  EXPECT_THROW(mindlin_stick_radius(a, 1.5), std::domain_error);
}

TEST(MindlinClosedForm, TractionIntegratesToTheForceAndStaysBelowTheLimit) {
  const double a = 2e-3, mu = 0.4, P = 50.0;
  const double p0 = 3 * P / (2 * kPi * a * a);
  for (double ratio : {0.1, 0.5, 0.9}) {
    const double Q = simpson([&](double r) { return mindlin_traction(r, a, mu * p0, ratio) * 2 * kPi * r; }, 0, a);
    EXPECT_NEAR(Q / (mu * P), ratio, 1e-6);
    const double c = mindlin_stick_radius(a, ratio);
    for (double r = 0.0; r < a; r += 0.01 * a) {
      const double limit = mu * p0 * std::sqrt(1 - r * r / (a * a));
      EXPECT_LE(mindlin_traction(r, a, mu * p0, ratio), limit * (1 + 1e-12) + 1e-9);
      if (r > c) {
        EXPECT_NEAR(mindlin_traction(r, a, mu * p0, ratio), limit, 1e-9 * mu * p0);
      }
    }
  }
}

TEST(MindlinClosedForm, UnloadingMindlinDeresiewicz) {
  const double a = 1e-3, mu = 0.3, P = 100.0, comp = 5e-11;
  const double p0 = 3 * P / (2 * kPi * a * a);
  const double qs = 0.6;
  // No unloading yet: the loading state.
  EXPECT_NEAR(mindlin_unloading_shift(mu, P, a, comp, qs, qs), mindlin_shift(mu, P, a, comp, qs), 1e-20);
  // Full reversal -Q*: the mirror of the loading state.
  EXPECT_NEAR(mindlin_unloading_shift(mu, P, a, comp, qs, -qs), -mindlin_shift(mu, P, a, comp, qs), 1e-18);
  // At Q = 0 the shift is positive (hysteresis) but smaller than at Q*.
  const double d0 = mindlin_unloading_shift(mu, P, a, comp, qs, 0.0);
  EXPECT_GT(d0, 0.0);
  EXPECT_LT(d0, mindlin_shift(mu, P, a, comp, qs));
  // Residual traction at Q = 0: nonzero, zero resultant.
  const double R = simpson([&](double r) { return mindlin_unloading_traction(r, a, mu * p0, qs, 0.0) * 2 * kPi * r; }, 0, a);
  EXPECT_NEAR(R / (mu * P), 0.0, 1e-6);
  EXPECT_GT(std::abs(mindlin_unloading_traction(0.9 * a, a, mu * p0, qs, 0.0)), 0.05 * mu * p0);
  // Unloading traction at Q integrates to Q.
  const double Rq = simpson([&](double r) { return mindlin_unloading_traction(r, a, mu * p0, qs, 0.2) * 2 * kPi * r; }, 0, a);
  EXPECT_NEAR(Rq / (mu * P), 0.2, 1e-6);
  EXPECT_THROW(mindlin_unloading_shift(mu, P, a, comp, 0.5, 0.7), std::domain_error);
}

TEST(CarterClosedForm, LimitsAndResultant) {
  const double a = 1e-3, R = 0.05, mu = 0.25, P = 2e5;
  const double p0 = 2 * P / (kPi * a);
  // F = 0: no creepage, stick everywhere, no traction.
  EXPECT_DOUBLE_EQ(carter_creepage(a, R, mu, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(carter_stick_half_width(a, 0.0), a);
  for (double x : {-0.9 * a, 0.0, 0.5 * a}) EXPECT_NEAR(carter_traction(x, a, p0, mu, 0.0), 0.0, 1e-9 * p0);
  // |F| = mu P: gross sliding at creepage mu a / R, traction -mu p everywhere.
  EXPECT_NEAR(carter_creepage(a, R, mu, -1.0), mu * a / R, 1e-15);
  EXPECT_DOUBLE_EQ(carter_stick_half_width(a, 1.0), 0.0);
  for (double x : {-0.9 * a, 0.0, 0.5 * a})
    EXPECT_NEAR(carter_traction(x, a, p0, mu, -1.0), -mu * p0 * std::sqrt(1 - x * x / (a * a)), 1e-9 * p0);
  // Resultant equals F (both signs); the traction has the sign of F.
  for (double f : {-0.5, 0.3, -0.9}) {
    const double F = simpson([&](double x) { return carter_traction(x, a, p0, mu, f); }, -a, a);
    EXPECT_NEAR(F / (mu * P), f, 1e-6);
    EXPECT_GE(carter_traction(0.99 * a, a, p0, mu, f) * f, 0.0);
  }
  // Creepage <-> force are inverse; saturation beyond mu a/R; small-creepage slope 2 R/(mu a).
  for (double f : {0.0, 0.1, 0.5, 0.99}) EXPECT_NEAR(carter_force_ratio(a, R, mu, carter_creepage(a, R, mu, f)), f, 1e-12);
  EXPECT_EQ(carter_force_ratio(a, R, mu, 2 * mu * a / R), 1.0);
  EXPECT_NEAR(carter_force_ratio(a, R, mu, 1e-9) / 1e-9, 2 * R / (mu * a), 1e-6 * R / (mu * a));
}

TEST(CarterClosedForm, StickZoneSitsAtTheLeadingEdge) {
  const double a = 1.0, p0 = 1.0, mu = 0.5, f = -0.5;
  const double ap = carter_stick_half_width(a, f);
  EXPECT_NEAR(ap, a * std::sqrt(0.5), 1e-15);
  for (double x = -a + 0.005; x < a; x += 0.01) {
    const double limit = mu * p0 * std::sqrt(1 - x * x);
    const double t = std::abs(carter_traction(x, a, p0, mu, f));
    if (x < a - 2 * ap - 1e-9) {
      EXPECT_NEAR(t, limit, 1e-12) << x;  // trailing slip zone
    } else if (x > a - 2 * ap + 1e-3) {
      EXPECT_LT(t, limit) << x;  // leading stick zone
    }
  }
  // In the stick zone the traction derivative equals that of the Hertz-shaped difference:
  // tau/(mu p0) = sqrt(1-x^2) - (a'/a) sqrt(1-((x-d)/a')^2) at the stick centre d = a - a'.
  const double d = a - ap;
  EXPECT_NEAR(carter_traction(d, a, p0, mu, f), -mu * p0 * (std::sqrt(1 - d * d) - ap), 1e-14);
}

TEST(Cattaneo2dClosedForm, CentredStickZoneResultantAndCarterShift) {
  const double a = 1e-3, mu = 0.25, P = 2e5;
  const double p0 = 2 * P / (kPi * a);
  // Q = 0: full stick, no traction; |Q| = mu P: full slip, -mu p on the body for Q < 0.
  EXPECT_DOUBLE_EQ(cattaneo_2d_stick_half_width(a, 0.0), a);
  EXPECT_DOUBLE_EQ(cattaneo_2d_stick_half_width(a, -1.0), 0.0);
  for (double x : {-0.9 * a, 0.0, 0.5 * a}) {
    EXPECT_NEAR(cattaneo_2d_traction(x, a, p0, mu, 0.0), 0.0, 1e-9 * p0);
    EXPECT_NEAR(cattaneo_2d_traction(x, a, p0, mu, -1.0), -mu * p0 * std::sqrt(1 - x * x / (a * a)), 1e-9 * p0);
  }
  EXPECT_EQ(cattaneo_2d_traction(1.01 * a, a, p0, mu, 0.5), 0.0);
  EXPECT_THROW(cattaneo_2d_traction(0.0, a, p0, mu, 1.5), std::domain_error);
  for (double f : {-0.5, 0.3, -0.9}) {
    // Resultant Q, even in x (centred stick zone), full slip |tau| = mu p outside |x| < c.
    const double Q = simpson([&](double x) { return cattaneo_2d_traction(x, a, p0, mu, f); }, -a, a);
    EXPECT_NEAR(Q / (mu * P), f, 1e-6);
    const double c = cattaneo_2d_stick_half_width(a, f);
    EXPECT_NEAR(c, a * std::sqrt(1 - std::abs(f)), 1e-15);
    for (double x : {0.1 * a, 0.5 * a, 0.95 * a}) {
      EXPECT_DOUBLE_EQ(cattaneo_2d_traction(x, a, p0, mu, f), cattaneo_2d_traction(-x, a, p0, mu, f));
      if (x > c) {
        EXPECT_NEAR(std::abs(cattaneo_2d_traction(x, a, p0, mu, f)), mu * p0 * std::sqrt(1 - x * x / (a * a)),
                    1e-9 * p0);
      }
    }
    // The same stick half-length as Carter at that force; the stick term mu p0 (c/a)
    // sqrt(1 - (x/c)^2) taken off the full-slip traction sits at x here, at x + (a - c) in Carter's.
    EXPECT_DOUBLE_EQ(c, carter_stick_half_width(a, f));
    const double sign = f < 0 ? -1.0 : 1.0, x = 0.3 * c, d = a - c;
    const double term = sign * mu * p0 * (c / a) * std::sqrt(1 - 0.3 * 0.3);
    auto slip = [&](double s) { return sign * mu * p0 * std::sqrt(1 - s * s / (a * a)); };
    EXPECT_NEAR(slip(x) - cattaneo_2d_traction(x, a, p0, mu, f), term, 1e-9 * p0);
    EXPECT_NEAR(slip(x + d) - carter_traction(x + d, a, p0, mu, f), term, 1e-9 * p0);
  }
}

TEST(LubkinClosedForm, StiffnessAndSlipMoment) {
  const auto steel = Elastic::from_E_nu(2.1e11, 0.3);
  const double a = 1e-3;
  EXPECT_NEAR(lubkin_stick_stiffness(a, {steel, steel}), 8.0 / 3.0 * steel.G * a * a * a, 1e-9 * steel.G * a * a * a);
  EXPECT_NEAR(lubkin_stick_stiffness(a, {Elastic::make_rigid(), steel}), 16.0 / 3.0 * steel.G * a * a * a,
              1e-9 * steel.G * a * a * a);
  EXPECT_THROW(lubkin_stick_stiffness(a, {Elastic::make_rigid(), Elastic::make_rigid()}), std::domain_error);
  // Full slip: M = int mu p r dA with the Hertz pressure.
  const double mu = 0.3, P = 10.0;
  const double p0 = 3 * P / (2 * kPi * a * a);
  const double M = simpson([&](double r) { return mu * p0 * std::sqrt(std::max(0.0, 1 - r * r / (a * a))) * r * 2 * kPi * r; }, 0, a);
  EXPECT_NEAR(lubkin_slip_moment(mu, P, a) / M, 1.0, 1e-6);
}

TEST(KalkerClosedForm, TableValuesAndInterpolation) {
  // Kalker (1990) / Johnson Table 8.1, a/b = 1.
  const auto k0 = kalker_circular(0.0), k1 = kalker_circular(0.25), k2 = kalker_circular(0.5);
  EXPECT_EQ(k0.c11, 3.40);
  EXPECT_EQ(k0.c22, 3.40);
  EXPECT_EQ(k0.c23, 1.33);
  EXPECT_EQ(k1.c11, 4.12);
  EXPECT_EQ(k1.c22, 3.67);
  EXPECT_EQ(k1.c23, 1.47);
  EXPECT_EQ(k2.c11, 5.20);
  EXPECT_EQ(k2.c22, 3.98);
  EXPECT_EQ(k2.c23, 1.63);
  // At nu = 0 longitudinal and lateral are the same problem.
  EXPECT_EQ(k0.c11, k0.c22);
  const auto km = kalker_circular(0.125), kq = kalker_circular(0.375);
  EXPECT_NEAR(km.c11, 0.5 * (3.40 + 4.12), 1e-14);
  EXPECT_NEAR(kq.c22, 0.5 * (3.67 + 3.98), 1e-14);
  EXPECT_NEAR(kalker_circular(0.28).c11, 4.12 + 0.12 * (5.20 - 4.12), 1e-14);
  EXPECT_THROW(kalker_circular(-0.1), std::domain_error);
  EXPECT_THROW(kalker_circular(0.6), std::domain_error);
  // Forces: opposite to the creepage, linear, spin enters F_y with c^3.
  const double G = 8e10, c = 2e-3;
  const auto f = kalker_linear_forces(G, c, k1, 1e-4, -2e-4, 0.05);
  EXPECT_NEAR(f.fx, -G * c * c * 4.12 * 1e-4, 1e-9);
  EXPECT_NEAR(f.fy, G * c * c * 3.67 * 2e-4 - G * c * c * c * 1.47 * 0.05, 1e-9);
}

TEST(SpenceClosedForm, DundursBeta) {
  const auto steel = Elastic::from_E_nu(2.1e11, 0.3);
  EXPECT_NEAR(dundurs_beta({steel, steel}), 0.0, 1e-15);
  // Rigid body on an elastic substrate: beta = -(1-2nu)/(2(1-nu)); incompressible -> 0.
  EXPECT_NEAR(dundurs_beta({Elastic::make_rigid(), steel}), -0.4 / 1.4, 1e-14);
  EXPECT_NEAR(dundurs_beta({steel, Elastic::make_rigid()}), 0.4 / 1.4, 1e-14);
  EXPECT_NEAR(dundurs_beta({Elastic::make_rigid(), Elastic::from_E_nu(1e6, 0.4999999)}), 0.0, 1e-6);
  const auto al = Elastic::from_E_nu(7e10, 0.33);
  EXPECT_NEAR(dundurs_beta({steel, al}), -dundurs_beta({al, steel}), 1e-15);
  EXPECT_LE(std::abs(dundurs_beta({steel, al})), 0.5);
}

TEST(SpenceClosedForm, StickRatioLimitsAndInverse) {
  // beta/mu -> 0 (mu -> infinity): full stick; beta/mu -> infinity (frictionless): c/a ~ 4 exp(-beta/mu).
  EXPECT_EQ(spence_stick_ratio(0.0), 1.0);
  EXPECT_GT(spence_stick_ratio(1e-3), 0.999999);
  EXPECT_NEAR(spence_stick_ratio(12.0) / (4 * std::exp(-12.0)), 1.0, 1e-3);
  // Monotone decreasing, and inverse of spence_beta_over_mu.
  double last = 1.0;
  for (double r : {0.3, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0}) {  // below ~0.2, c/a rounds to 1
    const double t = spence_stick_ratio(r);
    EXPECT_LT(t, last);
    last = t;
    EXPECT_NEAR(spence_beta_over_mu(t), r, 1e-10 * r);
    EXPECT_NEAR(spence_stick_ratio(-r), t, 0.0);  // only |beta| matters
  }
  // Values of 2 t K'(t) / ln((1+t)/(1-t)) computed independently (mpmath, 30 digits).
  EXPECT_NEAR(spence_beta_over_mu(0.5), 1.96294513518874874, 1e-12);
  EXPECT_NEAR(spence_beta_over_mu(0.7), 1.50334113724056145, 1e-12);
  EXPECT_NEAR(spence_beta_over_mu(0.9), 1.01150338744112700, 1e-12);
  // The same via K of the complementary parameter (hertz::ellipk takes m = k^2).
  const double t = 0.6;
  EXPECT_NEAR(spence_beta_over_mu(t), 2 * t * hertz::ellipk(1 - t * t) / std::log((1 + t) / (1 - t)), 1e-13);
  EXPECT_THROW(spence_beta_over_mu(1.0), std::domain_error);
}

}  // namespace
}  // namespace dc::closed_form
