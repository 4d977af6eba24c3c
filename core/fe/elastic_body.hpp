#pragma once
// The elastic body: stiffness K assembled from tet10 elements, factorised once (CHOLMOD) for
// the run. The body is free: its six rigid modes are its rigid motion, not springs. A load F
// deforms it by u = P' Ks^-1 P F (inertia relief): P F = F - M R (R'MR)^-1 R'F balances the
// load's resultant by rigid-body inertia forces, Ks is K with six supports of a statically
// determinate set (reactionless under a balanced load), and P' removes the rigid motion so
// that R'M u = 0 (displacements relative to the body's mean rigid motion).
#include <memory>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "body_mesh.hpp"
#include "elastic_stiffness.hpp"
#include "tet10.hpp"

namespace dc::fe {

class ElasticBody {
 public:
  /// materials[region] for every element's region; throws InputError("fe_body") when a
  /// region has no material or the body is not one connected solid.
  ElasticBody(BodyMesh mesh, std::vector<BodyMaterial> materials);
  ~ElasticBody();
  ElasticBody(const ElasticBody&) = delete;
  ElasticBody& operator=(const ElasticBody&) = delete;

  const BodyMesh& mesh() const { return mesh_; }
  std::size_t dofs() const { return mesh_.dofs(); }
  double mass() const { return mass_; }
  const Eigen::Vector3d& centre_of_mass() const { return centre_; }
  double factorisation_seconds() const { return factor_seconds_; }
  const Eigen::SparseMatrix<double>& stiffness() const { return K_; }

  /// u = P' Ks^-1 P F (see above): the deformation under a load of any resultant. Allocates
  /// nothing after the first call with the same sizes.
  void deform(const Eigen::VectorXd& F, Eigen::VectorXd& u) const;
  /// The same for many loads at once, one per column: one multi-column solve with the kept
  /// factor (BLAS 3 in the supernodes), much faster than a solve per column.
  void deform_columns(const Eigen::MatrixXd& F, Eigen::MatrixXd& u) const;
  /// The rigid modes (3n x 6: translations x, y, z, rotations about x, y, z at the centre of mass).
  const Eigen::MatrixXd& rigid_modes() const { return R_; }
  /// The pieces of deform() for programs that keep the equilibrium as sparse equalities
  /// (nlp/finite/saddle_form.*): Ks (lower half), the six held dofs, M R and R'M R.
  const Eigen::SparseMatrix<double>& supported_stiffness() const { return Ks_; }
  const std::vector<int>& supports() const { return supports_; }
  const Eigen::MatrixXd& mass_rigid_modes() const { return MR_; }
  const Eigen::Matrix<double, 6, 6>& rigid_mass() const { return RMR_; }
  /// Element e's node coordinates and stiffness (its region's material).
  TetNodes element_nodes(std::size_t e) const;
  const Stiffness& element_stiffness(std::size_t e) const { return materials_[mesh_.region[e]].C; }
  /// Stress (Voigt, Pa) at each element's centroid for a displacement field.
  std::vector<Eigen::Matrix<double, 6, 1>> element_stress(const Eigen::VectorXd& u) const;

 private:
  void assemble();
  void choose_supports();
  void factorise();

  BodyMesh mesh_;
  std::vector<BodyMaterial> materials_;
  Eigen::SparseMatrix<double> K_, Ks_;  // lower halves: free and supported stiffness
  Eigen::MatrixXd R_, MR_;     // rigid modes and the mass matrix times them
  Eigen::Matrix<double, 6, 6> RMR_, RMR_inv_;
  std::vector<int> supports_;  // six dofs held in Ks
  double mass_ = 0.0;
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  double factor_seconds_ = 0.0;
  struct Factor;
  std::unique_ptr<Factor> factor_;
  mutable Eigen::VectorXd work_;
};

}  // namespace dc::fe
