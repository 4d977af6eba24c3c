#include "voigt_stress.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

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
  // Cyclic Jacobi rotations on the symmetric 3x3 tensor (Golub & Van Loan, Matrix Computations,
  // 4th ed., 8.5.2-8.5.3, the symmetric Schur decomposition of each 2x2 block; the update in the
  // rounding-robust form of Rutishauser, Numerical Recipes 11.1, eq. 11.1.14-11.1.18). Each
  // rotation zeroes one off-diagonal entry exactly; convergence is quadratic (3-5 sweeps), and
  // the eigenvalues are accurate to rounding (backward stable: within a few eps |sigma| of
  // Eigen's QR solver, tests/test_voigt_stress.cpp) even at repeated roots, where closed-form
  // (Cardano) roots lose half the digits. 5-10 x faster than Eigen's iterative solver per point.
  double d[3] = {s[0], s[1], s[2]};
  double a01 = s[5], a02 = s[4], a12 = s[3];
  for (int sweep = 0; sweep < 50; ++sweep) {
    if (a01 == 0.0 && a02 == 0.0 && a12 == 0.0) break;
    // One rotation in the plane (p, q): apq -> 0; (apr, aqr) the entries of the third index r.
    const auto rotate = [&d](int p, int q, double& apq, double& apr, double& aqr) {
      if (apq == 0.0) return;
      const double dp = d[p], dq = d[q];
      // Below the rounding of both diagonal entries: the entry changes no eigenvalue's digit.
      if (std::abs(apq) <= 1e-18 * (std::abs(dp) + std::abs(dq))) {
        apq = 0.0;
        return;
      }
      const double theta = (dq - dp) / (2.0 * apq);
      const double t = std::abs(theta) > 1e150 ? 0.5 / theta
                                               : (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
      const double c = 1.0 / std::sqrt(t * t + 1.0), sn = t * c, tau = sn / (1.0 + c);
      d[p] = dp - t * apq;
      d[q] = dq + t * apq;
      apq = 0.0;
      const double g = apr, h = aqr;
      apr = g - sn * (h + g * tau);
      aqr = h + sn * (g - h * tau);
    };
    rotate(0, 1, a01, a02, a12);
    rotate(0, 2, a02, a01, a12);
    rotate(1, 2, a12, a01, a02);
  }
  Eigen::Vector3d e(d[0], d[1], d[2]);
  std::sort(e.data(), e.data() + 3);
  return e;  // ascending
}

namespace {
/// Tresca's shear where two principal stresses of the deviator (dx, dy, dz; shears s[3..5])
/// nearly coincide, Lode's r near +-1. The isolated eigenvalue l is accurate from Lode's angle
/// (the cosine at its extremum squares the angle's error); its eigenvector v is the largest cross
/// product of two rows of (dev - l I) (Kopp, Int. J. Mod. Phys. C 19 (2008) 523, the hybrid
/// method), well conditioned as l is isolated; the pair's half-difference d is that of the 2 x 2
/// projection of the deviator on the plane normal to v, with no cancellation. The pair's mean is
/// -l / 2 (trace zero), so (s1 - s3) / 2 = (1.5 |l| + d) / 2. Returns a negative value where the
/// rows are degenerate (the caller then uses the Jacobi eigenvalues).
double tresca_near_double_root(double dx, double dy, double dz, const Voigt& s, double j2, double r) {
  const double theta = std::acos(std::clamp(r, -1.0, 1.0)) / 3.0;
  const double radius = 2.0 * std::sqrt(j2 / 3.0);
  const double l = r >= 0.0 ? radius * std::cos(theta) : radius * std::cos(theta + 2.0 * std::numbers::pi / 3.0);
  const Eigen::Vector3d b0(dx - l, s[5], s[4]), b1(s[5], dy - l, s[3]), b2(s[4], s[3], dz - l);
  Eigen::Vector3d v = b0.cross(b1);
  for (const Eigen::Vector3d& c : {b0.cross(b2), b1.cross(b2)})
    if (c.squaredNorm() > v.squaredNorm()) v = c;
  const double length = v.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return -1.0;
  v /= length;
  // An orthonormal pair (u, w) normal to v: u from the axis v is least aligned with.
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(v(i)) < std::abs(v(k))) k = i;
  const Eigen::Vector3d u = v.cross(Eigen::Vector3d::Unit(k)).normalized(), w = v.cross(u);
  const Eigen::Matrix3d dev = (Eigen::Matrix3d() << dx, s[5], s[4], s[5], dy, s[3], s[4], s[3], dz).finished();
  const Eigen::Vector3d du = dev * u, dw = dev * w;
  const double d = std::hypot(0.5 * (u.dot(du) - w.dot(dw)), u.dot(dw));
  return 0.5 * (1.5 * std::abs(l) + d);
}
}  // namespace

double tresca_shear(const Voigt& s) { return stress_invariants(s).tresca; }

StressInvariants stress_invariants(const Voigt& s) {
  // Tresca from the deviator's invariants (Lode's angle; Jaeger, Cook & Zimmerman, Fundamentals
  // of Rock Mechanics, 4th ed., 2.13): s1 - s3 = 2 sqrt(J2) sin(theta + pi/3), theta = acos(r) / 3,
  // r = (3 sqrt 3 / 2) J3 / J2^(3/2). Where two principal stresses nearly coincide (|r| near 1)
  // acos amplifies the rounding of r by 1 / sqrt(1 - r^2); there the pair is split by a 2 x 2
  // projection (tresca_near_double_root), so the result is within a few eps |sigma| of the
  // eigenvalues everywhere (tests/test_voigt_stress.cpp).
  StressInvariants m;
  const double p = hydrostatic(s);
  m.hydrostatic = p;
  const double dx = s[0] - p, dy = s[1] - p, dz = s[2] - p;
  const double j2 = 0.5 * (dx * dx + dy * dy + dz * dz) + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  if (j2 == 0.0) return m;
  const double root = std::sqrt(j2);
  m.sqrt_j2 = root;
  const double j3 = dx * (dy * dz - s[3] * s[3]) - s[5] * (s[5] * dz - s[3] * s[4]) + s[4] * (s[5] * s[3] - dy * s[4]);
  const double r = 1.5 * std::sqrt(3.0) * j3 / (j2 * root);
  if (1.0 - r * r > 0.01) {
    m.tresca = root * std::sin(std::acos(r) / 3.0 + std::numbers::pi / 3.0);
    return m;
  }
  // Within ~6 degrees of a repeated root (or not finite).
  const double tau = std::isfinite(r) ? tresca_near_double_root(dx, dy, dz, s, j2, r) : -1.0;
  if (tau >= 0.0) {
    m.tresca = tau;
  } else {
    const Eigen::Vector3d e = principal_stresses(s);
    m.tresca = 0.5 * (e(2) - e(0));
  }
  return m;
}

}  // namespace dc
