#pragma once
// The condensed compliance of finite contact ((3.14) with inf over u done: K u = P't + F*):
// the grid sees C_halfspace t + B'K+B t / A, the body's part applied matrix-free (one pair of
// triangular solves with the kept factor per apply).
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "contact_face.hpp"
#include "elastic_body.hpp"
#include "linear_operator.hpp"

namespace dc {

/// The body's compliance on the grid for the traction components `components` (0 x, 1 y,
/// 2 z), stacked as the half-space operators stack them. The traction t = (tau_x, tau_y, p)
/// acts on the body (influence.hpp's convention, p > 0 pushing the body up), and the grid sees
/// the body's part of the relative displacement w = u+ - u-: the body's own mean displacement
/// (w_z > 0 opens the gap). Positive semi-definite (Betti).
class BodyCompliance final : public LinearOperator {
 public:
  BodyCompliance(const fe::ElasticBody& body, const fe::ContactFace& face, const Grid& grid,
                 std::vector<int> components);
  std::size_t rows() const override { return components_.size() * n_; }
  std::size_t cols() const override { return rows(); }
  void apply(const double* x, double* y) const override;
  /// Not known without one solve per element: 0 here, so the sum with the half-space
  /// reports the half-space's diagonal (a lower bound, used only for scaling).
  double diagonal(std::size_t) const override { return 0.0; }
  Eigen::MatrixXd to_dense(std::size_t max_entries) const override;
  std::string kind() const override { return "fe"; }
  /// The body's displacement under the tractions x (same layout as apply's input).
  void displacement(const double* x, Eigen::VectorXd& u) const;

 private:
  const fe::ElasticBody& body_;
  const fe::ContactFace& face_;
  std::size_t n_;
  std::vector<int> components_;
  mutable Eigen::VectorXd F_, u_;
};

/// A + B for two operators of the same size.
class SumOperator final : public LinearOperator {
 public:
  SumOperator(std::shared_ptr<const LinearOperator> a, std::shared_ptr<const LinearOperator> b);
  std::size_t rows() const override { return a_->rows(); }
  std::size_t cols() const override { return a_->cols(); }
  void apply(const double* x, double* y) const override;
  double diagonal(std::size_t i) const override { return a_->diagonal(i) + b_->diagonal(i); }
  Eigen::MatrixXd to_dense(std::size_t max_entries) const override {
    return a_->to_dense(max_entries) + b_->to_dense(max_entries);
  }
  std::string kind() const override { return a_->kind() + "+" + b_->kind(); }

 private:
  std::shared_ptr<const LinearOperator> a_, b_;
  mutable std::vector<double> work_;
};

}  // namespace dc
