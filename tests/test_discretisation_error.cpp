// The discretisation error estimate (core/discretisation_error.hpp) on sequences whose error is
// known: Q_h = Q* + C h^p, non-monotone values, bands, two grids, zero values.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "discretisation_error.hpp"

namespace {

using dc::Convergence;
using dc::GridValue;

/// Q* + C h^p on h, 2h, 4h (finest first).
std::vector<GridValue> power_law(double q_star, double c, double p, double h = 0.01, int grids = 3) {
  std::vector<GridValue> v;
  for (int k = 0; k < grids; ++k) {
    const double hk = h * std::pow(2.0, k);
    v.push_back({hk, q_star + c * std::pow(hk, p)});
  }
  return v;
}

TEST(DiscretisationError, SecondOrderSequenceIsExtrapolatedExactlyAndBoundedWithinThreeTimes) {
  const auto v = power_law(2.0, 50.0, 2.0);
  const auto e = dc::estimate_discretisation_error(v, Convergence::smooth);
  EXPECT_EQ(e.method, "richardson");
  ASSERT_TRUE(e.order.has_value());
  EXPECT_NEAR(*e.order, 2.0, 1e-9);
  EXPECT_NEAR(e.extrapolated, 2.0, 1e-12);
  const double truth = std::abs(v[0].value - 2.0);
  EXPECT_GE(e.error, truth);        // not below the true error
  EXPECT_LE(e.error, 3.0 * truth);  // and within a factor 3
  EXPECT_NEAR(e.relative_error, e.error / v[0].value, 1e-15);
}

TEST(DiscretisationError, FirstOrderSequenceIsNotUnderestimated) {
  const auto v = power_law(-1.0, 3.0, 1.0);
  const auto e = dc::estimate_discretisation_error(v, Convergence::smooth);
  ASSERT_TRUE(e.order.has_value());
  EXPECT_NEAR(*e.order, 1.0, 1e-9);
  EXPECT_NEAR(e.extrapolated, -1.0, 1e-12);
  const double truth = std::abs(v[0].value + 1.0);
  EXPECT_GE(e.error, truth);
  EXPECT_LE(e.error, 3.0 * truth);
}

TEST(DiscretisationError, AHighObservedOrderDoesNotShrinkTheEstimate) {
  // Order 4 on these grids: credited with the expected order, so the bound exceeds the truth.
  const auto v = power_law(1.0, 1e4, 4.0);
  const auto e = dc::estimate_discretisation_error(v, Convergence::smooth);
  ASSERT_TRUE(e.order.has_value());
  EXPECT_NEAR(*e.order, 4.0, 1e-6);
  EXPECT_GE(e.error, std::abs(v[0].value - 1.0));
}

TEST(DiscretisationError, AFinePairThatAgreesByChanceKeepsTheCoarsePairsPrediction) {
  // The finest two values almost agree (the contact set gained an element), the coarser pair
  // does not: the estimate stays at the coarser pair's prediction.
  std::vector<GridValue> v = {{0.01, 1.0 + 1e-4}, {0.02, 1.0 + 1.01e-4}, {0.04, 1.0 + 2e-3}};
  const auto e = dc::estimate_discretisation_error(v, Convergence::smooth);
  const double coarse_pair = (2e-3 - 1.01e-4) / ((std::pow(2.0, 1.75) - 1.0) * std::pow(2.0, 1.75));
  EXPECT_GE(e.error, coarse_pair);
}

TEST(DiscretisationError, NonMonotoneValuesGetABandOfTheChanges) {
  std::vector<GridValue> v = {{0.01, 1.000}, {0.02, 1.004}, {0.04, 0.990}};
  const auto e = dc::estimate_discretisation_error(v, Convergence::smooth);
  EXPECT_EQ(e.method, "band");
  EXPECT_FALSE(e.order.has_value());
  EXPECT_DOUBLE_EQ(e.extrapolated, 1.0);
  EXPECT_NEAR(e.error, std::max(0.004, 0.014 / std::pow(2.0, 1.75)), 1e-15);
}

TEST(DiscretisationError, ThreeDContactsCreditAtLeastTheSmallestOrderAndBoundNonMonotoneValues) {
  // The options a 3-D contact solve's estimate takes (apps/runs/accuracy_estimate.cpp): an
  // observed order of 1 is credited as 1.5 (a first-order sequence's estimate then falls below its
  // truth: the floor is for results that converge at O(h^2) overall), and non-monotone values get
  // the monotone bound at the expected order instead of the band of the last change.
  dc::ErrorEstimateOptions three_d;
  three_d.smallest_order = 1.5;
  three_d.order_bound_when_not_monotone = true;
  const auto first = power_law(-1.0, 3.0, 1.0);
  const auto e = dc::estimate_discretisation_error(first, Convergence::smooth, three_d);
  ASSERT_TRUE(e.order.has_value());
  EXPECT_NEAR(*e.order, 1.0, 1e-9) << "the observed order is reported";
  const double d1 = std::abs(first[0].value - first[1].value), d2 = std::abs(first[1].value - first[2].value);
  const double r15 = std::pow(2.0, 1.5);
  EXPECT_NEAR(e.error, 1.25 * std::max(d1 / (r15 - 1.0), d2 / ((r15 - 1.0) * r15)), 1e-15);
  EXPECT_LT(e.error, dc::estimate_discretisation_error(first, Convergence::smooth).error);
  // A second-order sequence is untouched by the floor.
  const auto second = power_law(2.0, 50.0, 2.0);
  EXPECT_DOUBLE_EQ(dc::estimate_discretisation_error(second, Convergence::smooth, three_d).error,
                   dc::estimate_discretisation_error(second, Convergence::smooth).error);
  std::vector<GridValue> v = {{0.01, 1.000}, {0.02, 1.004}, {0.04, 0.990}};
  const auto b = dc::estimate_discretisation_error(v, Convergence::smooth, three_d);
  EXPECT_EQ(b.method, "band");
  EXPECT_FALSE(b.order.has_value());
  EXPECT_DOUBLE_EQ(b.extrapolated, 1.0);
  const double r = std::pow(2.0, 1.75);
  EXPECT_NEAR(b.error, 1.25 * std::max(0.004 / (r - 1.0), 0.014 / ((r - 1.0) * r)), 1e-15);
}

TEST(DiscretisationError, BandQuantitiesAreFirstOrderByWholeElements) {
  // Three grids: 1.25 x max(the finer change, the coarser change / 2).
  std::vector<GridValue> v = {{0.01, 10.0}, {0.02, 10.3}, {0.04, 10.1}};
  auto e = dc::estimate_discretisation_error(v, Convergence::band);
  EXPECT_EQ(e.method, "band");
  EXPECT_NEAR(e.error, 1.25 * 0.3, 1e-12);
  EXPECT_NEAR(e.relative_error, 0.0375, 1e-12);
  v[2].value = 11.3;  // the coarser change governs
  e = dc::estimate_discretisation_error(v, Convergence::band);
  EXPECT_NEAR(e.error, 1.25 * 1.0 / 2.0, 1e-12);
  // Two grids: 3 x the change.
  v.pop_back();
  e = dc::estimate_discretisation_error(v, Convergence::band);
  EXPECT_NEAR(e.error, 3.0 * 0.3, 1e-12);
  // A first-order sequence is covered by 1.25 x its error.
  const std::vector<GridValue> first_order = {{0.01, 1.01}, {0.02, 1.02}, {0.04, 1.04}};
  EXPECT_NEAR(dc::estimate_discretisation_error(first_order, Convergence::band).error, 1.25 * 0.01, 1e-12);
  // In 2-D the band is no smaller than the largest change.
  dc::ErrorEstimateOptions two_d;
  two_d.band_at_least_largest_change = true;
  EXPECT_NEAR(dc::estimate_discretisation_error(first_order, Convergence::band, two_d).error, 0.02, 1e-12);
}

TEST(DiscretisationError, TwoGridsAssumeTheExpectedOrderWithTheLargerSafetyFactor) {
  const auto v = power_law(5.0, 100.0, 2.0, 0.01, 2);
  const auto e = dc::estimate_discretisation_error(v, Convergence::smooth);
  EXPECT_EQ(e.method, "assumed_order");
  EXPECT_FALSE(e.order.has_value());
  const double d = std::abs(v[0].value - v[1].value);
  EXPECT_NEAR(e.error, 3.0 * d / (std::pow(2.0, 1.75) - 1.0), 1e-12);
  EXPECT_GE(e.error, std::abs(v[0].value - 5.0));
}

TEST(DiscretisationError, AZeroValueIsJudgedAgainstItsScale) {
  std::vector<GridValue> v = {{0.01, 1e-9}, {0.02, 2e-9}, {0.04, -1e-9}};
  dc::ErrorEstimateOptions o;
  o.scale = 1.0;
  const auto e = dc::estimate_discretisation_error(v, Convergence::smooth, o);
  EXPECT_LT(e.relative_error, 1e-8);
}

/// A first-order error plus a part that depends on where the contact edge falls in an element
/// (a sine of the edge's position in element units): the grid's own value is off by the sine,
/// the mean over the grids shifted by thirds of an element is not.
TEST(DiscretisationError, ShiftedGridsSeparateTheEdgePositionFromTheSmoothError) {
  const double q_star = 1.0, c = 0.5, amplitude = 2.0, edge = 0.37;
  auto q = [&](double h, double shift) {
    return q_star + c * h + amplitude * h * std::sin(2.0 * std::acos(-1.0) * (edge / h + shift));
  };
  for (double h : {0.003, 0.0041, 0.0057}) {
    std::vector<dc::ShiftedGridValue> v;
    for (int k = 0; k < 3; ++k) {
      const double hk = h * (1 << k);
      v.push_back({hk, q(hk, 0.0), (q(hk, 0.0) + q(hk, 1.0 / 3.0) + q(hk, 2.0 / 3.0)) / 3.0});
    }
    const auto e = dc::estimate_discretisation_error_shifted(v, Convergence::smooth);
    EXPECT_EQ(e.method, "richardson_shifted");
    EXPECT_NEAR(e.extrapolated, q_star, 1e-12);  // the means are exactly first order here
    const double truth = std::abs(v[0].value - q_star);
    EXPECT_GE(e.error, truth) << h;
    EXPECT_LE(e.error, 3.0 * truth) << h;
  }
}

TEST(DiscretisationError, ShiftedMeansThatAreNotMonotoneFallBackToTheGridsOwnValues) {
  const std::vector<dc::ShiftedGridValue> v = {{0.01, 1.0, 1.001}, {0.02, 1.004, 0.999}, {0.04, 0.99, 1.003}};
  const auto e = dc::estimate_discretisation_error_shifted(v, Convergence::smooth);
  EXPECT_EQ(e.method, "band");
}

TEST(DiscretisationError, RejectsFewerThanTwoGridsAndUnorderedSizes) {
  EXPECT_THROW(dc::estimate_discretisation_error({{0.01, 1.0}}, Convergence::smooth), std::invalid_argument);
  EXPECT_THROW(dc::estimate_discretisation_error({{0.02, 1.0}, {0.01, 1.1}}, Convergence::smooth),
               std::invalid_argument);
}

}  // namespace
