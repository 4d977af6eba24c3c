// The smallest enclosing ball (core/enclosing_ball.hpp) and the Dang Van criterion
// (core/dang_van.hpp): paths whose ball is known in closed form, random clouds against a
// brute-force enumeration of support sets, the criterion's own calibration (fully reversed
// torsion and bending sit on the limit), the orthogonal-shear range, and the critical depth of
// frictionless line rolling (McEwen's field, tests/support/mcewen_reference.hpp, a = p0 = 1,
// nu = 0.3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "dang_van.hpp"
#include "enclosing_ball.hpp"
#include "mcewen_reference.hpp"

namespace dc::dang_van_tests {
namespace {

constexpr double kPi = std::numbers::pi;

using Vector5 = Eigen::Matrix<double, 5, 1>;

Voigt plus(const Voigt& a, const Voigt& b, double t = 1.0) {
  Voigt c;
  for (std::size_t k = 0; k < 6; ++k) c[k] = a[k] + t * b[k];
  return c;
}

/// The smallest ball by enumeration: every subset of at most d + 1 points, its ball in its own
/// affine hull (skipped when dependent), kept when it encloses every point; the smallest wins.
/// Exact for small clouds (the optimum is the ball of its support, d + 1 points at most).
std::pair<Eigen::VectorXd, double> brute_force_ball(const Eigen::MatrixXd& p, const Eigen::VectorXd& w) {
  const int d = static_cast<int>(p.rows()), n = static_cast<int>(p.cols());
  double best = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_c;
  for (unsigned mask = 1; mask < (1u << n); ++mask) {
    std::vector<int> s;
    for (int i = 0; i < n; ++i)
      if (mask & (1u << i)) s.push_back(i);
    if (static_cast<int>(s.size()) > d + 1) continue;
    const int k = static_cast<int>(s.size()) - 1;
    Eigen::VectorXd c = p.col(s[0]);
    if (k > 0) {
      Eigen::MatrixXd v(d, k);
      Eigen::VectorXd b(k);
      for (int l = 0; l < k; ++l) {
        v.col(l) = p.col(s[static_cast<std::size_t>(l + 1)]) - p.col(s[0]);
        b(l) = 0.5 * (v.col(l).squaredNorm() - w(s[static_cast<std::size_t>(l + 1)]) + w(s[0]));
      }
      const Eigen::MatrixXd g = v.transpose() * v;
      Eigen::FullPivLU<Eigen::MatrixXd> lu(g);
      if (lu.rank() < k) continue;
      c += v * lu.solve(b);
    }
    double value = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) value = std::max(value, (p.col(i) - c).squaredNorm() - w(i));
    // The ball of s must hold every point (its own points on the boundary, up to rounding).
    const double own = (p.col(s[0]) - c).squaredNorm() - w(s[0]);
    if (value > own + 1e-10) continue;
    if (own < best) {
      best = own;
      best_c = c;
    }
  }
  return {best_c, best};
}

void expect_certified(const EnclosingBall& b, double tol = 1e-12) {
  EXPECT_TRUE(b.certified(tol)) << "min mu " << b.min_multiplier << ", hull residual " << b.hull_residual
                                << ", relative gap " << b.relative_gap();
  EXPECT_GE(b.relative_gap(), -1e-14);
  double sum = 0.0;
  for (const double m : b.multipliers) sum += m;
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(DangVanEnclosingBall, RandomCloudsMatchBruteForce) {
  std::mt19937 rng(29);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const int d = 1 + trial % 5, n = 3 + trial % 10;
    Eigen::MatrixXd p(d, n);
    for (int i = 0; i < n; ++i)
      for (int r = 0; r < d; ++r) p(r, i) = normal(rng);
    const EnclosingBall b = smallest_enclosing_ball(p);
    const auto [c, value] = brute_force_ball(p, Eigen::VectorXd::Zero(n));
    expect_certified(b);
    EXPECT_NEAR(b.value, value, 1e-12 * (1 + value)) << "trial " << trial;
    EXPECT_LT((b.centre - c).norm(), 1e-9) << "trial " << trial;
  }
}

TEST(DangVanEnclosingBall, WeightedCloudsMatchBruteForce) {
  // The power-distance form (the shakedown cross-check's disks): positive and negative minima.
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 3.0);
  for (int trial = 0; trial < 30; ++trial) {
    const int d = 1 + trial % 3, n = 3 + trial % 9;
    Eigen::MatrixXd p(d, n);
    Eigen::VectorXd w(n);
    for (int i = 0; i < n; ++i) {
      for (int r = 0; r < d; ++r) p(r, i) = normal(rng);
      w(i) = uniform(rng);
    }
    const EnclosingBall b = minimax_power_distance(p, w);
    const auto [c, value] = brute_force_ball(p, w);
    expect_certified(b);
    EXPECT_NEAR(b.value, value, 1e-11 * (1 + std::abs(value))) << "trial " << trial;
    EXPECT_LT((b.centre - c).norm(), 1e-8) << "trial " << trial;
  }
}

TEST(DangVanEnclosingBall, LargeAndDegenerateClouds) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  // 2000 points in 5-D: no brute force, the certificate alone (hull, gap) and every point inside.
  Eigen::MatrixXd p(5, 2000);
  for (int i = 0; i < p.cols(); ++i)
    for (int r = 0; r < 5; ++r) p(r, i) = normal(rng) * (1 + r);
  const EnclosingBall b = smallest_enclosing_ball(p);
  expect_certified(b);
  for (int i = 0; i < p.cols(); ++i) EXPECT_LE((p.col(i) - b.centre).norm(), b.radius() * (1 + 1e-14));
  // Coincident points; a single point; collinear points (the radius is half the extent).
  Eigen::MatrixXd same = Eigen::MatrixXd::Constant(5, 7, 1.5);
  const EnclosingBall s = smallest_enclosing_ball(same);
  EXPECT_EQ(s.radius(), 0.0);
  EXPECT_LT((s.centre - same.col(0)).norm(), 1e-15);
  expect_certified(s);
  Eigen::MatrixXd line(5, 50);
  Vector5 dir;
  dir << 1, -2, 0.5, 3, 1;
  for (int i = 0; i < 50; ++i) line.col(i) = std::sin(0.37 * i) * dir;
  const EnclosingBall l = smallest_enclosing_ball(line);
  const double lo = line.row(0).minCoeff(), hi = line.row(0).maxCoeff();
  EXPECT_NEAR(l.radius(), 0.5 * (hi - lo) * dir.norm(), 1e-13);
  expect_certified(l);
  EXPECT_THROW(smallest_enclosing_ball(Eigen::MatrixXd(5, 0)), std::invalid_argument);
}

TEST(DangVan, ProportionalPathRadiusIsTheAmplitude) {
  // sigma(t) = sigma_m + sin(t) sigma_a: the deviatoric path is a segment from -dev sigma_a to
  // +dev sigma_a about dev sigma_m; its ball has radius sqrt(J2(sigma_a)) (half the range) and
  // centre dev sigma_m.
  const Voigt mean{50, -20, 10, 5, -8, 12}, amp{100, 30, -60, 20, 40, -10};
  std::vector<Voigt> path;
  for (int t = 0; t < 64; ++t) path.push_back(plus(mean, amp, std::sin(2 * kPi * t / 64)));
  const DangVanParameters par{0.3, 150.0};
  const DangVanResult r = dang_van(path, par);
  expect_certified(r.ball);
  EXPECT_NEAR(r.radius, sqrt_j2(amp), 1e-12 * sqrt_j2(amp));
  const Vector5 centre = deviatoric_coordinates(r.residual_deviator), expected = deviatoric_coordinates(mean);
  EXPECT_LT((centre - expected).norm(), 1e-10);
  EXPECT_NEAR(trace(r.residual_deviator), 0.0, 1e-12);
  // tau(t) = |sin t| Tresca(amp), p_h(t) = p_m + sin t p_a: the index from these directly.
  double index = -1e300;
  for (int t = 0; t < 64; ++t) {
    const double st = std::sin(2 * kPi * t / 64);
    EXPECT_NEAR(r.mesoscopic_shear[static_cast<std::size_t>(t)], std::abs(st) * tresca_shear(amp), 1e-10);
    const double p_h = hydrostatic(mean) + st * hydrostatic(amp);
    index = std::max(index, (std::abs(st) * tresca_shear(amp) + par.alpha * p_h) / par.beta);
  }
  EXPECT_NEAR(r.index, index, 1e-12);
}

TEST(DangVan, CircularPathInADeviatoricPlane) {
  // A rotating shear sigma_xz = R cos t, sigma_yz = R sin t about a static stress: a circle of
  // radius R (sqrt(J2) units) in the deviatoric plane of u3, u4, centred on the static deviator.
  // 97 cocircular instants: a degenerate support (any 3 non-collinear ones, or 2 antipodal).
  const double radius = 80.0;
  const Voigt mean{-30, 10, 40, 0, 0, 25};
  std::vector<Voigt> path;
  for (int t = 0; t < 97; ++t) {
    Voigt s = mean;
    s[4] += radius * std::cos(2 * kPi * t / 97);
    s[3] += radius * std::sin(2 * kPi * t / 97);
    path.push_back(s);
  }
  const DangVanResult r = dang_van(path, {0.0, 100.0});
  expect_certified(r.ball);
  EXPECT_NEAR(r.radius, radius, 1e-12 * radius);
  EXPECT_LT((deviatoric_coordinates(r.residual_deviator) - deviatoric_coordinates(mean)).norm(), 1e-10 * radius);
  // The shifted path is a pure rotating shear: tau = R at every instant.
  for (const double tau : r.mesoscopic_shear) EXPECT_NEAR(tau, radius, 1e-10 * radius);
  EXPECT_NEAR(r.index, radius / 100.0, 1e-12);
}

TEST(DangVan, FatigueLimitsSitOnTheCriterion) {
  // beta = t_-1, alpha = 3 (t_-1/f_-1 - 1/2): fully reversed torsion of amplitude t_-1 and
  // bending of amplitude f_-1 both give index 1.
  const double torsion = 300.0, bending = 500.0;
  const DangVanParameters par = DangVanParameters::from_fatigue_limits(torsion, bending);
  EXPECT_NEAR(par.alpha, 0.3, 1e-15);
  EXPECT_EQ(par.validate(), "");
  std::vector<Voigt> shear, tension;
  for (int t = 0; t < 40; ++t) {  // sin reaches +-1 exactly at t = 10, 30: symmetric paths
    const double st = std::sin(2 * kPi * t / 40);
    shear.push_back({0, 0, 0, 0, torsion * st, 0});
    tension.push_back({bending * st, 0, 0, 0, 0, 0});
  }
  EXPECT_NEAR(dang_van(shear, par).index, 1.0, 1e-12);
  // Bending: tau = f |sin| / 2, p_h = f sin / 3; at sin = 1: (f/2 + alpha f/3) / t = 1.
  EXPECT_NEAR(dang_van(tension, par).index, 1.0, 1e-12);
  EXPECT_NEAR(dang_van(tension, par).radius, bending / std::sqrt(3.0), 1e-10);
  EXPECT_FALSE(dang_van(tension, par).fatigue());
  EXPECT_THROW(dang_van({}, par), std::invalid_argument);
  EXPECT_THROW(dang_van(shear, {0.3, 0.0}), std::invalid_argument);
  EXPECT_NE((DangVanParameters{std::numeric_limits<double>::infinity(), 1.0}.validate()), "");
  shear[3][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(dang_van(shear, par), std::invalid_argument);
}

TEST(DangVan, OrthogonalShearRangeIndex) {
  // A static stress (any deviator, hydrostatic p) with an orthogonal shear sigma_xz sweeping
  // [tau_min, tau_max]: the ball is centred at the mean shear, radius the amplitude
  // (tau_max - tau_min)/2, and the index (amplitude + alpha p) / beta: the classical
  // orthogonal-shear range check of rolling contact.
  const Voigt stat{-400, -250, -700, 0, 0, 0};
  const double tau_min = -180, tau_max = 120;
  std::vector<Voigt> path;
  for (int t = 0; t <= 50; ++t) {
    Voigt s = stat;
    s[4] = tau_min + (tau_max - tau_min) * (0.5 - 0.5 * std::cos(2 * kPi * t / 50));
    path.push_back(s);
  }
  const DangVanParameters par{0.3, 200.0};
  const DangVanResult r = dang_van(path, par);
  expect_certified(r.ball);
  const double amplitude = 0.5 * (tau_max - tau_min);
  EXPECT_NEAR(r.radius, amplitude, 1e-12 * amplitude);
  EXPECT_NEAR(r.residual_deviator[4], 0.5 * (tau_max + tau_min), 1e-10);
  // The centre carries the static deviator and the mean shear: the shifted path is the pure
  // shear +-amplitude, whose Tresca shear is its magnitude.
  Voigt centre = from_deviatoric_coordinates(deviatoric_coordinates(stat));
  centre[4] = 0.5 * (tau_max + tau_min);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(r.residual_deviator[static_cast<std::size_t>(k)], centre[static_cast<std::size_t>(k)], 1e-9) << k;
  double largest = 0.0;
  for (const double tau : r.mesoscopic_shear) largest = std::max(largest, tau);
  EXPECT_NEAR(largest, amplitude, 1e-9);
  EXPECT_NEAR(r.index, (amplitude + par.alpha * hydrostatic(stat)) / par.beta, 1e-12);
}

TEST(DangVan, FrictionlessLineRollingCriticalDepth) {
  // The path of a material point at depth z as the Hertz line load passes (x from -4 a to 4 a,
  // 801 instants, sigma_yy = nu (sigma_xx + sigma_zz)), depths 0.05 a to 1.5 a in steps of 0.01 a.
  // With alpha = 0 the index is the mesoscopic shear amplitude: it peaks at z = 0.50 a with
  // 0.2500 p0 = the orthogonal shear amplitude (half its range -0.25..0.25 p0). With alpha = 0.3
  // the compressive hydrostatic stress under the load lowers the index most near the surface:
  // the peak moves to z = 0.61 a (this program's value on this sampling, no literature value).
  for (const double alpha : {0.0, 0.3}) {
    double best = -1.0, at = 0.0, radius_at_half = 0.0;
    for (int j = 5; j <= 150; ++j) {
      const double z = 0.01 * j;
      std::vector<Voigt> path;
      for (int i = 0; i <= 800; ++i) path.push_back(test::mcewen_voigt(-4.0 + 0.01 * i, z, 1.0, 1.0, 0.0, 0.3));
      const DangVanResult r = dang_van(path, {alpha, 1.0});
      ASSERT_TRUE(r.ball.certified(1e-12)) << z;
      if (j == 50) radius_at_half = r.radius;
      if (r.index > best) {
        best = r.index;
        at = z;
      }
    }
    std::printf("[ Dang Van, alpha = %.1f ] index (beta = p0) peaks at z = %.2f a: %.5f\n", alpha, at, best);
    if (alpha == 0.0) {
      EXPECT_NEAR(at, 0.50, 0.0101);
      EXPECT_NEAR(best, 0.25, 1e-3);
      EXPECT_NEAR(radius_at_half, 0.25, 1e-4);
    } else {
      EXPECT_NEAR(at, 0.61, 0.0201);
    }
  }
}

}  // namespace
}  // namespace dc::dang_van_tests
