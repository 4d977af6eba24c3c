#include "body_compliance.hpp"

#include <stdexcept>

namespace dc {

BodyCompliance::BodyCompliance(const fe::ElasticBody& body, const fe::ContactFace& face, const Grid& grid,
                               std::vector<int> components)
    : body_(body), face_(face), n_(grid.size()), components_(std::move(components)) {}

void BodyCompliance::displacement(const double* x, Eigen::VectorXd& u) const {
  F_.setZero(static_cast<Eigen::Index>(body_.dofs()));
  for (std::size_t c = 0; c < components_.size(); ++c) {
    face_.add_forces(x + c * n_, components_[c], 1.0, F_);
  }
  body_.deform(F_, u);
}

void BodyCompliance::apply(const double* x, double* y) const {
  displacement(x, u_);
  for (std::size_t c = 0; c < components_.size(); ++c) face_.mean_displacement(u_, components_[c], y + c * n_);
}

Eigen::MatrixXd BodyCompliance::to_dense(std::size_t max_entries) const {
  const std::size_t n = rows();
  if (n * n > max_entries) throw std::length_error("body compliance: too large for a dense matrix");
  Eigen::MatrixXd M(n, n);
  std::vector<double> e(n, 0.0), col(n);
  for (std::size_t j = 0; j < n; ++j) {
    e[j] = 1.0;
    apply(e.data(), col.data());
    e[j] = 0.0;
    for (std::size_t i = 0; i < n; ++i) M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = col[i];
  }
  return 0.5 * (M + M.transpose());
}

SumOperator::SumOperator(std::shared_ptr<const LinearOperator> a, std::shared_ptr<const LinearOperator> b)
    : a_(std::move(a)), b_(std::move(b)) {
  if (a_->rows() != b_->rows() || a_->cols() != b_->cols()) throw std::invalid_argument("sum operator: sizes differ");
}

void SumOperator::apply(const double* x, double* y) const {
  work_.resize(rows());
  a_->apply(x, y);
  b_->apply(x, work_.data());
  for (std::size_t i = 0; i < rows(); ++i) y[i] += work_[i];
}

}  // namespace dc
