// Interpolation along one axis by the cubic Hermite of limited slopes (core/limited_hermite.hpp):
// a quadratic is exact on unevenly spaced nodes, also half a spacing beyond the outer nodes; the
// slope is continuous at every node on noisy data (the linear fall-back of a minmod of second
// differences put kinks there); monotone data stay monotone between the nodes, a step's faces
// stay flat; two nodes give the line through them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "limited_hermite.hpp"

namespace dc {
namespace {

struct Table {
  std::vector<double> x, v;
  double at(std::size_t cell, double t) const {
    return limited_hermite(
        x.size(), cell, t, [&](std::size_t k) { return x[k]; }, [&](std::size_t k) { return v[k]; });
  }
};

/// Nodes 0, 1, ... with spacings drawn from [0.5, 1.5].
std::vector<double> uneven_nodes(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<double> spacing(0.5, 1.5);
  std::vector<double> x(n, 0.0);
  for (std::size_t k = 1; k < n; ++k) x[k] = x[k - 1] + spacing(rng);
  return x;
}

TEST(LimitedHermite, AQuadraticIsExactOnUnevenNodes) {
  std::mt19937 rng(7);
  Table table;
  table.x = uneven_nodes(9, rng);
  const auto q = [](double x) { return 0.4 - 1.3 * x + 0.25 * x * x; };  // its vertex at x = 2.6
  for (double x : table.x) table.v.push_back(q(x));
  for (std::size_t cell = 0; cell + 1 < table.x.size(); ++cell) {
    const bool outer = cell == 0 || cell + 2 == table.x.size();
    for (double t = outer ? -0.5 : 0.0; t <= (outer ? 1.5 : 1.0) + 1e-12; t += 0.125) {
      const double x = table.x[cell] + t * (table.x[cell + 1] - table.x[cell]);
      EXPECT_NEAR(table.at(cell, t), q(x), 1e-13) << cell << " " << t;
    }
  }
}

TEST(LimitedHermite, TheSlopeIsContinuousAtEveryNodeOnNoisyData) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  Table table;
  table.x = uneven_nodes(40, rng);
  for (double x : table.x) table.v.push_back(0.05 * x * x + noise(rng));
  const double eps = 1e-6;
  double largest_jump = 0.0, largest_secant_change = 0.0;
  for (std::size_t node = 1; node + 1 < table.x.size(); ++node) {
    const double left = table.x[node] - table.x[node - 1], right = table.x[node + 1] - table.x[node];
    // One-sided difference quotients at the node from the cell on each side.
    const double from_left = (table.at(node - 1, 1.0) - table.at(node - 1, 1.0 - eps)) / (eps * left);
    const double from_right = (table.at(node, eps) - table.at(node, 0.0)) / (eps * right);
    largest_jump = std::max(largest_jump, std::abs(from_left - from_right));
    const double secant_left = (table.v[node] - table.v[node - 1]) / left;
    const double secant_right = (table.v[node + 1] - table.v[node]) / right;
    largest_secant_change = std::max(largest_secant_change, std::abs(secant_right - secant_left));
    EXPECT_EQ(table.at(node - 1, 1.0), table.v[node]);  // through the nodes
  }
  // The difference quotients differ by O(eps x curvature); a kink would be of the secants' change.
  EXPECT_LT(largest_jump, 1e-4 * largest_secant_change) << largest_secant_change;
}

TEST(LimitedHermite, MonotoneDataStayMonotoneAndAStepsFacesFlat) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> rise(0.0, 1.0);
  Table table;
  table.x = uneven_nodes(30, rng);
  double v = 0.0;
  for (std::size_t k = 0; k < table.x.size(); ++k) {
    // rises of every size, flat stretches and steps of 50
    v += k % 7 == 3 ? 50.0 : (k % 5 == 0 ? 0.0 : rise(rng));
    table.v.push_back(v);
  }
  for (std::size_t cell = 0; cell + 1 < table.x.size(); ++cell) {
    double previous = table.v[cell];
    for (int s = 1; s <= 64; ++s) {
      const double value = table.at(cell, s / 64.0);
      EXPECT_GE(value, previous - 1e-12) << cell << " " << s;
      previous = value;
    }
    EXPECT_NEAR(previous, table.v[cell + 1], 1e-12);
  }
  // A step 0 -> 1 between nodes 5 and 6: both faces exactly flat up to their last node.
  Table step;
  for (int k = 0; k < 12; ++k) {
    step.x.push_back(0.1 * k);
    step.v.push_back(k > 5 ? 1.0 : 0.0);
  }
  for (double t = 0.0; t <= 1.0; t += 0.0625) {
    EXPECT_EQ(step.at(4, t), 0.0) << t;
    EXPECT_EQ(step.at(6, t), 1.0) << t;
    EXPECT_GE(step.at(5, t), 0.0);
    EXPECT_LE(step.at(5, t), 1.0);
  }
}

TEST(LimitedHermite, TwoNodesGiveTheLine) {
  const Table line{{1.0, 3.0}, {2.0, -4.0}};
  for (double t = -0.5; t <= 1.5; t += 0.25) EXPECT_NEAR(line.at(0, t), 2.0 - 6.0 * t, 1e-14) << t;
}

}  // namespace
}  // namespace dc
