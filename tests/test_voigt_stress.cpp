// Principal stresses (core/voigt_stress.hpp, cyclic Jacobi): against closed forms (diagonal and
// rotated tensors whose eigenvalues are known, repeated roots included) and against Eigen's
// QR solver on random tensors, both to a few eps times the tensor's norm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "voigt_stress.hpp"

namespace voigt_stress_tests {

using dc::Voigt;

constexpr double kEps = 2.220446049250313e-16;

/// The Voigt array of R diag(l) R^T.
Voigt rotated(const Eigen::Vector3d& l, const Eigen::Matrix3d& R) {
  return dc::from_matrix(R * l.asDiagonal() * R.transpose());
}

double norm_of(const Voigt& s) { return dc::to_matrix(s).norm(); }

TEST(PrincipalStresses, DiagonalAndZero) {
  const Eigen::Vector3d p = dc::principal_stresses(Voigt{3.0, -1.0, 2.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(p(0), -1.0);
  EXPECT_EQ(p(1), 2.0);
  EXPECT_EQ(p(2), 3.0);
  const Eigen::Vector3d z = dc::principal_stresses(Voigt{0.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(z.norm(), 0.0);
}

// Pure shear tau in the xy plane: principal stresses -tau, 0, tau; Tresca's shear tau.
TEST(PrincipalStresses, PureShear) {
  const Eigen::Vector3d p = dc::principal_stresses(Voigt{0.0, 0.0, 0.0, 0.0, 0.0, 2.5});
  EXPECT_NEAR(p(0), -2.5, 4 * kEps * 2.5);
  EXPECT_NEAR(p(1), 0.0, 4 * kEps * 2.5);
  EXPECT_NEAR(p(2), 2.5, 4 * kEps * 2.5);
  EXPECT_NEAR(dc::tresca_shear(Voigt{0.0, 0.0, 0.0, 0.0, 0.0, 2.5}), 2.5, 4 * kEps * 2.5);
}

// Known eigenvalues, among them double and triple roots and a spread of 1e12, under rotations.
TEST(PrincipalStresses, RotatedKnownRoots) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Vector3d cases[] = {{-1.0, 0.3, 2.0},      {1.0, 1.0, -0.5},     {-0.7, -0.7, -0.7},
                                   {1e-12, 1.0, 1.0},     {-1.0, -1.0 + 1e-9, 3.0}, {1e6, -1e-6, 0.0},
                                   {0.31, 0.31, -1.0}};
  for (const Eigen::Vector3d& l : cases)
    for (int k = 0; k < 50; ++k) {
      const Eigen::Matrix3d R = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
      const Voigt s = rotated(l, R);
      Eigen::Vector3d expect = l;
      std::sort(expect.data(), expect.data() + 3);
      const Eigen::Vector3d p = dc::principal_stresses(s);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(p(i), expect(i), 16 * kEps * norm_of(s)) << l.transpose();
    }
}

// Random tensors: the same eigenvalues as Eigen's QR solver to a few eps |sigma|.
TEST(PrincipalStresses, AgreesWithEigenSolver) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const double scale = std::pow(10.0, 6.0 * u(rng));
    const Voigt s{scale * u(rng), scale * u(rng), scale * u(rng), scale * u(rng), scale * u(rng), scale * u(rng)};
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(dc::to_matrix(s), Eigen::EigenvaluesOnly);
    const Eigen::Vector3d p = dc::principal_stresses(s);
    worst = std::max(worst, (p - eig.eigenvalues()).cwiseAbs().maxCoeff() / norm_of(s));
  }
  std::printf("[ info ] worst |jacobi - eigen| / |sigma|: %.2e\n", worst);
  EXPECT_LT(worst, 8 * kEps);
}

// Tresca's shear from the invariants (and Jacobi near repeated roots): half the spread of the
// principal stresses, to a few eps |sigma|, on random tensors and on tensors with (nearly)
// repeated roots, where the invariant form switches to the eigenvalues.
TEST(TrescaShear, AgreesWithPrincipalStresses) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  const auto check = [&](const Voigt& s) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(dc::to_matrix(s), Eigen::EigenvaluesOnly);
    const double expect = 0.5 * (eig.eigenvalues()(2) - eig.eigenvalues()(0));
    worst = std::max(worst, std::abs(dc::tresca_shear(s) - expect) / norm_of(s));
  };
  for (int k = 0; k < 20000; ++k) {
    const double scale = std::pow(10.0, 6.0 * u(rng));
    check(Voigt{scale * u(rng), scale * u(rng), scale * u(rng), scale * u(rng), scale * u(rng), scale * u(rng)});
    // Two roots apart by 10^-14 .. 10^0 of the third, and a large hydrostatic part.
    const double gap = std::pow(10.0, -7.0 + 7.0 * u(rng));
    const Eigen::Matrix3d R = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
    check(rotated(Eigen::Vector3d(-1.0 + 5.0 * u(rng), 0.3, 0.3 + gap), R));
  }
  EXPECT_EQ(dc::tresca_shear(Voigt{-2.0, -2.0, -2.0, 0.0, 0.0, 0.0}), 0.0);  // hydrostatic: no shear
  std::printf("[ info ] worst |tresca - (s1 - s3) / 2| / |sigma|: %.2e\n", worst);
  EXPECT_LT(worst, 8 * kEps);
}

}  // namespace voigt_stress_tests
