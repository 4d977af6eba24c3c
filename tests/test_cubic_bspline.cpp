// Clamped cubic B-splines (core/cubic_bspline.hpp) against their defining properties (L. Piegl,
// W. Tiller, The NURBS Book, 2nd ed., Springer 1997, section 2.3): partition of unity, the clamped
// ends, and the derivatives against central differences of the values.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "cubic_bspline.hpp"

namespace dc {
namespace {

/// Every basis function's value (derivative d) at t, as a dense vector.
std::vector<double> dense(const CubicBSplineBasis& b, double t, int d) {
  std::vector<double> v(static_cast<std::size_t>(b.size()), 0.0);
  const CubicBSplineBasis::Local l = b.evaluate(t);
  for (std::size_t r = 0; r < 4; ++r) v[static_cast<std::size_t>(l.first) + r] = l.derivative[static_cast<std::size_t>(d)][r];
  return v;
}

TEST(CubicBSpline, PartitionOfUnityAndDerivativesOnUnevenBreakpoints) {
  const CubicBSplineBasis b({-0.3, 0.0, 0.1, 0.35, 0.4, 1.0});
  ASSERT_EQ(b.size(), 8);
  for (int k = 0; k <= 130; ++k) {
    const double t = -0.3 + 1.3 * k / 130.0;
    double sum = 0.0, d1 = 0.0, d2 = 0.0;
    for (const double v : dense(b, t, 0)) {
      sum += v;
      EXPECT_GE(v, -1e-15);
    }
    for (const double v : dense(b, t, 1)) d1 += v;
    for (const double v : dense(b, t, 2)) d2 += v;
    EXPECT_NEAR(sum, 1.0, 1e-14) << t;
    EXPECT_NEAR(d1, 0.0, 1e-11) << t;
    EXPECT_NEAR(d2, 0.0, 1e-9) << t;
    // Central differences of the values (h = 1e-5: error h^2 f''' ~ 1e-10 x 1e4) and of the
    // first derivatives, away from the ends.
    if (t > -0.29 && t < 0.99) {
      const double h = 1e-5;
      const auto lo = dense(b, t - h, 0), hi = dense(b, t + h, 0), d = dense(b, t, 1);
      const auto lo1 = dense(b, t - h, 1), hi1 = dense(b, t + h, 1), dd = dense(b, t, 2);
      for (std::size_t a = 0; a < d.size(); ++a) {
        EXPECT_NEAR((hi[a] - lo[a]) / (2 * h), d[a], 1e-5 * (1 + std::abs(d[a]))) << t << " B_" << a;
        // The second derivative jumps at the breakpoints: compare between them only.
        bool at_break = false;
        for (const double p : b.breakpoints()) at_break = at_break || std::abs(t - p) < 2 * h;
        if (!at_break) {
          EXPECT_NEAR((hi1[a] - lo1[a]) / (2 * h), dd[a], 1e-4 * (1 + std::abs(dd[a]))) << t << " B_" << a;
        }
      }
    }
  }
}

TEST(CubicBSpline, ClampedEnds) {
  const CubicBSplineBasis b({0.0, 0.2, 0.5, 0.7});
  const int n = b.size();
  const auto v0 = dense(b, 0.0, 0), d0 = dense(b, 0.0, 1), v1 = dense(b, 0.7, 0), d1 = dense(b, 0.7, 1);
  EXPECT_DOUBLE_EQ(v0[0], 1.0);
  EXPECT_DOUBLE_EQ(v1[static_cast<std::size_t>(n - 1)], 1.0);
  EXPECT_NEAR(d0[0], -3.0 / 0.2, 1e-12);  // -p / (t_1 - t_0)
  EXPECT_NEAR(d0[1], 3.0 / 0.2, 1e-12);
  EXPECT_NEAR(d1[static_cast<std::size_t>(n - 1)], 3.0 / 0.2, 1e-12);
  for (int a = 1; a < n; ++a) EXPECT_EQ(v0[static_cast<std::size_t>(a)], 0.0) << a;
  for (int a = 2; a < n; ++a) EXPECT_EQ(d0[static_cast<std::size_t>(a)], 0.0) << a;
  for (int a = 0; a < n - 1; ++a) EXPECT_EQ(v1[static_cast<std::size_t>(a)], 0.0) << a;
  for (int a = 0; a < n - 2; ++a) EXPECT_EQ(d1[static_cast<std::size_t>(a)], 0.0) << a;
  EXPECT_THROW(CubicBSplineBasis({0.0}), std::invalid_argument);
  EXPECT_THROW(CubicBSplineBasis({0.0, 0.0, 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace dc
