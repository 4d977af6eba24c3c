// Finite contact in every time step (problem "dynamic" with an fe_body): an FE hemisphere
// dropped on the half-space against the Hertz impact. Checks:
// - a very stiff body (1000 x the half-space's modulus) agrees with the rigid-body dynamic run
//   of the same drop, and both are the Hertz impact of a rigid sphere on the half-space (Johnson 11.4: contact time 2.9432 delta*/v0, peak force
//   4/3 E* R^1/2 delta*^3/2, elastic rebound at v0), with the mesh's mass;
// - a body of the half-space's material: the Hertz impact of the pair (E* halved, contact time
//   2^(2/5) = 1.32 x longer);
// Error budget: the static finite program gives Hertz's p0 within 3 % (stiff) and 5 % (pair)
// on these meshes (test_finite_contact); the force-approach law, which sets the impact, is
// no worse. Contact time and peak force: 3 % (stiff), 5 % (pair); rebound 1 % (the FE body's
// deformation is quasi-static in its accelerating frame: no energy goes into vibrations).
#include <cstdio>

#include <gtest/gtest.h>

#include "finite_drop.hpp"

namespace dc::dynamics {
namespace {

using namespace dc::dynamics::test;

TEST(FiniteDynamic, StiffBodyIsTheRigidSphereHertzImpact) {
  const nlohmann::json doc = drop_case(1000.0 * kE, "bdf2", 40);
  const Drop d = run_drop(doc);
  ASSERT_TRUE(d.result.completed) << d.result.status;
  // The rigid-body run of the same drop (a rigid sphere profile, the same mass, grid, steps):
  // the same impact within the FE face's gap error (3 %).
  const Drop rigid = run_drop(rigid_drop_case(doc, d.mass, d.centre_height));
  ASSERT_TRUE(rigid.result.completed) << rigid.result.status;
  EXPECT_NEAR(d.duration / rigid.duration, 1.0, 0.03) << d.duration << " vs the rigid run's " << rigid.duration;
  EXPECT_NEAR(d.peak / rigid.peak, 1.0, 0.03) << d.peak << " vs the rigid run's " << rigid.peak;
  EXPECT_NEAR(d.rebound / rigid.rebound, 1.0, 0.01);
  std::printf("stiff FE body: contact %.4g s, peak %.4g N, rebound %.5g m/s; rigid run %.4g s, %.4g N, %.5g m/s\n",
              d.duration, d.peak, d.rebound, rigid.duration, rigid.peak, rigid.rebound);
  // The mesh's mass and the half-space's E*.
  const HertzImpact h = hertz_impact(d.mass, kR, kE / (1.0 - kNu * kNu), kV0);
  EXPECT_NEAR(d.duration / h.duration, 1.0, 0.03) << "contact time " << d.duration << " vs " << h.duration;
  EXPECT_NEAR(d.peak / h.peak, 1.0, 0.03) << "peak force " << d.peak << " vs " << h.peak;
  EXPECT_NEAR(d.rebound / kV0, 1.0, 0.01);
  EXPECT_LE(d.result.worst_certificate, 1e-6);
  EXPECT_GT(d.max_body_displacement, 0.0);
  const HertzImpact hz = h;
  std::printf("Hertz: contact %.4g s, peak %.4g N\n", hz.duration, hz.peak);
}

TEST(FiniteDynamic, BodyOfTheHalfSpacesMaterialGivesThePairsLongerContact) {
  const Drop stiff = run_drop(drop_case(1000.0 * kE, "bdf2", 40));
  const Drop same = run_drop(drop_case(kE, "bdf2", 40));
  ASSERT_TRUE(same.result.completed) << same.result.status;
  const HertzImpact h = hertz_impact(same.mass, kR, 0.5 * kE / (1.0 - kNu * kNu), kV0);
  std::printf("pair: contact %.4g s (Hertz %.4g), peak %.4g N (Hertz %.4g); stiff body %.4g s, %.4g N\n", same.duration,
              h.duration, same.peak, h.peak, stiff.duration, stiff.peak);
  EXPECT_NEAR(same.duration / h.duration, 1.0, 0.05) << "contact time " << same.duration << " vs " << h.duration;
  EXPECT_NEAR(same.peak / h.peak, 1.0, 0.05) << "peak force " << same.peak << " vs " << h.peak;
  // Against the stiff body's run: 2^(2/5) longer, 2^(-2/5) lower peak (the same mesh's errors).
  EXPECT_NEAR(same.duration / stiff.duration, std::pow(2.0, 0.4), 0.03 * std::pow(2.0, 0.4));
  EXPECT_NEAR(same.peak / stiff.peak, std::pow(2.0, -0.4), 0.03 * std::pow(2.0, -0.4));
  EXPECT_GT(same.max_body_displacement, 100.0 * stiff.max_body_displacement);
}

}  // namespace
}  // namespace dc::dynamics
