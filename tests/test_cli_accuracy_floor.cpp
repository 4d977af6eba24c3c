// The floor of the approach's and the normal force's estimated error by the height detail the
// coarse grids miss (apps/runs/accuracy_estimate.hpp): the contact stiffness it scales the force's
// floor by is 2 E* sqrt(A / pi), Hertz's 3/2 P / delta and Boussinesq's punch P / delta.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "accuracy_estimate.hpp"
#include "hertz.hpp"

namespace {

using dc::runs::contact_stiffness;

TEST(ContactStiffness, IsHertzsAndBoussinesqs) {
  const double e_star = 1.15e11, R = 0.01, P = 100.0;
  const dc::hertz::SphereSolution h = dc::hertz::sphere(R, P, e_star);
  const double area = std::numbers::pi * h.a * h.a;
  EXPECT_NEAR(contact_stiffness(e_star, area), 1.5 * P / h.approach, 1e-12 * P / h.approach);
  // A rigid flat punch of radius a pressed by delta: P = 2 a E* delta (Boussinesq).
  const double a = 2e-3, delta = 1e-6, punch_force = 2.0 * a * e_star * delta;
  EXPECT_NEAR(contact_stiffness(e_star, std::numbers::pi * a * a), punch_force / delta, 1e-12 * punch_force / delta);
}

TEST(UnresolvedHeightFloor, TheForcesBandIsTheStiffnessTimesTheMissedHeight) {
  dc::runs::EstimatedQuantity force;
  force.quantity.name = "normal_force";
  force.quantity.value = 250.0;
  force.error.value = 250.0;
  force.error.error = 1e-3;
  force.error.relative_error = 4e-6;
  force.error.method = "richardson";
  force.error.order = 2.0;
  dc::runs::EstimatedQuantity approach = force;
  approach.quantity.name = "approach";
  approach.error.value = 2e-6;
  approach.error.error = 1e-10;
  std::vector<dc::runs::EstimatedQuantity> q{force, approach};
  const double unresolved = 3e-9, stiffness = contact_stiffness(1.15e11, 1e-6);
  dc::runs::floor_by_unresolved_height(q, unresolved, stiffness);
  EXPECT_DOUBLE_EQ(q[0].error.error, stiffness * unresolved);
  EXPECT_DOUBLE_EQ(q[0].error.relative_error, stiffness * unresolved / 250.0);
  EXPECT_EQ(q[0].error.method, "band");
  EXPECT_FALSE(q[0].error.order.has_value());
  EXPECT_DOUBLE_EQ(q[1].error.error, unresolved);  // the approach: the missed height itself
  // A floor below the estimate changes nothing.
  std::vector<dc::runs::EstimatedQuantity> kept{force};
  dc::runs::floor_by_unresolved_height(kept, 1e-15, stiffness);
  EXPECT_EQ(kept[0].error.method, "richardson");
  EXPECT_DOUBLE_EQ(kept[0].error.error, 1e-3);
}

}  // namespace
