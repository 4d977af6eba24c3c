// The sensitivity of a tangential solution to its rigid-slip increments with the stick/slip
// set fixed (dynamics/contact_sensitivity): against finite differences of the contact solve
// itself (a small extra shift after a Cattaneo step) and against Mindlin's full-stick stiffness
// 8 G* a (Johnson 7.2; 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2) within the grid's discretisation.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_sensitivity.hpp"
#include "tangential_support.hpp"

namespace dc::dynamics {
namespace {

using namespace dc::test;

TEST(ContactSensitivity, MatchesFiniteDifferencesAndMindlin) {
  const MaterialPair m = steel_on_steel();
  const double R = 0.01, P = 100.0, mu = 0.3;
  const SphereSetup s = sphere_setup(24, 1.3, m, R, P);
  TangentialProblem problem(s.grid, m, s.heights, FrictionLaw::coulomb(mu));
  const SolverSpec solver = [] {
    SolverSpec sp = native_tangential_solver();
    sp.tol = 1e-12;
    return sp;
  }();
  const NormalSpec load{Control::force, P};
  // A small shift: nearly all of the contact sticks (Mindlin).
  const double shift = 1e-9;
  TangentialSolution base = problem.convected_step(load, {shift, 0.0, 0.0}, 0.0, solver);
  expect_certified(base);
  const TangentialMemory memory = problem.memory();
  TangentialSensitivity sensitivity;
  const Eigen::Matrix3d G = sensitivity.compute(problem.tangential_compliance(), s.grid, base);
  const double h = 1e-11;
  const TangentialSolution more = problem.convected_step(load, {h, 0.0, 0.0}, 0.0, solver);
  problem.restore(memory);
  const double fd = (more.resultants[0] - base.resultants[0]) / h;
  EXPECT_NEAR(G(0, 0) / fd, 1.0, 0.02) << "G00 " << G(0, 0) << " finite difference " << fd;
  const double G1 = m.body.G, G2 = m.base.G, nu = 0.3;
  const double G_star = 1.0 / ((2.0 - nu) / G1 + (2.0 - nu) / G2);
  EXPECT_NEAR(-G(0, 0) / (8.0 * G_star * s.hz.a), 1.0, 0.05) << "Mindlin";
  EXPECT_NEAR(G(1, 1) / G(0, 0), 1.0, 0.02);  // the circle: x and y alike
}

}  // namespace
}  // namespace dc::dynamics
