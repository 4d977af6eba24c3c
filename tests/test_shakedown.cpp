// Melan shakedown of a moving load as a convex program (nlp/shakedown_problem.hpp), its
// certificate and its per-depth cross-check (nlp/shakedown_by_depth.hpp), against the line
// rolling contact's classical limits (K. L. Johnson, Contact Mechanics, Cambridge 1985, sections
// 4.2 and 7.2, chapter 9; K. L. Johnson, J. A. Jefferis, Proc. Symp. Fatigue in Rolling Contact,
// IMechE 1963): McEwen's closed-form field (core/subsurface_closed_forms.hpp via tests/support/mcewen_reference.hpp), a = p0 = 1, nu = 0.3.
//
// Sampling (unless a test says otherwise): depths z_j = 0.02 a j, j = 0..63 (0 to 1.26 a, the
// surface and z = 0.5 a among them) x positions x_i = -3 a + 6 a i / 255, i = 0..255 (dx =
// 0.0235 a): the brief's 64 x 256. Melan's discrete limit is an upper bound of the continuous one
// sampled more finely (fewer constraints); with this sampling the sampled limits lie within 2e-4
// of the continuous ones (the orthogonal shear's peak is flat in x: its error is second order in
// dx), so the literature values are checked to 0.2 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "mcewen_reference.hpp"
#include "shakedown_3d.hpp"
#include "shakedown_by_depth.hpp"
#include "shakedown_problem.hpp"
#include "shakedown_samples.hpp"
#include "subsurface_closed_forms.hpp"
#include "subsurface_field.hpp"

namespace dc::shakedown_tests {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNu = 0.3;

/// The McEwen field of p0 = 1 (a = 1) with traction mu_t p on the sampling of the header, every
/// stress times `p0` (the load as given, for the verdict).
StressHistory line_contact_history(double mu_t, int depths = 64, int positions = 256, double dz = 0.02,
                                   double half_span = 3.0, double p0 = 1.0) {
  StressHistory h;
  for (int j = 0; j < depths; ++j) h.depths.push_back(dz * j);
  for (int i = 0; i < positions; ++i) h.positions.push_back(-half_span + 2.0 * half_span * i / (positions - 1));
  for (const double z : h.depths)
    for (const double x : h.positions) h.stress.push_back(test::mcewen_voigt(x, z, 1.0, p0, mu_t * p0, kNu));
  return h;
}

/// The largest |sigma_xz| / p0 of McEwen's field on a fine scan (z to 1.5 a in steps of 0.0025 a,
/// x in [-3, 3] a in steps of 0.0025 a): independent of the program.
double max_orthogonal_shear(double mu_t) {
  double best = 0.0;
  for (int j = 0; j <= 600; ++j)
    for (int i = 0; i <= 2400; ++i)
      best = std::max(best, std::abs(test::mcewen_stress(-3.0 + 0.0025 * i, 0.0025 * j, 1.0, 1.0, mu_t).xz));
  return best;
}

/// Flamant's line-load kernels (Johnson 1985 chapter 2, z into the solid) integrated over the
/// Hertz pressure and traction, s = a sin(theta), by the midpoint rule in theta.
test::LineContactStress flamant_quadrature(double x, double z, double mu_t, int n) {
  test::LineContactStress s;
  for (int k = 0; k < n; ++k) {
    const double theta = -kPi / 2 + (k + 0.5) * kPi / n;
    const double weight = std::cos(theta) * std::cos(theta) * kPi / n;  // sqrt(1 - s^2) ds
    const double dx = x - std::sin(theta), r2 = dx * dx + z * z, c = 2.0 / kPi * weight / (r2 * r2);
    s.xx -= c * (dx * dx * z + mu_t * dx * dx * dx);
    s.zz -= c * (z * z * z + mu_t * dx * z * z);
    s.xz -= c * (dx * z * z + mu_t * dx * dx * z);
  }
  return s;
}

TEST(ShakedownMcEwenReference, MatchesFlamantQuadrature) {
  // 2e5 midpoints resolve the kernels down to z = 0.05 a: agreement to 1e-7 p0.
  for (const double mu_t : {0.0, 0.3})
    for (const auto& [x, z] : std::vector<std::pair<double, double>>{
             {0.3, 0.2}, {-0.7, 0.5}, {0.87, 0.5}, {1.5, 0.3}, {-2.0, 1.0}, {0.1, 1.2}, {-0.4, 0.05}}) {
      const auto m = test::mcewen_stress(x, z, 1.0, 1.0, mu_t);
      const auto f = flamant_quadrature(x, z, mu_t, 200000);
      EXPECT_NEAR(m.xx, f.xx, 1e-7) << "x " << x << " z " << z << " mu " << mu_t;
      EXPECT_NEAR(m.zz, f.zz, 1e-7) << "x " << x << " z " << z << " mu " << mu_t;
      EXPECT_NEAR(m.xz, f.xz, 1e-7) << "x " << x << " z " << z << " mu " << mu_t;
    }
}

TEST(ShakedownMcEwenReference, AxisAndSurfaceValues) {
  for (const double z : {0.0, 0.1, 0.5, 0.786, 1.0, 3.0}) {
    const auto s = test::mcewen_stress(0.0, z, 1.0, 1.0, 0.0);
    const double r = std::sqrt(1.0 + z * z);
    EXPECT_NEAR(s.zz, -1.0 / r, 1e-14) << z;                      // -p0 a / sqrt(a^2 + z^2)
    EXPECT_NEAR(s.xx, -((1.0 + 2.0 * z * z) / r - 2.0 * z), 1e-14) << z;  // -p0 [(a^2+2z^2)/(a r) - 2z/a]
    EXPECT_NEAR(s.xz, 0.0, 1e-15) << z;
  }
  // The orthogonal shear's extremes: -/+ 0.25 p0 at z = a/2, x = +/- (sqrt 3 / 2) a = 0.866 a
  // (there m^2 = 3/4, n^2 = 1/4 exactly), and nothing larger on a fine scan.
  EXPECT_NEAR(test::mcewen_stress(std::sqrt(3.0) / 2, 0.5, 1.0, 1.0, 0.0).xz, -0.25, 1e-15);
  EXPECT_NEAR(test::mcewen_stress(-std::sqrt(3.0) / 2, 0.5, 1.0, 1.0, 0.0).xz, 0.25, 1e-15);
  EXPECT_NEAR(max_orthogonal_shear(0.0), 0.25, 2e-6);  // the scan's step 0.0025 a misses the peak by 8e-7
  // The surface under traction: sigma_zz = -p, sigma_xz = -q, sigma_xx = -p - 2 q0 x / a inside.
  for (const double x : {-0.9, -0.3, 0.0, 0.5, 0.95}) {
    const auto s = test::mcewen_stress(x, 0.0, 1.0, 1.0, 0.2);
    const double p = std::sqrt(1.0 - x * x);
    EXPECT_NEAR(s.zz, -p, 1e-14);
    EXPECT_NEAR(s.xz, -0.2 * p, 1e-14);
    EXPECT_NEAR(s.xx, -p - 0.4 * x, 1e-14);
  }
  // Tresca first yield: the largest principal shear 0.300 p0 at z = 0.786 a on the axis.
  double tau1 = 0.0;
  for (int j = 0; j <= 2000; ++j) {
    const auto s = test::mcewen_stress(0.0, 0.001 * j, 1.0, 1.0, 0.0);
    tau1 = std::max(tau1, std::hypot(0.5 * (s.xx - s.zz), s.xz));
  }
  EXPECT_NEAR(tau1, 0.3003, 5e-4);
}

/// The program's answer checked by its own certificate and by the per-depth bisection to 1e-6.
void expect_certified(const ShakedownResult& r, const StressHistory& h, const YieldCriterion& y,
                      const ResidualModel& model = ResidualModel::line_contact()) {
  ASSERT_EQ(r.status, ShakedownStatus::optimal) << r.message;
  EXPECT_LE(r.certificate.yield_violation, 1e-7);
  EXPECT_LE(r.certificate.duality_gap, 1e-7);
  EXPECT_GE(r.certificate.duality_gap, -1e-12);
  EXPECT_LE(r.certificate.lower_bound, r.certificate.upper_bound * (1 + 1e-12));
  const DepthShakedownLimits by_depth = shakedown_by_depth(h, y, model, 1e-12);
  EXPECT_NEAR(r.load_factor / by_depth.min_load_factor, 1.0, 1e-6)
      << "Ipopt " << r.load_factor << ", bisection " << by_depth.min_load_factor;
  // The certified bracket holds the bisection's value.
  EXPECT_LE(r.certificate.lower_bound, by_depth.min_load_factor * (1 + 1e-9));
  EXPECT_GE(r.certificate.upper_bound, by_depth.min_load_factor * (1 - 1e-9));
  // Ipopt's critical depth is a depth whose own limit is the minimum.
  ASSERT_GE(r.critical_depth, 0);
  EXPECT_NEAR(by_depth.load_factor[static_cast<std::size_t>(r.critical_depth)] / by_depth.min_load_factor, 1.0, 1e-5);
}

TEST(ShakedownLineContact, TrescaFrictionlessIsFourK) {
  // Johnson & Jefferis (1963), Johnson (1985) chapter 9: with rho_xx(z) free the residual
  // cancels (sigma_xx - sigma_zz)/2 where the orthogonal shear peaks, so p0/k = 1 / 0.25 = 4.0
  // at z = 0.5 a. First yield (Johnson 1985 section 4.2): p0/k = 1 / 0.300 = 3.3.
  const StressHistory h = line_contact_history(0.0);
  const YieldCriterion tresca = YieldCriterion::tresca_plane_xz(1.0);
  const ShakedownResult r = solve_shakedown(h, tresca);
  expect_certified(r, h, tresca);
  std::printf("[ Tresca mu=0 ] p0/k: shakedown %.6f (depth %.2f a), elastic limit %.6f; %d iterations, %.3f s, "
              "gap %.1e\n",
              r.load_factor, h.depths[static_cast<std::size_t>(r.critical_depth)], r.elastic_limit, r.iterations,
              r.time_s, r.certificate.duality_gap);
  EXPECT_NEAR(r.load_factor, 4.0, 4.0 * 2e-3);
  EXPECT_GE(r.load_factor, 4.0 * (1 - 1e-9));  // fewer constraints than the continuum: never below
  EXPECT_NEAR(h.depths[static_cast<std::size_t>(r.critical_depth)], 0.5, 1e-9);
  EXPECT_NEAR(r.elastic_limit, 3.33, 0.005 * 3.33);
  // At the limit the feasible rho_xx of the critical depth shrinks to about one value: in the
  // continuum the one cancelling (sigma_xx - sigma_zz)/2 where the orthogonal shear peaks (both
  // peaks, x = +/- 0.866 a at z = 0.5 a, have the same value), rho_xx = -lambda (sigma_xx -
  // sigma_zz)(0.866 a, 0.5 a) = -4 (2 - sqrt 3) p0 / 2 = -(4 - 2 sqrt 3) k = -0.536 k; on the
  // samples (dx = 0.0235 a) the neighbours of the peak decide it: checked to 0.03 k. And the
  // unloaded state must not yield: |rho_xx| / 2 <= k.
  const auto peak = test::mcewen_stress(std::sqrt(3.0) / 2, 0.5, 1.0, 1.0, 0.0);
  const double rho = r.residual[static_cast<std::size_t>(r.critical_depth)][0];
  EXPECT_NEAR(rho, -4.0 * (peak.xx - peak.zz), 0.03);
  EXPECT_LE(std::abs(rho) / 2, 1.0);
  EXPECT_EQ(r.residual[static_cast<std::size_t>(r.critical_depth)][2], 0.0);  // rho_zz never free
}

TEST(ShakedownLineContact, VerdictAtTheLoadAsGiven) {
  const YieldCriterion tresca = YieldCriterion::tresca_plane_xz(1.0);
  const auto verdict = [&](double p0) {
    return solve_shakedown(line_contact_history(0.0, 32, 128, 0.04, 3.0, p0), tresca).verdict;
  };
  EXPECT_EQ(verdict(3.0), ShakedownVerdict::elastic);            // below 3.3 k
  EXPECT_EQ(verdict(3.7), ShakedownVerdict::elastic_shakedown);  // between 3.3 k and 4.0 k
  EXPECT_EQ(verdict(4.3), ShakedownVerdict::beyond_shakedown);   // above 4.0 k
}

TEST(ShakedownLineContact, TrescaWithTractionFollowsTheLargestOrthogonalShear) {
  // With rho_xx free and Tresca in the x-z plane, only sigma_xz escapes the residual: the limit
  // is p0/k = p0 / max |sigma_xz| (Johnson 1985 chapter 9), the subsurface branch falling with
  // mu_t until max |sigma_xz| = mu_t p0 reaches the surface, then p0/k = 1/mu_t (Johnson 1985
  // Fig. 9.7's surface branch). The max |sigma_xz| comes from a fine scan of McEwen's field (not
  // from the program); on this sampling (z = 0 included) the two agree to 0.2 %.
  const YieldCriterion tresca = YieldCriterion::tresca_plane_xz(1.0);
  for (const double mu_t : {0.1, 0.2, 0.3}) {
    const StressHistory h = line_contact_history(mu_t);
    const ShakedownResult r = solve_shakedown(h, tresca);
    expect_certified(r, h, tresca);
    const double expected = 1.0 / max_orthogonal_shear(mu_t);
    std::printf("[ Tresca mu=%.2f ] p0/k: shakedown %.5f at z = %.2f a (1/max|sxz| %.5f), elastic limit %.5f\n", mu_t,
                r.load_factor, h.depths[static_cast<std::size_t>(r.critical_depth)], expected, r.elastic_limit);
    EXPECT_NEAR(r.load_factor / expected, 1.0, 2e-3) << mu_t;
    EXPECT_GT(h.depths[static_cast<std::size_t>(r.critical_depth)], 0.3) << mu_t;  // subsurface
    EXPECT_LT(r.load_factor, 1.0 / mu_t) << mu_t;
  }
  // The surface governs beyond mu_t = 0.367 (where the subsurface max |sigma_xz| = mu_t p0):
  // p0/k = 1/mu_t exactly at z = 0 (there ((s_xx - s_zz)/2)^2 + s_xz^2 = (mu_t p)^2 + ... =
  // (mu_t p0)^2 at every point of the contact with rho = 0).
  for (const double mu_t : {0.4, 0.5}) {
    const StressHistory h = line_contact_history(mu_t);
    const ShakedownResult r = solve_shakedown(h, tresca);
    expect_certified(r, h, tresca);
    std::printf("[ Tresca mu=%.2f ] p0/k: shakedown %.6f at z = %.2f a (1/mu %.6f)\n", mu_t, r.load_factor,
                h.depths[static_cast<std::size_t>(r.critical_depth)], 1.0 / mu_t);
    EXPECT_NEAR(r.load_factor, 1.0 / mu_t, 1e-6 / mu_t) << mu_t;
  }
  // Either side of the crossing (the subsurface limit 1/max|sigma_xz| = 2.7237 at 0.367).
  EXPECT_LT(1.0 / max_orthogonal_shear(0.35), 1.0 / 0.35);
  EXPECT_NEAR(max_orthogonal_shear(0.38), 0.38, 1e-12);
}

TEST(ShakedownLineContact, VonMisesFrictionlessIsFourK) {
  // Von Mises with rho_xx(z) and rho_yy(z) free (plane strain, nu = 0.3): J2 >= ((s_xx - s_zz)/2)^2
  // + s_xz^2, so the limit is at most Tresca's 4.0 k, and rho_yy can bring sigma_yy to the mean of
  // sigma_xx and sigma_zz at the two symmetric points of peak orthogonal shear: p0/k = 4.0 again
  // (k = Y / sqrt 3), the value quoted for the line contact with either criterion. First yield:
  // p0 = 1.79 Y (Johnson 1985 section 4.2, nu = 0.3), p0/k = 3.11.
  const StressHistory h = line_contact_history(0.0);
  const YieldCriterion mises = YieldCriterion::von_mises(std::sqrt(3.0));  // k = 1
  const ShakedownResult r = solve_shakedown(h, mises);
  expect_certified(r, h, mises);
  std::printf("[ von Mises mu=0 ] p0/k: shakedown %.6f (depth %.2f a), elastic limit %.6f (p0/Y %.4f); "
              "%d iterations, %.3f s\n",
              r.load_factor, h.depths[static_cast<std::size_t>(r.critical_depth)], r.elastic_limit,
              r.elastic_limit / std::sqrt(3.0), r.iterations, r.time_s);
  EXPECT_NEAR(r.load_factor, 4.0, 4.0 * 2e-3);
  EXPECT_NEAR(r.elastic_limit / std::sqrt(3.0), 1.79, 0.005 * 1.79);
  // With rho_xx alone the von Mises limit cannot be higher.
  const ShakedownResult xx_only = solve_shakedown(h, mises, ResidualModel{{VoigtComponent::xx}});
  expect_certified(xx_only, h, mises, ResidualModel{{VoigtComponent::xx}});
  EXPECT_LE(xx_only.load_factor, r.load_factor * (1 + 1e-7));
  std::printf("[ von Mises mu=0, rho_xx only ] p0/k: %.6f\n", xx_only.load_factor);
}

TEST(ShakedownLineContact, VonMisesWithTraction) {
  // The subsurface limit is Tresca's (rho_yy balances sigma_yy there); the surface's falls faster
  // than 1/mu_t (sigma_yy = nu (sigma_xx + sigma_zz) varies along the surface and one rho_yy
  // cannot follow it), so the surface governs from mu_t = 0.32 or so. Certified at every mu_t;
  // the values are this program's (printed), no literature value is checked here.
  const YieldCriterion mises = YieldCriterion::von_mises(std::sqrt(3.0));
  for (const double mu_t : {0.1, 0.25, 0.4}) {
    const StressHistory h = line_contact_history(mu_t);
    const ShakedownResult r = solve_shakedown(h, mises);
    expect_certified(r, h, mises);
    std::printf("[ von Mises mu=%.2f ] p0/k: shakedown %.5f at z = %.2f a, elastic limit %.5f\n", mu_t, r.load_factor,
                h.depths[static_cast<std::size_t>(r.critical_depth)], r.elastic_limit);
    if (mu_t < 0.3) {
      EXPECT_NEAR(r.load_factor / (1.0 / max_orthogonal_shear(mu_t)), 1.0, 2e-3) << mu_t;
    }
    if (mu_t > 0.35) {
      EXPECT_EQ(r.critical_depth, 0) << mu_t;
    }
  }
}

TEST(ShakedownProgram, SixtyFourDepthsTimesTwoHundredFiftySixPositionsIsFast) {
  const StressHistory h = line_contact_history(0.2);
  for (const YieldCriterion& y : {YieldCriterion::tresca_plane_xz(1.0), YieldCriterion::von_mises(std::sqrt(3.0))}) {
    const ShakedownResult r = solve_shakedown(h, y);
    ASSERT_EQ(r.status, ShakedownStatus::optimal) << r.message;
    std::printf("[ %s, 64 x 256 ] %.3f s, %d Ipopt iterations\n", to_string(y.kind), r.time_s, r.iterations);
    std::printf("[ %s, 64 x 256 ] %d rounds, %d of %d yield conditions in the last program\n", to_string(y.kind),
                r.rounds, r.constraints, h.n_depths() * h.n_positions());
    // 0.13-0.2 s on this machine with two cores shared; the bound leaves room for a loaded one.
    // A sanitizer build checks every memory access (6 x slower here): the factor the interrupt
    // tests allow it (test_cli_interrupt.cpp).
    EXPECT_LT(r.time_s, DYNCONTACT_SANITIZED ? 3.0 : 1.0);
  }
}

TEST(ShakedownProgram, ConstraintGenerationAgreesWithTheWholeProgram) {
  // Every sample at once (16384 / 4 conditions here) against the working sets: one optimum.
  const StressHistory h = line_contact_history(0.2, 32, 128, 0.04);
  for (const YieldCriterion& y : {YieldCriterion::tresca_plane_xz(1.0), YieldCriterion::von_mises(std::sqrt(3.0))}) {
    ShakedownOptions whole;
    whole.constraint_generation = false;
    const ShakedownResult a = solve_shakedown(h, y), b = solve_shakedown(h, y, ResidualModel::line_contact(), whole);
    expect_certified(a, h, y);
    expect_certified(b, h, y);
    EXPECT_EQ(b.rounds, 1);
    EXPECT_EQ(b.constraints, 32 * 128);
    EXPECT_LT(a.constraints, b.constraints / 4);
    EXPECT_NEAR(a.load_factor / b.load_factor, 1.0, 2e-7);
  }
}

TEST(ShakedownProgram, UnboundedWhenTheResidualAbsorbsEveryStress) {
  // A stress constant in time along xx: rho_xx = -lambda sigma_xx absorbs it at any lambda.
  StressHistory h;
  h.depths = {0.1, 0.2};
  h.positions = {-1.0, 0.0, 1.0};
  for (int k = 0; k < 6; ++k) h.stress.push_back({2.0 + k / 3, 0.0, 0.0, 0.0, 0.0, 0.0});
  const ShakedownResult r = solve_shakedown(h, YieldCriterion::tresca_plane_xz(1.0));
  EXPECT_EQ(r.status, ShakedownStatus::unbounded) << r.message;
  EXPECT_TRUE(std::isinf(r.load_factor));
  EXPECT_NEAR(r.elastic_limit, 2.0 / 3.0, 1e-15);  // |(s_xx - s_zz)/2| = 1.5 k at the second depth
  EXPECT_EQ(r.verdict, ShakedownVerdict::elastic_shakedown);
  EXPECT_TRUE(std::isinf(shakedown_by_depth(h, YieldCriterion::tresca_plane_xz(1.0)).min_load_factor));
  // No residual at all: the program is first yield, bounded.
  const ShakedownResult none = solve_shakedown(h, YieldCriterion::tresca_plane_xz(1.0), ResidualModel::none());
  ASSERT_EQ(none.status, ShakedownStatus::optimal) << none.message;
  EXPECT_NEAR(none.load_factor, none.elastic_limit, 1e-7);
  // A history with no stress at all.
  for (auto& s : h.stress) s = Voigt{};
  const ShakedownResult zero = solve_shakedown(h, YieldCriterion::von_mises(1.0));
  EXPECT_EQ(zero.status, ShakedownStatus::unbounded);
  EXPECT_TRUE(std::isinf(zero.elastic_limit));
  EXPECT_EQ(zero.verdict, ShakedownVerdict::elastic);
}

TEST(ShakedownProgram, CertifiedBoundsHoldWhenIpoptStopsEarly) {
  // Three iterations: no converged point, but the scaled point's lambda is feasible and the
  // multipliers' dual bound an upper bound: the bisection's limit lies between them.
  const StressHistory h = line_contact_history(0.2, 32, 128, 0.04);
  const YieldCriterion tresca = YieldCriterion::tresca_plane_xz(1.0);
  ShakedownOptions o;
  o.max_iter = 3;
  const ShakedownResult r = solve_shakedown(h, tresca, ResidualModel::line_contact(), o);
  EXPECT_EQ(r.status, ShakedownStatus::not_converged) << r.message;
  const double exact = shakedown_by_depth(h, tresca).min_load_factor;
  EXPECT_LE(r.certificate.lower_bound, exact * (1 + 1e-12));
  EXPECT_GE(r.certificate.upper_bound, exact * (1 - 1e-12));
  EXPECT_GT(r.certificate.duality_gap, 1e-7);
}

TEST(ShakedownProgram, InvalidInputIsRejected) {
  StressHistory h = line_contact_history(0.0, 2, 4);
  const YieldCriterion tresca = YieldCriterion::tresca_plane_xz(1.0);
  EXPECT_THROW(solve_shakedown(h, YieldCriterion::tresca_plane_xz(0.0)), std::invalid_argument);
  EXPECT_THROW(solve_shakedown(h, tresca, ResidualModel{{VoigtComponent::zz}}), std::invalid_argument);
  EXPECT_THROW(solve_shakedown(h, tresca, ResidualModel{{VoigtComponent::xx, VoigtComponent::xx}}),
               std::invalid_argument);
  ShakedownOptions o;
  o.tol = 0.0;
  EXPECT_EQ(o.validate().rfind("tol:", 0), 0u);
  EXPECT_THROW(solve_shakedown(h, tresca, ResidualModel::line_contact(), o), std::invalid_argument);
  h.stress[3][4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(h.validate().rfind("stress:", 0), 0u);
  EXPECT_THROW(solve_shakedown(h, tresca), std::invalid_argument);
  h.stress.pop_back();
  EXPECT_THROW(shakedown_by_depth(h, tresca), std::invalid_argument);
}

TEST(ShakedownProgram, ResidualComponentsThatCannotActAreDropped) {
  // Tresca in the x-z plane never sees rho_yy; von Mises sees rho_xx, rho_yy and rho_xy.
  const StressHistory h = line_contact_history(0.0, 2, 4);
  const ResidualModel all{{VoigtComponent::xx, VoigtComponent::yy, VoigtComponent::xy}};
  EXPECT_EQ(shakedown_samples(h, YieldCriterion::tresca_plane_xz(1.0), all).p(), 1);
  EXPECT_EQ(shakedown_samples(h, YieldCriterion::von_mises(1.0), all).p(), 3);
}


TEST(ShakedownYield, InscribedConeLiesBetweenTrescaAndItsOuterCylinder) {
  // tau <= sqrt(J2) <= 2 tau / sqrt 3 (core/yield_criterion.hpp): the cone's ratio is at least
  // Tresca's and at most 2/sqrt 3 times it, equal in pure shear, the other extreme in uniaxial stress.
  const YieldCriterion c = YieldCriterion::tresca_inscribed(2.0);
  EXPECT_NEAR(c.outer_factor(), 2.0 / std::sqrt(3.0), 1e-15);
  EXPECT_EQ(YieldCriterion::von_mises(1.0).outer_factor(), 1.0);
  unsigned state = 7u;
  const auto next = [&]() {
    state = state * 1103515245u + 12345u;
    return static_cast<double>(state % 20001u) / 10000.0 - 1.0;
  };
  for (int n = 0; n < 1000; ++n) {
    const Voigt s{next(), next(), next(), next(), next(), next()};
    EXPECT_GE(c.ratio(s), c.exact_ratio(s) * (1 - 1e-12));
    EXPECT_LE(c.ratio(s), c.outer_factor() * c.exact_ratio(s) * (1 + 1e-12));
  }
  const Voigt shear{0.0, 0.0, 0.0, 0.0, 1.0, 0.0}, uniaxial{1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_NEAR(c.ratio(shear), 0.5, 1e-15);
  EXPECT_NEAR(c.exact_ratio(shear), 0.5, 1e-15);
  EXPECT_NEAR(c.ratio(uniaxial) / c.exact_ratio(uniaxial), 2.0 / std::sqrt(3.0), 1e-14);
  EXPECT_EQ(c.rows(), 5);
}

// ---- 3-D: residual stresses rho(y, z) (nlp/shakedown_3d.hpp) ----

/// The 3-D history of a 2-D one repeated on `lines` lines y = -1 .. 1 (a load that does not vary along y).
StressHistory3d strip_history(const StressHistory& h, int lines) {
  StressHistory3d g;
  g.depths = h.depths;
  g.positions = h.positions;
  for (int j = 0; j < lines; ++j) g.lines.push_back(-1.0 + 2.0 * j / (lines - 1));
  for (int k = 0; k < h.n_depths(); ++k)
    for (int j = 0; j < lines; ++j)
      for (int i = 0; i < h.n_positions(); ++i) g.stress.push_back(h.at(k, i));
  return g;
}

/// The samples of every line of a depth as the positions of one 2-D depth (the depth-only model's view).
StressHistory flattened(const StressHistory3d& g) {
  StressHistory h;
  h.depths = g.depths;
  for (int j = 0; j < g.n_lines(); ++j)
    for (const double x : g.positions) h.positions.push_back(x + 100.0 * j);  // labels only
  h.stress = g.stress;  // (k * lines + j) * positions + i = k * (lines * positions) + (j * positions + i)
  return h;
}

void expect_certified_3d(const ShakedownResult& r) {
  ASSERT_EQ(r.status, ShakedownStatus::optimal) << r.message;
  EXPECT_LE(r.certificate.yield_violation, 1e-7);
  EXPECT_LE(r.certificate.duality_gap, 1e-7);
  EXPECT_GE(r.certificate.duality_gap, -1e-12);
}

TEST(ShakedownResidual3d, StressFunctionsAreSelfEquilibratedAndTractionFree) {
  // Equation (3) of shakedown_3d.hpp by central differences (h = 1e-5 on breakpoint spacings
  // 0.05 .. 0.25), at random unknowns, on uneven breakpoints; the free surface and the box's
  // boundary exactly.
  const std::vector<double> depths{0.05, 0.1, 0.2, 0.28, 0.4, 0.55}, lines{-0.5, -0.3, -0.2, 0.0, 0.15, 0.4};
  const ResidualBasis3d basis(depths, lines, {});
  ASSERT_GT(basis.stress_function_unknowns(), 0);
  std::vector<double> theta(static_cast<std::size_t>(basis.unknowns()));
  unsigned state = 12345u;
  for (double& t : theta) {
    state = state * 1103515245u + 12345u;
    t = static_cast<double>(state % 20001u) / 10000.0 - 1.0;
  }
  const double h = 1e-5;
  const auto rho = [&](double y, double z) { return basis.stress_function_part(theta, y, z); };
  double scale = 0.0, worst = 0.0;
  for (int a = 0; a <= 40; ++a)
    for (int b = 1; b <= 30; ++b) {
      const double y = -0.69 + 1.28 * a / 40.0, z = 0.68 * b / 31.0;
      const Voigt yp = rho(y + h, z), ym = rho(y - h, z), zp = rho(y, z + h), zm = rho(y, z - h);
      // Voigt: xx, yy, zz, yz, xz, xy.
      const double e1 = (yp[5] - ym[5]) / (2 * h) + (zp[4] - zm[4]) / (2 * h);
      const double e2 = (yp[1] - ym[1]) / (2 * h) + (zp[3] - zm[3]) / (2 * h);
      const double e3 = (yp[3] - ym[3]) / (2 * h) + (zp[2] - zm[2]) / (2 * h);
      for (const double v : rho(y, z)) scale = std::max(scale, std::abs(v));
      worst = std::max({worst, std::abs(e1), std::abs(e2), std::abs(e3)});
    }
  std::printf("[ 3-D residual ] largest stress %.3g, largest divergence %.3g (per unit length)\n", scale, worst);
  ASSERT_GT(scale, 0.5);
  // One derivative of a stress of size `scale` over a spacing 0.05 is 20 scale: the divergence
  // vanishes to 1e-6 of that (the differences' truncation and rounding).
  EXPECT_LT(worst, 1e-6 * scale / 0.05);
  for (int a = 0; a <= 50; ++a) {
    const double y = -0.7 + 1.35 * a / 50.0;
    const Voigt s = rho(y, 0.0);
    EXPECT_NEAR(s[2], 0.0, 1e-12 * scale) << y;  // rho_zz
    EXPECT_NEAR(s[3], 0.0, 1e-12 * scale) << y;  // rho_yz
    EXPECT_NEAR(s[4], 0.0, 1e-12 * scale) << y;  // rho_xz
    const Voigt bottom = rho(y, 0.7);  // the box's floor: 0.55 + 0.15
    EXPECT_NEAR(bottom[2], 0.0, 1e-12 * scale) << y;
    EXPECT_NEAR(bottom[3], 0.0, 1e-12 * scale) << y;
    EXPECT_NEAR(bottom[4], 0.0, 1e-12 * scale) << y;
    for (const double v : rho(y, 0.71)) EXPECT_EQ(v, 0.0);  // zero outside the box
  }
  for (int b = 0; b <= 50; ++b) {
    const double z = 0.7 * b / 50.0;
    for (const double y : {-0.7, 0.65}) {  // the box's sides: one spacing beyond the outer lines
      const Voigt s = rho(y, z);
      EXPECT_NEAR(s[5], 0.0, 1e-12 * scale) << y << " " << z;  // rho_xy
      EXPECT_NEAR(s[1], 0.0, 1e-12 * scale) << y << " " << z;  // rho_yy
      EXPECT_NEAR(s[3], 0.0, 1e-12 * scale) << y << " " << z;  // rho_yz
    }
  }
  const ResidualBasis3d depth_only(depths, lines, ResidualModel3d{false});
  EXPECT_EQ(depth_only.stress_function_unknowns(), 0);
  EXPECT_EQ(depth_only.unknowns(), 3 * static_cast<int>(depths.size()));
}

TEST(Shakedown3d, StripLoadReproducesTheLineContact) {
  // A load that does not vary along y (McEwen's field on 3 lines, the 2-D sampling of the header):
  // no residual of (y, z) can beat the line contact's bound. At the two samples of a station where
  // the orthogonal shear peaks (+/- t), |lambda sigma_xz + rho_xz| <= sqrt(J2) <= k gives
  // lambda t <= k whatever rho, so 1 / max|sigma_xz| of the samples bounds the 3-D limit; the
  // depth-only von Mises program (rho_xx, rho_yy, rho_xy) is a subset. Johnson & Jefferis'
  // p0/k = 4.0 (frictionless, Tresca; von Mises reaches it too, VonMisesFrictionlessIsFourK) to
  // the 2-D test's 2e-3 on this sampling.
  const StressHistory h = line_contact_history(0.0);
  const StressHistory3d g = strip_history(h, 3);
  const YieldCriterion mises = YieldCriterion::von_mises(std::sqrt(3.0));
  const ShakedownResult r = solve_shakedown_3d(g, mises);
  expect_certified_3d(r);
  const ShakedownResult line =
      solve_shakedown(h, mises, ResidualModel{{VoigtComponent::xx, VoigtComponent::yy, VoigtComponent::xy}});
  ASSERT_EQ(line.status, ShakedownStatus::optimal) << line.message;
  double tmax = 0.0;
  for (const Voigt& s : h.stress) tmax = std::max(tmax, std::abs(s[4]));
  std::printf("[ 3-D strip, von Mises ] p0/k: %.6f (2-D depth-only %.6f, 1/max|sxz| %.6f) at z = %.2f a; "
              "%.2f s, %d rounds, %d conditions\n",
              r.load_factor, line.load_factor, 1.0 / tmax, h.depths[static_cast<std::size_t>(r.critical_depth)],
              r.time_s, r.rounds, r.constraints);
  EXPECT_NEAR(r.load_factor, 4.0, 4.0 * 2e-3);
  EXPECT_GE(r.load_factor, line.load_factor * (1 - 1e-7));
  EXPECT_LE(r.certificate.lower_bound, (1.0 / tmax) * (1 + 1e-9));
  EXPECT_NEAR(h.depths[static_cast<std::size_t>(r.critical_depth)], 0.5, 0.021);
  // Tresca through the inscribed cone: the same program (k the same), Tresca's own first yield
  // 1 / 0.300 = 3.33 (Johnson 1985 section 4.2; sigma_yy = nu (sigma_xx + sigma_zz) the
  // intermediate stress), and Tresca's limit bracketed by [lambda, 2/sqrt 3 lambda_up].
  const ShakedownResult t = solve_shakedown_3d(g, YieldCriterion::tresca_inscribed(1.0));
  expect_certified_3d(t);
  EXPECT_NEAR(t.load_factor / r.load_factor, 1.0, 1e-6);
  EXPECT_NEAR(t.elastic_limit, 3.33, 0.005 * 3.33);
  EXPECT_NEAR(t.limit_upper_bound, 2.0 / std::sqrt(3.0) * t.certificate.upper_bound, 1e-12);
  EXPECT_EQ(t.verdict, ShakedownVerdict::elastic);  // p0 = 1 < 3.33 k (k = 1)
  // At p0/k = 5.0 the line contact is beyond shakedown (Tresca's 4.0); the cone's certificate
  // brackets Tresca's limit by 2/sqrt 3 x 4.0 = 4.62 < 5.0, so the verdict is certain.
  StressHistory3d heavy = g;
  for (Voigt& v : heavy.stress)
    for (double& c : v) c *= 5.0;
  const ShakedownResult beyond = solve_shakedown_3d(heavy, YieldCriterion::tresca_inscribed(1.0));
  EXPECT_LT(beyond.limit_upper_bound, 1.0);
  EXPECT_EQ(beyond.verdict, ShakedownVerdict::beyond_shakedown);
  EXPECT_THROW(solve_shakedown_3d(g, YieldCriterion::tresca_plane_xz(1.0)), std::invalid_argument);
}

/// Hertz's frictionless circular contact, a = p0 = 1, nu = 0.3: the field of the piecewise-
/// constant pressure on 41 x 41 elements over [-2.05, 2.05]^2 (dx = 0.1 a; core/subsurface_field.hpp,
/// checked against Johnson's (3.45) in test_subsurface_field.cpp), sampled at depths 0 .. 0.9 a
/// (step 0.05 a) on the 25 lines |y| <= 1.2 a and the 41 positions along x.
StressHistory3d hertz_point_history() {
  const int n = 41;
  const Grid grid = Grid::make(3, n, n, -2.05, 2.05, -2.05, 2.05);
  SurfaceTractions t;
  t.p.resize(grid.size());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double r2 = grid.xc(i) * grid.xc(i) + grid.yc(j) * grid.yc(j);
      t.p[grid.index(i, j)] = r2 < 1.0 ? std::sqrt(1.0 - r2) : 0.0;
    }
  StressHistory3d g;
  for (int k = 0; k <= 18; ++k) g.depths.push_back(0.05 * k);
  SubsurfaceField field(grid, Elastic::from_E_nu(1.0, kNu), BodySide::body);
  const SubsurfaceResult r = field.compute(t, g.depths);
  std::vector<int> lines;
  for (int j = 0; j < n; ++j)
    if (std::abs(grid.yc(j)) <= 1.2 + 1e-9) {
      lines.push_back(j);
      g.lines.push_back(grid.yc(j));
    }
  for (int i = 0; i < n; ++i) g.positions.push_back(grid.xc(i));
  for (std::size_t k = 0; k < g.depths.size(); ++k)
    for (const int j : lines)
      for (int i = 0; i < n; ++i) g.stress.push_back(voigt_stress(r.point(k, i, j)));
  return g;
}

TEST(Shakedown3d, HertzPointContactAgainstPublishedBounds) {
  // Published (frictionless free rolling, circular Hertz contact): the kinematic (upper) bound
  // p0/k = 4.7 for Tresca (A. R. S. Ponter, A. D. Hearle, K. L. Johnson, J. Mech. Phys. Solids 33
  // (1985) 339-362; K. L. Johnson, Contact Mechanics 1985, section 9.5 and Fig. 9.7); the line
  // contact's 4.0 for comparison. Our value is a static (Melan) lower bound for Tresca through the
  // inscribed cone (k = 1), so it must lie below 4.7: the 1 % allowed is the sampling's (the
  // sampled program can exceed the continuum's limit: 0.2 % in the line contact at dx = 0.02 a,
  // here dx = 0.1 a). First yield is exact: Tresca's largest shear on the axis, 0.31 p0 at
  // z = 0.48 a (Johnson (3.45), from the closed form on a fine scan below), p0/k = 1/0.31 = 3.2;
  // checked to 1 % (the piecewise-constant pressure at dx = 0.1 a and the depth step 0.05 a).
  const StressHistory3d g = hertz_point_history();
  double tau_axis = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const auto s = closed_form::hertz_sphere_axis(1e-4 * k, 1.0, 1.0, kNu);
    tau_axis = std::max(tau_axis, 0.5 * std::abs(s.sigma_z - s.sigma_r));
  }
  EXPECT_NEAR(tau_axis, 0.31, 0.005);
  const YieldCriterion tresca = YieldCriterion::tresca_inscribed(1.0);
  const ShakedownResult r = solve_shakedown_3d(g, tresca);
  expect_certified_3d(r);
  const ShakedownResult depth_only = solve_shakedown_3d(g, tresca, ResidualModel3d{false});
  expect_certified_3d(depth_only);
  std::printf("[ 3-D Hertz point, Tresca ] p0/k: shakedown >= %.4f (depth-only residual %.4f), Tresca's limit <= "
              "%.4f; at z = %.2f a, y = %.2f a; elastic limit %.4f (closed form 1/%.4f = %.4f); %.2f s, %d rounds, "
              "%d conditions, %d iterations\n",
              r.certificate.lower_bound, depth_only.load_factor, r.limit_upper_bound,
              g.depths[static_cast<std::size_t>(r.critical_depth)], g.lines[static_cast<std::size_t>(r.critical_line)],
              r.elastic_limit, tau_axis, 1.0 / tau_axis, r.time_s, r.rounds, r.constraints, r.iterations);
  EXPECT_NEAR(r.elastic_limit * tau_axis, 1.0, 0.01);
  EXPECT_NEAR(g.lines[static_cast<std::size_t>(r.elastic_limit_line)], 0.0, 1e-12);  // on the axis
  EXPECT_LE(r.certificate.lower_bound, 4.7 * 1.01);
  EXPECT_GE(r.load_factor, depth_only.load_factor * (1 - 1e-7));  // a superset of residuals
  EXPECT_GT(r.load_factor, r.elastic_limit * std::sqrt(3.0) / 2);  // above the cone's own first yield
}

TEST(Shakedown3d, DepthOnlyModelIsTheLineContactProgramOnEveryLine) {
  // vary_across = false is the depth-only set rho_xx(z), rho_yy(z), rho_xy(z): the 2-D program with
  // the samples of all lines as one depth's positions, and the per-depth bisection
  // (shakedown_by_depth.hpp, no Ipopt), to 1e-6; von Mises on the point contact's history.
  const StressHistory3d g = hertz_point_history();
  const YieldCriterion mises = YieldCriterion::von_mises(std::sqrt(3.0));
  const ResidualModel all{{VoigtComponent::xx, VoigtComponent::yy, VoigtComponent::xy}};
  const ShakedownResult a = solve_shakedown_3d(g, mises, ResidualModel3d{false});
  expect_certified_3d(a);
  const StressHistory h = flattened(g);
  const ShakedownResult b = solve_shakedown(h, mises, all);
  ASSERT_EQ(b.status, ShakedownStatus::optimal) << b.message;
  const DepthShakedownLimits c = shakedown_by_depth(h, mises, all, 1e-12);
  std::printf("[ 3-D Hertz point, von Mises, depth-only ] p0/k: %.6f (2-D program %.6f, bisection %.6f); "
              "elastic limit %.4f\n",
              a.load_factor, b.load_factor, c.min_load_factor, a.elastic_limit);
  EXPECT_NEAR(a.load_factor / b.load_factor, 1.0, 1e-6);
  EXPECT_NEAR(a.load_factor / c.min_load_factor, 1.0, 1e-6);
  EXPECT_EQ(a.critical_depth, b.critical_depth);
  EXPECT_NEAR(a.elastic_limit, b.elastic_limit, 1e-12 * b.elastic_limit);
}

TEST(Shakedown3d, InvalidInputIsRejected) {
  StressHistory3d g = strip_history(line_contact_history(0.0, 3, 4), 3);
  const YieldCriterion mises = YieldCriterion::von_mises(1.0);
  g.lines = {0.0, 0.0, 1.0};
  EXPECT_THROW(solve_shakedown_3d(g, mises), std::invalid_argument);
  g.lines = {-1.0, 0.0, 1.0};
  g.depths[0] = -0.1;
  EXPECT_THROW(solve_shakedown_3d(g, mises), std::invalid_argument);
  g.depths[0] = 0.0;
  EXPECT_EQ(g.validate(), "");
  g.stress.pop_back();
  EXPECT_EQ(g.validate().rfind("stress:", 0), 0u);
}

}  // namespace
}  // namespace dc::shakedown_tests
