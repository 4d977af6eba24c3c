#pragma once
// The quadratic tetrahedron (10 nodes) with straight edges: vertices 0-3, then the mid-edge
// nodes of (0,1), (1,2), (0,2), (0,3), (1,3), (2,3). Straight edges make the map affine, so
// the rules below integrate the stiffness and the rigid-mode loads exactly.
#include <array>

#include <Eigen/Dense>

#include "elastic_stiffness.hpp"

namespace dc::fe {

inline constexpr int kTetEdges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};

using TetNodes = Eigen::Matrix<double, 3, 10>;  ///< node coordinates, one column per node
using Tet10Matrix = Eigen::Matrix<double, 30, 30>;
using Tet10Vector = Eigen::Matrix<double, 30, 1>;

/// Signed volume of the vertex tetrahedron (positive for the right-handed ordering).
double tet_volume(const TetNodes& x);
/// Shape functions at barycentric coordinates L (L0..L3, summing to 1).
Eigen::Matrix<double, 10, 1> tet10_shape(const Eigen::Vector4d& L);
/// Strain-displacement matrix (Voigt, engineering shears) at L; u ordered node by node (x, y, z).
Eigen::Matrix<double, 6, 30> tet10_strain(const TetNodes& x, const Eigen::Vector4d& L);
/// The 4-point rule (degree 2) of the stiffness: strain-displacement matrix and weight (V/4) at
/// each point. The strains of the affine element are linear, so the rule is exact for B'CB.
struct Tet10StrainPoint {
  Eigen::Matrix<double, 6, 30> B;
  double weight = 0.0;
};
std::array<Tet10StrainPoint, 4> tet10_strain_points(const TetNodes& x);
/// Element stiffness int B'CB dV (the 4-point rule, exact for the affine element).
Tet10Matrix tet10_stiffness(const TetNodes& x, const Stiffness& C);
/// int rho N_i r_m dV for the six rigid modes r_m about `centre` (translations x, y, z, then
/// rotations about x, y, z): the mass matrix times the rigid modes (degree-3 rule, exact).
Eigen::Matrix<double, 30, 6> tet10_rigid_mode_loads(const TetNodes& x, double density,
                                                    const Eigen::Vector3d& centre);
/// The six rigid modes at a point.
Eigen::Matrix<double, 3, 6> rigid_modes_at(const Eigen::Vector3d& p, const Eigen::Vector3d& centre);

}  // namespace dc::fe
