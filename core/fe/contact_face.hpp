#pragma once
// The body's contact face against the half-space grid. Tractions are piecewise constant on
// the grid (per unit area of the plane); B (nodes x grid elements) holds int_{element} N_i dA
// over the face's projection, so nodal forces are F = B t and the grid sees the mean
// displacement over each element, w = B'u / A (any mesh: faces need not match the grid).
// The initial gap is the face's height over each element centre above the body's lowest point.
#include <vector>

#include <Eigen/Sparse>

#include "body_mesh.hpp"
#include "grid.hpp"

namespace dc::fe {

class ContactFace {
 public:
  /// Faces of the body's boundary that look down (outward normal z < 0); `samples` points per
  /// side of each grid element integrate the shape functions. Throws InputError("fe_body")
  /// when no such face lies over the grid.
  ContactFace(const BodyMesh& mesh, const Grid& grid, int samples = 4);

  /// Heights above the lowest point of the face (m) at the grid element centres; +infinity
  /// where no face lies over the centre (cannot touch).
  const std::vector<double>& heights() const { return heights_; }
  double lowest_z() const { return lowest_z_; }
  /// The mean edge length (m) of the face's triangle over each grid element centre (0 where no
  /// face lies over it): how finely the body resolves the contact there.
  const std::vector<double>& face_element_sizes() const { return face_sizes_; }
  /// F(3 i + component) += scale sum_k B_ik t_k for the traction component t (one value per element).
  void add_forces(const double* traction, int component, double scale, Eigen::VectorXd& F) const;
  /// w_k = (B'u_component)_k / A: the mean displacement component over each grid element.
  void mean_displacement(const Eigen::VectorXd& u, int component, double* w) const;
  /// B' (grid elements x nodes): row k holds int_{element k} N_i dA.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& transfer() const { return Bt_; }
  std::size_t face_triangles() const { return n_triangles_; }

 private:
  Grid grid_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> Bt_;  // grid elements x nodes
  std::vector<double> heights_;
  std::vector<double> face_sizes_;
  double lowest_z_ = 0.0;
  std::size_t n_triangles_ = 0;
};

}  // namespace dc::fe
