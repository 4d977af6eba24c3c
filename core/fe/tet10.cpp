#include "tet10.hpp"

namespace dc::fe {

namespace {

/// Gradients of the barycentric coordinates (rows: L0..L3), constant on the affine element.
Eigen::Matrix<double, 4, 3> barycentric_gradients(const TetNodes& x) {
  Eigen::Matrix4d A;
  for (int i = 0; i < 4; ++i) {
    A(0, i) = 1.0;
    A.block<3, 1>(1, i) = x.col(i);
  }
  // [1; x] = A L  =>  L = A^{-1} [1; x]: dL/dx = columns 1..3 of A^{-1}.
  const Eigen::Matrix4d Ainv = A.inverse();
  return Ainv.block<4, 3>(0, 1);
}

}  // namespace

double tet_volume(const TetNodes& x) {
  const Eigen::Vector3d a = x.col(1) - x.col(0), b = x.col(2) - x.col(0), c = x.col(3) - x.col(0);
  return a.dot(b.cross(c)) / 6.0;
}

Eigen::Matrix<double, 10, 1> tet10_shape(const Eigen::Vector4d& L) {
  Eigen::Matrix<double, 10, 1> N;
  for (int i = 0; i < 4; ++i) N(i) = L(i) * (2.0 * L(i) - 1.0);
  for (int e = 0; e < 6; ++e) N(4 + e) = 4.0 * L(kTetEdges[e][0]) * L(kTetEdges[e][1]);
  return N;
}

Eigen::Matrix<double, 6, 30> tet10_strain(const TetNodes& x, const Eigen::Vector4d& L) {
  const Eigen::Matrix<double, 4, 3> dL = barycentric_gradients(x);
  Eigen::Matrix<double, 10, 3> dN;
  for (int i = 0; i < 4; ++i) dN.row(i) = (4.0 * L(i) - 1.0) * dL.row(i);
  for (int e = 0; e < 6; ++e) {
    const int a = kTetEdges[e][0], b = kTetEdges[e][1];
    dN.row(4 + e) = 4.0 * (L(a) * dL.row(b) + L(b) * dL.row(a));
  }
  Eigen::Matrix<double, 6, 30> B = Eigen::Matrix<double, 6, 30>::Zero();
  for (int n = 0; n < 10; ++n) {
    const double gx = dN(n, 0), gy = dN(n, 1), gz = dN(n, 2);
    const int c = 3 * n;
    B(0, c) = gx;
    B(1, c + 1) = gy;
    B(2, c + 2) = gz;
    B(3, c + 1) = gz;  // gamma_yz
    B(3, c + 2) = gy;
    B(4, c) = gz;      // gamma_xz
    B(4, c + 2) = gx;
    B(5, c) = gy;      // gamma_xy
    B(5, c + 1) = gx;
  }
  return B;
}

std::array<Tet10StrainPoint, 4> tet10_strain_points(const TetNodes& x) {
  // Degree-2 rule: 4 points at (a, b, b, b) and permutations, weights V/4.
  const double a = 0.5854101966249685, b = 0.1381966011250105;
  const double V = tet_volume(x);
  std::array<Tet10StrainPoint, 4> points;
  for (int q = 0; q < 4; ++q) {
    Eigen::Vector4d L = Eigen::Vector4d::Constant(b);
    L(q) = a;
    points[q].B = tet10_strain(x, L);
    points[q].weight = 0.25 * V;
  }
  return points;
}

Tet10Matrix tet10_stiffness(const TetNodes& x, const Stiffness& C) {
  Tet10Matrix K = Tet10Matrix::Zero();
  for (const auto& point : tet10_strain_points(x)) K.noalias() += point.weight * point.B.transpose() * C * point.B;
  return K;
}

Eigen::Matrix<double, 3, 6> rigid_modes_at(const Eigen::Vector3d& p, const Eigen::Vector3d& centre) {
  const Eigen::Vector3d r = p - centre;
  Eigen::Matrix<double, 3, 6> R = Eigen::Matrix<double, 3, 6>::Zero();
  R.block<3, 3>(0, 0).setIdentity();
  // omega x r for omega = e_x, e_y, e_z.
  R.col(3) << 0.0, -r.z(), r.y();
  R.col(4) << r.z(), 0.0, -r.x();
  R.col(5) << -r.y(), r.x(), 0.0;
  return R;
}

Eigen::Matrix<double, 30, 6> tet10_rigid_mode_loads(const TetNodes& x, double density,
                                                    const Eigen::Vector3d& centre) {
  // Degree-3 rule: the centroid with weight -4/5 V, (1/2, 1/6, 1/6, 1/6) and permutations 9/20 V.
  const double V = tet_volume(x);
  Eigen::Matrix<double, 30, 6> out = Eigen::Matrix<double, 30, 6>::Zero();
  auto add_point = [&](const Eigen::Vector4d& L, double w) {
    const Eigen::Matrix<double, 10, 1> N = tet10_shape(L);
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) p += L(i) * x.col(i);
    const Eigen::Matrix<double, 3, 6> R = rigid_modes_at(p, centre);
    for (int n = 0; n < 10; ++n) out.block<3, 6>(3 * n, 0) += (w * density * N(n)) * R;
  };
  add_point(Eigen::Vector4d::Constant(0.25), -0.8 * V);
  for (int q = 0; q < 4; ++q) {
    Eigen::Vector4d L = Eigen::Vector4d::Constant(1.0 / 6.0);
    L(q) = 0.5;
    add_point(L, 0.45 * V);
  }
  return out;
}

}  // namespace dc::fe
