// The closed forms themselves (core/hertz): tabulated elliptic integrals, limits, identities.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hertz.hpp"

namespace dc::hertz {
namespace {

TEST(HertzClosedForms, EllipticIntegralsMatchTables) {
  // Abramowitz & Stegun, Table 17.1: K(0.5), E(0.5); K(0) = E(0) = pi/2; E(1) = 1.
  EXPECT_NEAR(ellipk(0.5), 1.8540746773013719, 1e-15);
  EXPECT_NEAR(ellipe(0.5), 1.3506438810476755, 1e-15);
  EXPECT_NEAR(ellipk(0.9), 2.5780921133481733, 1e-14);
  EXPECT_NEAR(ellipe(0.9), 1.1047747327040733, 1e-14);
  EXPECT_DOUBLE_EQ(ellipk(0.0), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(ellipe(0.0), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(ellipe(1.0), 1.0);
}

TEST(HertzClosedForms, SphereRelations) {
  const double R = 0.01, P = 100.0, Es = 1.2e11;
  const auto s = sphere(R, P, Es);
  EXPECT_NEAR(s.a, std::cbrt(3 * P * R / (4 * Es)), 1e-18);
  EXPECT_NEAR(s.p0, 2 * s.a * Es / (std::numbers::pi * R), 1e-6 * s.p0);  // p0 = 2aE*/(pi R)
  EXPECT_NEAR(P, 2.0 / 3.0 * std::numbers::pi * s.a * s.a * s.p0, 1e-9 * P);
}

TEST(HertzClosedForms, EllipticReducesToSphere) {
  const double R = 0.02, P = 50.0, Es = 7e10;
  const auto s = sphere(R, P, Es);
  const auto e = elliptic(1 / (2 * R), 1 / (2 * R) * (1 + 1e-12), P, Es);
  EXPECT_NEAR(e.a / s.a, 1.0, 1e-6);
  EXPECT_NEAR(e.b / s.a, 1.0, 1e-6);
  EXPECT_NEAR(e.approach / s.approach, 1.0, 1e-6);
  EXPECT_NEAR(e.p0 / s.p0, 1.0, 1e-6);
}

TEST(HertzClosedForms, EllipticMatchesJohnsonTable) {
  // The defining relation (Johnson 4.2) B/A = [(a/b)^2 E(e) - K(e)] / [K(e) - E(e)] and
  // P = 2/3 pi a b p0 must hold for the returned semi-axes.
  for (double ratio : {1.5, 4.0, 20.0, 150.0}) {
    const auto e = elliptic(1.0, ratio, 10.0, 1e11);
    ASSERT_GT(e.a, e.b);
    const double m = 1 - (e.b / e.a) * (e.b / e.a);
    const double K = ellipk(m), E = ellipe(m);
    EXPECT_NEAR(((e.a / e.b) * (e.a / e.b) * E - K) / (K - E), ratio, 1e-8 * ratio);
    EXPECT_NEAR(10.0, 2.0 / 3.0 * std::numbers::pi * e.a * e.b * e.p0, 1e-9);
    // Hamrock & Brewe's fit a/b = 1.0339 (B/A)^0.636 (a fit good to ~3 %).
    if (ratio <= 20.0) {
      EXPECT_NEAR(e.a / e.b, 1.0339 * std::pow(ratio, 0.636), 0.03 * e.a / e.b);
    }
  }
  // Swapping the curvatures swaps the axes.
  const auto e1 = elliptic(1.0, 3.0, 10.0, 1e11), e2 = elliptic(3.0, 1.0, 10.0, 1e11);
  EXPECT_DOUBLE_EQ(e1.a, e2.b);
  EXPECT_DOUBLE_EQ(e1.b, e2.a);
}

TEST(HertzClosedForms, CylinderAndPunch) {
  const auto c = cylinder2d(0.02, 1e5, 1e11);
  EXPECT_NEAR(c.a, std::sqrt(4 * 1e5 * 0.02 / (std::numbers::pi * 1e11)), 1e-15);
  EXPECT_NEAR(c.p0, 2 * 1e5 / (std::numbers::pi * c.a), 1e-6);
  EXPECT_DOUBLE_EQ(flat_punch_force(1e-3, 1e-6, 1e11), 2 * 1e-3 * 1e11 * 1e-6);
  EXPECT_EQ(flat_punch_pressure(1e-3, 10, 2e-3), 0.0);
  EXPECT_NEAR(flat_punch_pressure(1e-3, 10, 0.0), 10 / (2 * std::numbers::pi * 1e-6), 1e-3);
}

TEST(HertzClosedForms, SphereImpact) {
  // Johnson 11.4: the kinetic energy is the elastic energy at the deepest approach,
  // 1/2 m v^2 = 8/15 E* sqrt(R) delta^(5/2); the 10 mm steel ball (32.7 g) at 1 m/s on steel:
  // peak force 1.74 kN, contact time 69 us (examples/ball-impact.json).
  const double E = 2.1e11 / (2.0 * (1.0 - 0.09)), R = 0.01, m = 0.032673, v = 1.0;
  const ImpactSolution s = sphere_impact(R, m, v, E);
  EXPECT_NEAR(8.0 / 15.0 * E * std::sqrt(R) * std::pow(s.approach, 2.5) / (0.5 * m * v * v), 1.0, 1e-12);
  EXPECT_NEAR(s.force, 1744.0, 2.0);
  EXPECT_NEAR(s.duration, 6.89e-5, 0.01e-5);
  EXPECT_NEAR(s.duration * v / s.approach, 2.9432751843, 1e-9);  // (4/5) B(2/5, 1/2)
  EXPECT_EQ(sphere_impact(R, m, -v, E).duration, s.duration);  // a downward speed as an upward one
}

}  // namespace
}  // namespace dc::hertz
