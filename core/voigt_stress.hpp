#pragma once
// A stress tensor at one material point as 6 Voigt components, in the order of
// elastic_stiffness.hpp: xx, yy, zz, yz, xz, xy (tension positive, shears the tensor's own
// off-diagonal entries, not engineering strains); and the invariants the yield and fatigue
// criteria use (core/yield_criterion.hpp, core/dang_van.hpp).
//
// Deviatoric coordinates: the deviator s = sigma - (tr sigma / 3) I in an orthonormal basis
// (for the inner product s:t / 2) of the 5-D space of symmetric traceless tensors,
//   u1 = (2 s_zz - s_xx - s_yy) / (2 sqrt 3),  u2 = (s_xx - s_yy) / 2,
//   u3 = s_yz,  u4 = s_xz,  u5 = s_xy,
// so that |u|^2 = s:s / 2 = J2: the Euclidean norm of u is sqrt(J2), the von Mises-consistent
// norm in shear units (pure shear tau: |u| = tau; uniaxial Y: |u| = Y / sqrt 3). The 5-vector
// of the deviatoric-space fatigue criteria (Dang Van, Crossland), scaled to sqrt(J2).
#include <array>
#include <cmath>

#include <Eigen/Core>

namespace dc {

/// Voigt components, in order. The values index a Voigt array.
enum class VoigtComponent { xx = 0, yy = 1, zz = 2, yz = 3, xz = 4, xy = 5 };

using Voigt = std::array<double, 6>;

inline int index_of(VoigtComponent c) { return static_cast<int>(c); }

/// "xx", "yy", "zz", "yz", "xz", "xy".
const char* to_string(VoigtComponent c);

inline double trace(const Voigt& s) { return s[0] + s[1] + s[2]; }
inline double hydrostatic(const Voigt& s) { return trace(s) / 3.0; }

/// The symmetric 3x3 tensor.
Eigen::Matrix3d to_matrix(const Voigt& s);
/// The Voigt components of a (symmetrised) 3x3 tensor.
Voigt from_matrix(const Eigen::Matrix3d& m);

/// The deviator's 5 coordinates (header comment): |u| = sqrt(J2).
Eigen::Matrix<double, 5, 1> deviatoric_coordinates(const Voigt& s);
/// The traceless tensor with those coordinates (the inverse of deviatoric_coordinates on deviators).
Voigt from_deviatoric_coordinates(const Eigen::Matrix<double, 5, 1>& u);
/// The 5 x 6 matrix D with u = D s (deviatoric_coordinates as a linear map).
Eigen::Matrix<double, 5, 6> deviatoric_coordinate_map();

/// sqrt(J2) = sqrt(s:s / 2).
double sqrt_j2(const Voigt& s);
/// Tresca's shear: half the largest difference of principal stresses, (s1 - s3) / 2, from the
/// deviator's invariants: sqrt(J2) sin(theta + pi/3), Lode's angle theta = acos(r) / 3,
/// r = (3 sqrt 3 / 2) J3 / J2^(3/2); within 6 degrees of a repeated root (1 - r^2 <= 0.01) the
/// close pair is split on the plane normal to the isolated principal direction. Within 8 eps
/// |sigma| of the exact value.
double tresca_shear(const Voigt& s);
/// The measures of one tensor from one pass over its deviator: sigma_kk / 3, sqrt(J2) and
/// Tresca's shear (those of hydrostatic, sqrt_j2 and tresca_shear, to rounding).
struct StressInvariants {
  double hydrostatic = 0.0, sqrt_j2 = 0.0, tresca = 0.0;
};
StressInvariants stress_invariants(const Voigt& s);
/// Principal stresses, ascending: cyclic Jacobi rotations (backward stable, within 8 eps |sigma|).
Eigen::Vector3d principal_stresses(const Voigt& s);

}  // namespace dc
