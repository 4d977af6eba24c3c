// The transient contact model (the paper's (3.8): memory convected by the step's travel) and
// the steady one (Section 5's quasi-stationary assumption) agree where both are valid: a 2-D
// steel cylinder (cylinder-dynamic-2d) rolling at a fixed creepage with small steps reaches
// steady rolling after its material has passed through the contact, and its creep force is
// then the steady model's at the same creepage.
//  - Travel of one element per step: the convected step is the marching step whose fixed point
//    the steady solver computes, so after a few contact lengths the two agree to the solvers'
//    certificates (bound: 10 certificate_tol mu P).
//  - Travel of 0.4 element per step: the memory is interpolated between whole-element shifts;
//    linear interpolation errs by O(dx / a) of the traction (bound: (dx / a) mu P).
// Both also match Carter's closed form within the grid's creep-law error.
#include <gtest/gtest.h>

#include <cmath>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "contact_closed_forms.hpp"
#include "contact_wrench.hpp"

namespace dc::dynamics {
namespace {

struct Rolling {
  Case c;
  double a, R, mu, P, xi;
  StepKinematics k;
};

Rolling rolling_case(const char* model) {
  nlohmann::json doc = dc::test::example_json("cylinder-dynamic-2d");
  doc["contact_model"] = model;
  Rolling r{build_case(doc), 0, 0, 0, 0, 0, {}};
  const DynamicSpec& s = *r.c.dynamic;
  r.R = s.radius;
  r.P = -s.force[2].value;
  r.mu = r.c.friction->mu;
  r.a = std::sqrt(4.0 * r.P * r.R / (M_PI * r.c.materials.E_star()));
  r.xi = closed_form::carter_creepage(r.a, r.R, r.mu, 0.5);  // half of mu P
  const double V = s.velocity[0];
  r.k = {Eigen::Vector3d(0, 0, r.R), Eigen::Quaterniond::Identity(), Eigen::Vector3d(V, 0, 0),
         Eigen::Vector3d(0, V * (1.0 - r.xi) / r.R, 0), 0.0};
  return r;
}

/// The creep force after rolling `lengths` contact lengths with steps travelling `travel` (m).
double transient_force(double travel, double lengths) {
  Rolling r = rolling_case("transient");
  ContactWrench contact(r.c);
  const double dt = travel / r.k.velocity.x();
  const int steps = static_cast<int>(std::ceil(lengths * 2.0 * r.a / travel));
  double F = 0.0;
  for (int n = 1; n <= steps; ++n) {
    contact.begin_step(dt);
    r.k.time = n * dt;
    F = contact.evaluate(r.k, -r.P).force.x();
    EXPECT_TRUE(contact.state().converged) << contact.state().message;
    contact.accept(r.k, -r.P);
  }
  EXPECT_GT(contact.state().n_stick, 0);
  EXPECT_GT(contact.state().n_slip, 0);
  return F;
}

double steady_force() {
  Rolling r = rolling_case("steady");
  ContactWrench contact(r.c);
  contact.begin_step(1e-3);
  const double F = contact.evaluate(r.k, -r.P).force.x();
  EXPECT_TRUE(contact.state().converged) << contact.state().message;
  return F;
}

TEST(DynamicTransientSteady, WholeElementTravelReachesTheSteadyCreepForce) {
  const Rolling r = rolling_case("steady");
  const double muP = r.mu * r.P, dx = r.c.grid.dx;
  const double steady = steady_force();
  const double transient = transient_force(dx, 8.0);
  EXPECT_NEAR(transient / muP, steady / muP, 10.0 * r.c.solver.certificate_tol);
  // Carter: |F| / (mu P) = 1/2 at this creepage; the force brakes (xi > 0: V > Omega R).
  EXPECT_NEAR(-steady / muP, 0.5, dx / r.a) << "creep law within the grid's error";
}

TEST(DynamicTransientSteady, FractionalTravelReachesTheSteadyCreepForce) {
  const Rolling r = rolling_case("steady");
  const double muP = r.mu * r.P, dx = r.c.grid.dx;
  const double steady = steady_force();
  const double transient = transient_force(0.4 * dx, 4.0);
  EXPECT_NEAR(transient / muP, steady / muP, dx / r.a);
}

}  // namespace
}  // namespace dc::dynamics
