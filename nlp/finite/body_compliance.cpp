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
  // Columns in blocks, each block one multi-column solve with the kept factor (BLAS 3): at 16k
  // dofs and 1152 columns 1.6 s against 8.6 s for one apply per column (blocks of 16 or 256:
  // 1.9 s). Unit tractions on grid elements the face does not reach load nothing: their
  // columns stay 0.
  constexpr std::size_t kBlock = 64;  // 64 columns of a 50k-dof body: 26 MB per block
  const auto dofs = static_cast<Eigen::Index>(body_.dofs());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  std::vector<double> e(n, 0.0);
  Eigen::VectorXd column(dofs);
  Eigen::MatrixXd F, U;
  std::vector<std::size_t> loaded;
  for (std::size_t j0 = 0; j0 < n;) {
    loaded.clear();
    F.setZero(dofs, static_cast<Eigen::Index>(kBlock));
    for (; j0 < n && loaded.size() < kBlock; ++j0) {
      const std::size_t c = j0 / n_, k = j0 % n_;
      e[k] = 1.0;
      column.setZero();
      face_.add_forces(e.data(), components_[c], 1.0, column);
      e[k] = 0.0;
      if (column.isZero(0.0)) continue;
      F.col(static_cast<Eigen::Index>(loaded.size())) = column;
      loaded.push_back(j0);
    }
    if (loaded.empty()) continue;
    body_.deform_columns(F.leftCols(static_cast<Eigen::Index>(loaded.size())), U);
    for (std::size_t l = 0; l < loaded.size(); ++l) {
      column = U.col(static_cast<Eigen::Index>(l));
      double* out = M.col(static_cast<Eigen::Index>(loaded[l])).data();
      for (std::size_t c = 0; c < components_.size(); ++c) face_.mean_displacement(column, components_[c], out + c * n_);
    }
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
