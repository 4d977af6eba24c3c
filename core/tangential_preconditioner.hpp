#pragma once
// FFT preconditioner for the tangential program (4.8): an approximate inverse of the tangential
// compliance B22 on the grid, M^-1 r = F^-1 [ S(k)^-1 F(r) ], with S(k) the 2 x 2 symbol (1 x 1
// in 2-D) of the Cerruti kernels on a periodic box the size of the grid. As for the normal
// problem (normal_preconditioner.hpp; Vollebregt, J. Comput. Phys. 257, 2014), the kernels
// behave like 1 / |k| in wavenumber, so B22's condition number grows with the grid; dividing
// by the symbol removes that growth. The native tangential solver applies it on the face of
// the friction set it works on (stick elements, the tangents of slipping ones).
#include <vector>

#include "grid.hpp"
#include "linear_operator.hpp"
#include "padded_fft.hpp"

namespace dc {

class TangentialPreconditioner final : public LinearOperator {
 public:
  /// Built from the compliance's responses to unit tangential loads at the grid centre (one
  /// apply per component; any operator kind). `compliance` maps comps * N tractions (component
  /// blocks, x first) to as many displacements; comps = 1 in 2-D, 2 in 3-D.
  TangentialPreconditioner(const LinearOperator& compliance, const Grid& grid);

  using LinearOperator::apply;
  std::size_t rows() const override { return comps_ * n_; }
  std::size_t cols() const override { return comps_ * n_; }
  /// y = M^-1 x. Allocates nothing.
  void apply(const double* x, double* y) const override;
  double diagonal(std::size_t i) const override;  ///< kept (translation invariant)
  Eigen::MatrixXd to_dense(std::size_t max_entries) const override;
  std::string kind() const override { return "fft-preconditioner"; }

 private:
  std::size_t n_;
  int comps_;
  /// Per complex entry: the inverse symbol (xx, xy, yy), normalised by the box size.
  std::vector<double> ixx_, ixy_, iyy_;
  mutable PaddedFft fft_;
  double diagonal_[2] = {0.0, 0.0};  ///< per component: the same at every element
  mutable std::vector<double> spectrum_x_;  ///< the x component's spectrum while y is transformed
};

}  // namespace dc
