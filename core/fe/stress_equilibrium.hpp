#pragma once
// The body's equilibrium written in stresses: the stiffness K = sum_q w_q B_q' C B_q of the
// 4-point rule (exact for tet10) is K = Gt H^-1 Gt' with one weighted stress
// s_q = sqrt(w_q) sigma_q (Voigt, 6 values) at every quadrature point, Gt = [sqrt(w_q) B_q']
// (the nodal forces of the stresses) and H the block-diagonal complementary-energy Hessian
// H_q = C^-1 of the point's element (weighting by sqrt(w_q) keeps every block of the same
// order, however small the element). The body's complementary energy under balanced nodal
// forces F is then
//     1/2 F'K+F = min { 1/2 s'H s : Gt s = F },
// whose KKT matrix [[H, Gt'], [Gt, 0]] is quasi-definite: H's 6 x 6 blocks pivot first and
// leave -K, so a sparse LDL' needs no 2 x 2 pivots (the sparse saddle form, nlp/finite/).
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "elastic_body.hpp"

namespace dc::fe {

struct StressEquilibrium {
  /// dofs x (6 x points): column 6 q + k is the nodal force of a unit weighted stress component k at point q.
  Eigen::SparseMatrix<double> forces;
  /// H_q = C_e^-1 for each quadrature point q (4 per element, element by element).
  std::vector<Eigen::Matrix<double, 6, 6>> compliance;
  /// sqrt(w_q): the stress at point q is s_q / sqrt(w_q).
  std::vector<double> root_weight;
  std::size_t stresses() const { return 6 * compliance.size(); }
};

StressEquilibrium stress_equilibrium(const ElasticBody& body);

}  // namespace dc::fe
