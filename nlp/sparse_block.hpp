#pragma once
// Further unknowns of a quadratic program kept as a sparse block (the finite body's sparse
// saddle form, nlp/finite/saddle_form.hpp): after the program's own x come y (block.n of them),
// the objective gains 1/2 y'H y, and the sparse rows J (x, y) = 0 hold as equalities.
#include <cstddef>
#include <memory>

#include <Eigen/Sparse>

#include "quadratic_program.hpp"

namespace dc {

struct SparseBlock {
  int n = 0;                                           ///< extra unknowns y
  Eigen::SparseMatrix<double> hessian;                 ///< H (n x n), lower triangle
  Eigen::SparseMatrix<double, Eigen::RowMajor> rows;   ///< J (m x (qp.n + n)), right-hand side 0
};

/// A program with a sparse block as a plain one over (x, y) for backends that take dense rows
/// (NLopt): Q and H block-diagonal, the block's rows as dense equalities after the program's.
class FlatProgram {
 public:
  explicit FlatProgram(const QuadraticProgram& qp);  // qp.block must be set
  QuadraticProgram program;
  /// The flat program's outcome as the original's: x and block_x apart, the block rows'
  /// multipliers dropped.
  SolveOutcome split(SolveOutcome flat) const;

 private:
  std::unique_ptr<LinearOperator> op_;
  std::size_t n_ = 0, n_eq_ = 0;
};

}  // namespace dc
