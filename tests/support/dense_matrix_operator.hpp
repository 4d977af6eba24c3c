#pragma once
// A LinearOperator wrapping an explicit Eigen matrix: small test problems for the backends.
#include <cstddef>
#include <string>

#include <Eigen/Dense>

#include "linear_operator.hpp"

namespace dc::test {

class DenseMatrixOperator final : public LinearOperator {
 public:
  explicit DenseMatrixOperator(Eigen::MatrixXd matrix);
  std::size_t rows() const override;
  std::size_t cols() const override;
  void apply(const double* x, double* y) const override;
  double diagonal(std::size_t i) const override;
  Eigen::MatrixXd to_dense(std::size_t max_entries = 4096u * 4096u) const override;
  std::string kind() const override { return "dense"; }
  using LinearOperator::apply;

  const Eigen::MatrixXd& matrix() const { return matrix_; }
  /// How many times apply() ran (the backends' operator cost).
  std::size_t apply_count() const { return apply_count_; }

 private:
  Eigen::MatrixXd matrix_;
  mutable std::size_t apply_count_ = 0;
};

/// A random symmetric positive definite n x n matrix with unit-order diagonal
/// (B B^T / n + shift I, B uniform in [-1, 1]); deterministic for a given seed.
Eigen::MatrixXd random_spd(int n, unsigned seed, double shift = 0.1);

}  // namespace dc::test
