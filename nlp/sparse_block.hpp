#pragma once
// Further unknowns of a quadratic program kept as a sparse block (the finite body's sparse
// saddle form, nlp/finite/saddle_form.hpp): after the program's own x come y (block.n of them),
// the objective gains 1/2 y'H y, and the sparse rows J (x, y) = 0 hold as equalities.
#include <Eigen/Sparse>

namespace dc {

struct SparseBlock {
  int n = 0;                                           ///< extra unknowns y
  Eigen::SparseMatrix<double> hessian;                 ///< H (n x n), lower triangle
  Eigen::SparseMatrix<double, Eigen::RowMajor> rows;   ///< J (m x (qp.n + n)), right-hand side 0
};

}  // namespace dc
