// Label slow: Ipopt factors the saddle matrix (body + dense half-space block) every iteration, ~40 s a case here.
// The sparse saddle form (a) against the condensed program (b) on the same finite body: Ipopt's
// saddle point over (p, v, a) satisfies the condensed program's KKT conditions (its certificate,
// measured with the kept factor), gives the same pressure, approach and energy, and its body
// displacement satisfies the free body's equilibrium K u = Pi B p (the resultant balanced by
// the rigid-body inertia, no support reactions). The tangential problem (shift by force,
// torsion by angle, partial slip) by the sparse form over (tau, v, a) gives the condensed
// program's tractions, rigid shift or rotation and resultants, and its certificate.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "finite_contact.hpp"
#include "hertz.hpp"
#include "sparse_tangential_pair.hpp"
#include "linear_operator.hpp"
#include "saddle_form.hpp"
#include "stress_equilibrium.hpp"

namespace dc {
namespace {

constexpr double kR = 0.01, kE = 2.1e11, kNu = 0.3;
constexpr double kCertificateTol = 1e-6;  // SolverOptions's default

FeBodySpec hemisphere(const std::string& program) {
  FeBodySpec s;
  s.shape = FeShape::hemisphere;
  s.radius = kR;
  s.elements = {3, 3, 2};  // a coarse body (about 2k dofs): MUMPS factors the saddle matrix quickly
  s.contact_size = 5e-4;
  s.material = {fe::isotropic_stiffness(kE, kNu, "test"), 7800.0};
  s.program = program;
  return s;
}

struct Both {
  FiniteNormalSolution condensed, sparse;
  double p_max = 0.0;
};

Both solve_both(const NormalSpec& control, int cells, Hessian hessian = Hessian::automatic) {
  const double L = 1.2e-3;
  const Grid g = Grid::make(3, cells, cells, -L, L, -L, L);
  SolverOptions native;
  native.backend = Backend::native;
  SolverOptions ipopt;
  ipopt.backend = Backend::ipopt;
  ipopt.hessian = hessian;
  const Elastic base = Elastic::from_E_nu(kE, kNu);
  FiniteContact b(hemisphere("condensed"), g, base);
  FiniteContact a(hemisphere("sparse"), g, base);
  Both out{b.solve_normal(control, native), a.solve_normal(control, ipopt), 0.0};
  EXPECT_EQ(out.condensed.contact.report.status, SolveStatus::converged) << out.condensed.contact.report.message;
  EXPECT_EQ(out.sparse.contact.report.status, SolveStatus::converged) << out.sparse.contact.report.message;
  for (double p : out.condensed.contact.pressure) out.p_max = std::max(out.p_max, p);
  return out;
}

/// Distance of two certified points of a strictly convex QP: of order the square root of
/// their KKT residual (degenerate complementarity), relative to the peak pressure.
void expect_same_point(const Both& r) {
  const double tol = std::sqrt(kCertificateTol);
  const auto& pa = r.sparse.contact.pressure;
  const auto& pb = r.condensed.contact.pressure;
  ASSERT_EQ(pa.size(), pb.size());
  double diff = 0.0;
  for (std::size_t i = 0; i < pa.size(); ++i) diff = std::max(diff, std::abs(pa[i] - pb[i]));
  EXPECT_LT(diff / r.p_max, tol);
  EXPECT_NEAR(r.sparse.contact.approach, r.condensed.contact.approach, tol * std::abs(r.condensed.contact.approach));
  EXPECT_NEAR(r.sparse.contact.force, r.condensed.contact.force, tol * r.condensed.contact.force);
  // The energy (the functional's value) at the optimum: second order in the distance.
  EXPECT_NEAR(r.sparse.contact.report.objective, r.condensed.contact.report.objective,
              kCertificateTol * std::abs(r.condensed.contact.report.objective) * 10.0);
  // The body's own displacement: the same field from v (sparse) and from the factor (condensed).
  const double u_scale = r.condensed.body_displacement.cwiseAbs().maxCoeff();
  EXPECT_LT((r.sparse.body_displacement - r.condensed.body_displacement).cwiseAbs().maxCoeff(), tol * u_scale);
}

TEST(FiniteSaddle, ForceControlAgreesWithTheCondensedProgram) {
  const Both r = solve_both({Control::force, 3000.0}, 12);
  EXPECT_LE(r.sparse.contact.report.certificate.worst(), kCertificateTol);
  expect_same_point(r);
}

TEST(FiniteSaddle, ApproachControlAgreesWithTheCondensedProgram) {
  const Both r = solve_both({Control::approach, 2e-6}, 12);
  expect_same_point(r);
}

TEST(FiniteSaddle, LimitedMemoryHessianReachesTheSamePoint) {
  const Both r = solve_both({Control::force, 3000.0}, 10, Hessian::limited_memory);
  expect_same_point(r);
}

TEST(FiniteSaddle, SaddlePointSatisfiesTheFreeBodysEquilibrium) {
  // K u = Pi B p with the free (unsupported) K: the supports carry no reaction because the
  // resultant of the contact force is balanced by the rigid-body inertia M R a.
  const double L = 1.2e-3;
  const Grid g = Grid::make(3, 10, 10, -L, L, -L, L);
  FiniteContact a(hemisphere("sparse"), g, Elastic::from_E_nu(kE, kNu));
  SolverOptions ipopt;
  ipopt.backend = Backend::ipopt;
  const FiniteNormalSolution s = a.solve_normal({Control::force, 3000.0}, ipopt);
  ASSERT_EQ(s.contact.report.status, SolveStatus::converged) << s.contact.report.message;
  const fe::ElasticBody& body = a.body();
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(body.dofs()));
  a.face().add_forces(s.contact.pressure.data(), 2, 1.0, F);
  EXPECT_NEAR(F.sum(), s.contact.force, 1e-9 * s.contact.force);  // B integrates the pressure
  const Eigen::Matrix<double, 6, 1> acc = body.rigid_mass().ldlt().solve(body.rigid_modes().transpose() * F);
  const Eigen::VectorXd balanced = F - body.mass_rigid_modes() * acc;
  const Eigen::VectorXd Ku = body.stiffness().selfadjointView<Eigen::Lower>() * s.body_displacement;
  EXPECT_LT((Ku - balanced).cwiseAbs().maxCoeff(), std::sqrt(kCertificateTol) * F.cwiseAbs().maxCoeff());
  // No mean rigid motion: (M R)'u = 0.
  const Eigen::Matrix<double, 6, 1> rigid = body.mass_rigid_modes().transpose() * s.body_displacement;
  EXPECT_LT(rigid.norm(), 1e-9 * body.mass() * s.body_displacement.cwiseAbs().maxCoeff());
}

TEST(FiniteSaddle, TangentialShiftByForceAgreesWithTheCondensedProgram) {
  const fe::testing::Pair r = fe::testing::solve_both(fe::testing::shift_by_force(0.6), 12, {3, 3, 2}, Backend::ipopt);
  fe::testing::expect_same_point(r);
  EXPECT_LT(r.sparse.amplitudes[0], 0.0) << "a force +F_x on the body meets a shift -s_x";
}

TEST(FiniteSaddle, TangentialTorsionByAngleAgreesWithTheCondensedProgram) {
  // An angle that slips the rim of the contact (a ~ 0.5 mm, mu p0 a / G ~ 4e-3 rad).
  const fe::testing::Pair r = fe::testing::solve_both(fe::testing::twist_by_angle(3e-3), 12, {3, 3, 2}, Backend::ipopt);
  fe::testing::expect_same_point(r);
  EXPECT_LT(r.sparse.resultants[2], 0.0) << "a twist +beta of the body meets a moment of the opposite sense";
}

TEST(FiniteSaddle, SaddlePointStressesAreTheBodysStresses) {
  // The inner minimum over the stresses (stress_equilibrium.hpp) is attained at the stresses of
  // a displacement field: H s = Gt'u, i.e. sigma_q = C B_q u at every quadrature point, with the
  // displacement u of the saddle point's pressure. Stresses in equilibrium that are not
  // compatible would leave the program above the condensed one's minimum.
  const double L = 1.2e-3;
  const Grid g = Grid::make(3, 10, 10, -L, L, -L, L);
  FiniteContact a(hemisphere("sparse"), g, Elastic::from_E_nu(kE, kNu));
  const HalfSpace half_space(g, MaterialPair{Elastic::make_rigid(), Elastic::from_E_nu(kE, kNu)});
  const std::unique_ptr<LinearOperator> hs(half_space.normal(OperatorKind::automatic));
  SolveOptions options;
  options.tol = 1e-10;
  const fe::StressEquilibrium eq = fe::stress_equilibrium(a.body());
  const SaddleNormalOutcome o = solve_saddle_normal(a.body(), eq, a.face(), *hs, g, a.face().heights(),
                                                    {Control::force, 3000.0}, options, "ipopt");
  ASSERT_TRUE(o.success) << o.message;
  ASSERT_EQ(o.weighted_stresses.size(), eq.stresses());
  const Eigen::VectorXd compatible = eq.forces.transpose() * o.body_displacement;  // Gt'u
  double worst = 0.0, scale = 0.0;
  for (std::size_t q = 0; q < eq.compliance.size(); ++q) {
    const Eigen::Matrix<double, 6, 1> Hs =
        eq.compliance[q] * Eigen::Map<const Eigen::Matrix<double, 6, 1>>(o.weighted_stresses.data() + 6 * q);
    worst = std::max(worst, (Hs - compatible.segment<6>(6 * static_cast<Eigen::Index>(q))).cwiseAbs().maxCoeff());
    scale = std::max(scale, Hs.cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, std::sqrt(kCertificateTol) * scale) << "largest incompatibility " << worst << " of " << scale;
}

}  // namespace
}  // namespace dc
