#pragma once
// General anisotropic linear elasticity: the 6x6 Voigt stiffness (21 constants), with the
// isotropic and cubic shorthands. Voigt order: 11, 22, 33, 23, 13, 12 (engineering shears).
#include <array>
#include <string>

#include <Eigen/Dense>

namespace dc::fe {

using Stiffness = Eigen::Matrix<double, 6, 6>;

/// Isotropic stiffness from Young's modulus and Poisson's ratio (validated, naming `key`).
Stiffness isotropic_stiffness(double E, double nu, const std::string& key);
/// Cubic stiffness (axes along x, y, z) from C11, C12, C44.
Stiffness cubic_stiffness(double c11, double c12, double c44, const std::string& key);
/// The upper triangle row by row (C11 C12 ... C16 C22 ... C66): 21 values.
Stiffness anisotropic_stiffness(const std::array<double, 21>& upper, const std::string& key);
/// Throws InputError(key) unless the stiffness is symmetric positive definite (a stable material).
void check_stiffness(const Stiffness& C, const std::string& key);

/// One material of the body: stiffness and density (kg/m^3).
struct BodyMaterial {
  Stiffness C = Stiffness::Zero();
  double density = 0.0;
};

}  // namespace dc::fe
