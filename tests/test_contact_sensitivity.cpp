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
  const SolverOptions solver = [] {
    SolverOptions sp = native_tangential_solver();
    sp.tol = 1e-12;
    return sp;
  }();
  const NormalSpec load{Control::force, P};
  // A small shift: nearly all of the contact sticks (Mindlin).
  const double shift = 1e-9;
  TangentialSolution base = problem.convected_step(load, {shift, 0.0, 0.0}, {0.0, 0.0}, solver);
  expect_certified(base);
  const TangentialMemory memory = problem.memory();
  TangentialSensitivity sensitivity;
  const Eigen::Matrix3d G = sensitivity.compute(problem.tangential_compliance(), s.grid, base);
  const double h = 1e-11;
  const TangentialSolution more = problem.convected_step(load, {h, 0.0, 0.0}, {0.0, 0.0}, solver);
  problem.restore(memory);
  const double fd = (more.resultants[0] - base.resultants[0]) / h;
  EXPECT_NEAR(G(0, 0) / fd, 1.0, 0.02) << "G00 " << G(0, 0) << " finite difference " << fd;
  const double G1 = m.body.G, G2 = m.base.G, nu = 0.3;
  const double G_star = 1.0 / ((2.0 - nu) / G1 + (2.0 - nu) / G2);
  EXPECT_NEAR(-G(0, 0) / (8.0 * G_star * s.hz.a), 1.0, 0.05) << "Mindlin";
  EXPECT_NEAR(G(1, 1) / G(0, 0), 1.0, 0.02);  // the circle: x and y alike
}

/// Newton's Jacobian of a step (`compute_full`, partial slip, kappa != 0) against central
/// differences of the same step (from the same memory, the same travel) in each shift, to 1e-3.
/// The step: a shift `a` with the memory carried over `travel` (m, along x and y).
void expect_full_sensitivity_matches_central_differences(TangentialProblem& problem, double mu,
                                                         const NormalSpec& load,
                                                         const std::array<double, 3>& a,
                                                         const std::array<double, 2>& travel,
                                                         const SolverOptions& solver) {
  const TangentialMemory memory = problem.memory();  // before the step
  const TangentialSolution base = problem.convected_step(load, a, travel, solver);
  expect_certified(base);
  ASSERT_GT(base.n_slip, 0);
  ASSERT_GT(base.n_stick, 0);
  TangentialSensitivity sensitivity;
  ASSERT_NE(problem.tangential_from_normal(), nullptr);
  TangentialSensitivity::Coupling coupling{&problem.normal_compliance(), problem.tangential_from_normal(),
                                           problem.normal_from_tangential(), true};
  const Eigen::Matrix3d G =
      sensitivity.compute_full(problem.tangential_compliance(), coupling, FrictionLaw::coulomb(mu), problem.grid(), base);
  const Eigen::Matrix3d G0 = sensitivity.compute(problem.tangential_compliance(), problem.grid(), base);
  // compute_full starts each mode's GMRES from the last call's solution: called again on the same
  // step it starts at the answer (one operator apply per mode, the initial residual) and gives
  // the same Jacobian to GMRES's tolerance (1e-6).
  const long iterations_before = sensitivity.iterations();
  const Eigen::Matrix3d G_again =
      sensitivity.compute_full(problem.tangential_compliance(), coupling, FrictionLaw::coulomb(mu), problem.grid(), base);
  EXPECT_LE(sensitivity.iterations() - iterations_before, 3) << "a warm start at the answer";
  EXPECT_LE((G_again - G).cwiseAbs().maxCoeff(), 1e-5 * G.cwiseAbs().maxCoeff());
  // Newton's Jacobian: the same step (from the same memory) with its increment changed by +-h.
  const double h = 1e-4 * std::hypot(a[0], a[1]);
  for (int l = 0; l < 2; ++l) {
    std::array<double, 3> plus = a, minus = a;
    plus[l] += h;
    minus[l] -= h;
    problem.restore(memory);
    const TangentialSolution more = problem.convected_step(load, plus, travel, solver);
    problem.restore(memory);
    const TangentialSolution less = problem.convected_step(load, minus, travel, solver);
    const double fd = (more.resultants[l] - less.resultants[l]) / (2.0 * h);
    EXPECT_NEAR(G(l, l) / fd, 1.0, 1e-3) << "mode " << l << ": coupled " << G(l, l) << ", uncoupled " << G0(l, l)
                                         << ", finite difference " << fd;
    // Started from another step's sensitivity (the neighbouring increment's): the same bound.
    TangentialSensitivity warm;
    (void)warm.compute_full(problem.tangential_compliance(), coupling, FrictionLaw::coulomb(mu), problem.grid(), more);
    const Eigen::Matrix3d G_warm =
        warm.compute_full(problem.tangential_compliance(), coupling, FrictionLaw::coulomb(mu), problem.grid(), base);
    EXPECT_NEAR(G_warm(l, l) / fd, 1.0, 1e-3) << "mode " << l << " from a warm start";
  }
}

/// A soft body on steel (kappa != 0, (4.3)), its Hertz setup and a partial-slip shift: a third of
/// the full-sliding one (Mindlin: 3 mu P / (16 G* a)).
struct SoftSphere {
  MaterialPair m{Elastic::from_E_nu(2.0e9, 0.4), Elastic::from_E_nu(2.1e11, 0.3)};
  double R = 0.01, P = 10.0, mu = 0.3;
  SphereSetup s = sphere_setup(20, 1.3, m, R, P);
  double shift = mu * P / (16.0 * (1.0 / ((2.0 - m.body.nu) / m.body.G + (2.0 - m.base.nu) / m.base.G)) * s.hz.a);
  SolverOptions solver = [] {
    SolverOptions sp = native_tangential_solver();
    sp.tol = 1e-12;
    return sp;
  }();
};

TEST(ContactSensitivity, DissimilarMaterialsCouplePressureAndTraction) {
  // A soft body on steel (kappa != 0, (4.3)) under partial slip: the traction changes the
  // pressure (kappa B32) and the pressure the slip (kappa B21), and the slipping elements'
  // traction turns with the slip. Newton's Jacobian is the derivative of the step's resultants
  // with respect to the step's own increment: against central differences of the same step
  // (from the same memory) for each shift. With no element changing state within +-h the map
  // is linear there, so they agree to the solver's tolerance: bound 1e-3 (the stick-set-only
  // sensitivity, which holds the pressure and the slipping tractions, is off by ~2x).
  const SoftSphere b;
  ASSERT_GT(std::abs(b.m.kappa()) * b.m.body.G, 0.1);
  TangentialProblem problem(b.s.grid, b.m, b.s.heights, FrictionLaw::coulomb(b.mu));
  expect_full_sensitivity_matches_central_differences(problem, b.mu, {Control::force, b.P},
                                                      {b.shift, 0.3 * b.shift, 0.0}, {0.0, 0.0}, b.solver);
}

TEST(ContactSensitivity, HoldsForAStepWithLateralConvection) {
  // The same after a first step, with the memory carried over a diagonal travel of (0.3, 0.4)
  // elements (bilinear between four shifts): the travel is held in Newton's Jacobian, and at a
  // fixed travel the step's linearisation is still the derivative of its resultants.
  const SoftSphere b;
  TangentialProblem problem(b.s.grid, b.m, b.s.heights, FrictionLaw::coulomb(b.mu));
  const NormalSpec load{Control::force, b.P};
  const std::array<double, 3> a = {0.3 * b.shift, 0.2 * b.shift, 0.0};
  expect_certified(problem.convected_step(load, a, {0.0, 0.0}, b.solver));
  expect_full_sensitivity_matches_central_differences(problem, b.mu, load, a,
                                                      {0.3 * b.s.grid.dx, 0.4 * b.s.grid.dy}, b.solver);
}

TEST(ContactSensitivity, SteadyRollingWithDissimilarMaterialsMatchesCentralDifferences) {
  // The steady model's Jacobian with kappa != 0: per element of travel the slip is
  // d(ds) = dx dxi m + (B22 - S B22) dtau + kappa (B21 - S B21) dp, and the pressure follows the
  // traction through kappa B32. Against central differences of steady rolling in each
  // creepage, to 1e-3; the creep law's own linearisation (the pressure held) is reported beside.
  const SoftSphere b;
  TangentialProblem problem(b.s.grid, b.m, b.s.heights, FrictionLaw::coulomb(b.mu));
  const double creepage = 0.2 * b.mu * b.s.hz.a / b.R;  // partial slip: about a third of Kalker's saturation
  RollingLoad rolling;
  rolling.normal = {Control::force, b.P};
  rolling.modes[0].value = creepage;
  rolling.modes[1].value = 0.3 * creepage;
  const TangentialSolution base = problem.steady_rolling(rolling, b.solver);
  expect_certified(base);
  ASSERT_GT(base.n_slip, 0);
  ASSERT_GT(base.n_stick, 0);
  ASSERT_NE(problem.convective_from_normal(), nullptr);
  TangentialSensitivity sensitivity;
  const TangentialSensitivity::Coupling coupling{&problem.normal_compliance(), problem.convective_from_normal(),
                                                 problem.normal_from_tangential(), true};
  const Eigen::Matrix3d G = b.s.grid.dx * sensitivity.compute_full(problem.convective_compliance(), coupling,
                                                                   FrictionLaw::coulomb(b.mu), problem.grid(), base);
  const Eigen::Matrix3d G0 = sensitivity.compute_steady(problem.convective_compliance(),
                                                        problem.tangential_compliance(), problem.grid(), base);
  const double h = 1e-4 * creepage;
  for (int l = 0; l < 2; ++l) {
    RollingLoad plus = rolling, minus = rolling;
    plus.modes[l].value += h;
    minus.modes[l].value -= h;
    const double fd =
        (problem.steady_rolling(plus, b.solver).resultants[l] - problem.steady_rolling(minus, b.solver).resultants[l]) /
        (2.0 * h);
    EXPECT_NEAR(G(l, l) / fd, 1.0, 1e-3) << "creepage " << l << ": coupled " << G(l, l) << ", pressure held "
                                         << G0(l, l) << ", finite difference " << fd;
  }
}

}  // namespace
}  // namespace dc::dynamics
