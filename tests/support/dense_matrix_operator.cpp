#include "dense_matrix_operator.hpp"

#include <random>
#include <stdexcept>
#include <utility>

namespace dc::test {

DenseMatrixOperator::DenseMatrixOperator(Eigen::MatrixXd matrix) : matrix_(std::move(matrix)) {}

std::size_t DenseMatrixOperator::rows() const { return static_cast<std::size_t>(matrix_.rows()); }
std::size_t DenseMatrixOperator::cols() const { return static_cast<std::size_t>(matrix_.cols()); }

void DenseMatrixOperator::apply(const double* x, double* y) const {
  ++apply_count_;
  Eigen::Map<Eigen::VectorXd>(y, matrix_.rows()) =
      matrix_ * Eigen::Map<const Eigen::VectorXd>(x, matrix_.cols());
}

double DenseMatrixOperator::diagonal(std::size_t i) const {
  const auto k = static_cast<Eigen::Index>(i);
  return matrix_(k, k);
}

Eigen::MatrixXd DenseMatrixOperator::to_dense(std::size_t max_entries) const {
  if (rows() * cols() > max_entries) throw std::length_error("DenseMatrixOperator::to_dense: too large");
  return matrix_;
}

Eigen::MatrixXd random_spd(int n, unsigned seed, double shift) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd b(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) b(i, j) = uniform(rng);
  Eigen::MatrixXd a = b * b.transpose() / n;
  a.diagonal().array() += shift;
  return 0.5 * (a + a.transpose());
}

}  // namespace dc::test
