#pragma once
// s * A without copying A: the programs hand backends operators scaled to unit diagonal.
#include "linear_operator.hpp"

namespace dc {

class ScaledOperator final : public LinearOperator {
 public:
  ScaledOperator(const LinearOperator& op, double scale) : op_(op), scale_(scale) {}
  std::size_t rows() const override { return op_.rows(); }
  std::size_t cols() const override { return op_.cols(); }
  void apply(const double* x, double* y) const override {
    op_.apply(x, y);
    const std::size_t n = op_.rows();
    for (std::size_t i = 0; i < n; ++i) y[i] *= scale_;
  }
  double diagonal(std::size_t i) const override { return scale_ * op_.diagonal(i); }
  Eigen::MatrixXd to_dense(std::size_t max_entries) const override { return scale_ * op_.to_dense(max_entries); }
  std::string kind() const override { return op_.kind(); }

 private:
  const LinearOperator& op_;
  double scale_;
};

}  // namespace dc
