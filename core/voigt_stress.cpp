#include "voigt_stress.hpp"

#include <Eigen/Eigenvalues>

namespace dc {

const char* to_string(VoigtComponent c) {
  switch (c) {
    case VoigtComponent::xx: return "xx";
    case VoigtComponent::yy: return "yy";
    case VoigtComponent::zz: return "zz";
    case VoigtComponent::yz: return "yz";
    case VoigtComponent::xz: return "xz";
    case VoigtComponent::xy: return "xy";
  }
  return "?";
}

Eigen::Matrix3d to_matrix(const Voigt& s) {
  Eigen::Matrix3d m;
  m << s[0], s[5], s[4],  //
      s[5], s[1], s[3],   //
      s[4], s[3], s[2];
  return m;
}

Voigt from_matrix(const Eigen::Matrix3d& m) {
  return {m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(1, 2) + m(2, 1)), 0.5 * (m(0, 2) + m(2, 0)),
          0.5 * (m(0, 1) + m(1, 0))};
}

Eigen::Matrix<double, 5, 6> deviatoric_coordinate_map() {
  const double c = 1.0 / (2.0 * std::sqrt(3.0));
  Eigen::Matrix<double, 5, 6> d = Eigen::Matrix<double, 5, 6>::Zero();
  d(0, 0) = -c;
  d(0, 1) = -c;
  d(0, 2) = 2.0 * c;
  d(1, 0) = 0.5;
  d(1, 1) = -0.5;
  d(2, 3) = 1.0;
  d(3, 4) = 1.0;
  d(4, 5) = 1.0;
  return d;
}

Eigen::Matrix<double, 5, 1> deviatoric_coordinates(const Voigt& s) {
  const double c = 1.0 / (2.0 * std::sqrt(3.0));
  Eigen::Matrix<double, 5, 1> u;
  u << c * (2.0 * s[2] - s[0] - s[1]), 0.5 * (s[0] - s[1]), s[3], s[4], s[5];
  return u;
}

Voigt from_deviatoric_coordinates(const Eigen::Matrix<double, 5, 1>& u) {
  // s_zz = 2 u1 / sqrt 3, s_xx = -u1 / sqrt 3 + u2, s_yy = -u1 / sqrt 3 - u2 (trace zero).
  const double r3 = std::sqrt(3.0);
  return {-u(0) / r3 + u(1), -u(0) / r3 - u(1), 2.0 * u(0) / r3, u(2), u(3), u(4)};
}

double sqrt_j2(const Voigt& s) { return deviatoric_coordinates(s).norm(); }

Eigen::Vector3d principal_stresses(const Voigt& s) {
  // Closed-form eigenvalues are inaccurate near repeated roots; Eigen's 3x3 solver is exact
  // to rounding and cheap.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(to_matrix(s), Eigen::EigenvaluesOnly);
  return eig.eigenvalues();  // ascending
}

double tresca_shear(const Voigt& s) {
  const Eigen::Vector3d p = principal_stresses(s);
  return 0.5 * (p(2) - p(0));
}

}  // namespace dc
