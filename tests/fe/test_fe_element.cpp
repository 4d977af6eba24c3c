// The tet10 element and the free elastic body: patch test, rigid modes, anisotropic block
// under uniform stress against the closed form, stiffness checks, bad meshes.
#include <gtest/gtest.h>

#include "elastic_body.hpp"
#include "errors.hpp"
#include "fe_test_meshes.hpp"
#include "stress_equilibrium.hpp"
#include "tet10.hpp"

namespace dc::fe {
namespace {

Stiffness triclinic() {
  // A stable triclinic material (positive definite, every coupling present), Pa.
  std::array<double, 21> c{};
  const double diag[6] = {200e9, 180e9, 160e9, 60e9, 50e9, 70e9};
  int k = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j) c[k++] = i == j ? diag[i] : (i < 3 && j < 3 ? 70e9 : 5e9 + 1e9 * (i + j));
  return anisotropic_stiffness(c, "test");
}

Eigen::VectorXd linear_field(const BodyMesh& m, const Eigen::Matrix3d& G) {
  Eigen::VectorXd u(static_cast<Eigen::Index>(m.dofs()));
  for (std::size_t k = 0; k < m.nodes.size(); ++k) u.segment<3>(3 * static_cast<Eigen::Index>(k)) = G * m.nodes[k];
  return u;
}

Eigen::Matrix<double, 6, 1> voigt_strain(const Eigen::Matrix3d& G) {
  const Eigen::Matrix3d e = 0.5 * (G + G.transpose());
  Eigen::Matrix<double, 6, 1> v;
  v << e(0, 0), e(1, 1), e(2, 2), 2 * e(1, 2), 2 * e(0, 2), 2 * e(0, 1);
  return v;
}

TEST(FeElement, StiffnessChecksRejectUnstableMaterials) {
  EXPECT_NO_THROW(triclinic());
  EXPECT_THROW(isotropic_stiffness(1e9, 0.5, "m"), InputError);
  EXPECT_THROW(cubic_stiffness(100e9, 120e9, 50e9, "m"), InputError);  // C11 < C12: unstable
  std::array<double, 21> bad{};
  bad[0] = 1e9;
  EXPECT_THROW(anisotropic_stiffness(bad, "m"), InputError);
  const Stiffness C = isotropic_stiffness(2e11, 0.3, "m");
  EXPECT_NEAR(C(3, 3), 2e11 / 2.6, 1e-6 * 2e11);
}

TEST(FeElement, PatchTestLinearFieldHasNoInteriorForcesAndExactStress) {
  const BodyMesh m = testing::box_mesh(2, 1.0, 1.2, 0.8);
  const ElasticBody body(m, {BodyMaterial{triclinic(), 1000.0}});
  Eigen::Matrix3d G;
  G << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, 0.0, 4e-4, 1.5e-3;
  const Eigen::VectorXd u = linear_field(m, G);
  const Eigen::SparseMatrix<double> K = body.stiffness().selfadjointView<Eigen::Lower>();
  const Eigen::VectorXd f = K * u;
  const double scale = f.cwiseAbs().maxCoeff();
  for (std::size_t k = 0; k < m.nodes.size(); ++k) {
    const auto& x = m.nodes[k];
    const bool interior = x.x() > 1e-9 && x.x() < 1.0 - 1e-9 && x.y() > 1e-9 && x.y() < 1.2 - 1e-9 &&
                          x.z() > 1e-9 && x.z() < 0.8 - 1e-9;
    if (interior) {
      EXPECT_LT(f.segment<3>(3 * static_cast<Eigen::Index>(k)).norm(), 1e-9 * scale);
    }
  }
  const auto stress = body.element_stress(u);
  const Eigen::Matrix<double, 6, 1> exact = triclinic() * voigt_strain(G);
  for (const auto& s : stress) EXPECT_LT((s - exact).norm(), 1e-9 * exact.norm());
}

TEST(FeElement, RigidModesCarryNoForceAndStiffnessIsSymmetricPositive) {
  const BodyMesh m = testing::box_mesh(2, 1.0, 1.0, 1.0);
  const ElasticBody body(m, {BodyMaterial{triclinic(), 1000.0}});
  const Eigen::SparseMatrix<double> K = body.stiffness().selfadjointView<Eigen::Lower>();
  const Eigen::MatrixXd KR = K * body.rigid_modes();
  EXPECT_LT(KR.cwiseAbs().maxCoeff(), 1e-12 * 200e9);
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Kd);
  // Exactly six zero eigenvalues (the rigid modes), the rest positive.
  const double lmax = eig.eigenvalues().maxCoeff();
  int zeros = 0;
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i) {
    EXPECT_GT(eig.eigenvalues()(i), -1e-10 * lmax);
    zeros += eig.eigenvalues()(i) < 1e-10 * lmax ? 1 : 0;
  }
  EXPECT_EQ(zeros, 6);
  EXPECT_NEAR(body.mass(), 1000.0, 1e-9);
  EXPECT_NEAR(body.centre_of_mass().x(), 0.5, 1e-12);
}

TEST(FeElement, StressFormReproducesTheStiffnessAndTheElementStresses) {
  // K = Gt H^-1 Gt' (stress_equilibrium.hpp), and for any u the stresses C B_q u minimise the
  // complementary energy among stresses in equilibrium with K u: H s = Gt' u, s_q = sqrt(w_q) sigma_q.
  const BodyMesh m = testing::box_mesh(2, 1.0, 1.0, 1.0);
  const ElasticBody body(m, {BodyMaterial{triclinic(), 1000.0}});
  const StressEquilibrium eq = stress_equilibrium(body);
  ASSERT_EQ(eq.stresses(), 24 * m.elements.size());
  const Eigen::MatrixXd G = Eigen::MatrixXd(eq.forces);
  Eigen::MatrixXd HinvGt = Eigen::MatrixXd::Zero(G.cols(), G.rows());
  for (std::size_t q = 0; q < eq.compliance.size(); ++q)
    HinvGt.middleRows(6 * static_cast<Eigen::Index>(q), 6) =
        eq.compliance[q].inverse() * G.middleCols(6 * static_cast<Eigen::Index>(q), 6).transpose();
  const Eigen::MatrixXd K = Eigen::MatrixXd(Eigen::SparseMatrix<double>(body.stiffness().selfadjointView<Eigen::Lower>()));
  EXPECT_LT((G * HinvGt - K).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
  // A linear field: every point's stress is C times the uniform strain.
  Eigen::Matrix3d grad;
  grad << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, 0.0, 4e-4, 7e-4;
  const Eigen::VectorXd weighted = HinvGt * linear_field(m, grad);
  const Eigen::Matrix<double, 6, 1> expected = triclinic() * voigt_strain(grad);
  for (std::size_t q = 0; q < eq.compliance.size(); ++q)
    EXPECT_LT((weighted.segment<6>(6 * static_cast<Eigen::Index>(q)) / eq.root_weight[q] - expected).norm(),
              1e-9 * expected.norm());
}

TEST(FeElement, AnisotropicBlockUnderUniformStressMatchesClosedForm) {
  // Uniform stress sigma: the equivalent nodal loads int B'sigma dV do not depend on C.
  // The free body deforms by the strain C^-1 sigma exactly (the element passes the patch test).
  const BodyMesh m = testing::box_mesh(2, 0.02, 0.03, 0.01);
  const Stiffness C = triclinic();
  const ElasticBody body(m, {BodyMaterial{C, 7800.0}});
  Eigen::Matrix<double, 6, 1> sigma;
  sigma << 50e6, -20e6, 10e6, 5e6, -8e6, 12e6;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.dofs()));
  const double a = 0.5854101966249685, b = 0.1381966011250105;
  for (const auto& el : m.elements) {
    TetNodes x;
    for (int i = 0; i < 10; ++i) x.col(i) = m.nodes[el[i]];
    for (int q = 0; q < 4; ++q) {
      Eigen::Vector4d L = Eigen::Vector4d::Constant(b);
      L(q) = a;
      const Tet10Vector fe = 0.25 * tet_volume(x) * tet10_strain(x, L).transpose() * sigma;
      for (int n = 0; n < 10; ++n) F.segment<3>(3 * el[n]) += fe.segment<3>(3 * n);
    }
  }
  Eigen::VectorXd u;
  body.deform(F, u);
  for (const auto& s : body.element_stress(u)) EXPECT_LT((s - sigma).norm(), 1e-7 * sigma.norm());
}

TEST(FeElement, DegenerateElementIsAnInputError) {
  std::vector<Eigen::Vector3d> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  EXPECT_THROW(quadratic_mesh_from_linear(v, {{0, 1, 2, 3}}, "fe_body.mesh"), InputError);
}

TEST(FeElement, InvertedElementIsAnInputError) {
  std::vector<Eigen::Vector3d> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  // Three elements of one handedness and one turned round.
  const std::vector<std::array<int, 4>> tets{{0, 1, 2, 3}, {1, 2, 3, 4}, {0, 1, 2, 3}, {0, 2, 1, 3}};
  try {
    quadratic_mesh_from_linear(v, tets, "fe_body.mesh");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "fe_body.mesh");
    EXPECT_NE(std::string(e.what()).find("inverted"), std::string::npos);
  }
}

}  // namespace
}  // namespace dc::fe
