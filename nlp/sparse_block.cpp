#include "sparse_block.hpp"

#include <stdexcept>

namespace dc {
namespace {

/// diag(Q, H) over (x, y).
class BlockDiagonal final : public LinearOperator {
 public:
  BlockDiagonal(const LinearOperator& q, const Eigen::SparseMatrix<double>& h_lower)
      : q_(q), h_(h_lower.selfadjointView<Eigen::Lower>()), n_(q.rows()) {}
  std::size_t rows() const override { return n_ + static_cast<std::size_t>(h_.rows()); }
  std::size_t cols() const override { return rows(); }
  void apply(const double* x, double* y) const override {
    q_.apply(x, y);
    const auto m = h_.rows();
    Eigen::Map<Eigen::VectorXd>(y + n_, m) = h_ * Eigen::Map<const Eigen::VectorXd>(x + n_, m);
  }
  double diagonal(std::size_t i) const override {
    const auto k = static_cast<Eigen::Index>(i - n_);
    return i < n_ ? q_.diagonal(i) : h_.coeff(k, k);
  }
  Eigen::MatrixXd to_dense(std::size_t max_entries) const override {
    const std::size_t n = rows();
    if (n * n > max_entries) throw std::length_error("sparse block: too large for a dense matrix");
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    const auto nq = static_cast<Eigen::Index>(n_);
    m.topLeftCorner(nq, nq) = q_.to_dense(max_entries);
    m.bottomRightCorner(h_.rows(), h_.cols()) = Eigen::MatrixXd(h_);
    return m;
  }
  std::string kind() const override { return q_.kind() + "+sparse"; }

 private:
  const LinearOperator& q_;
  Eigen::SparseMatrix<double> h_;
  std::size_t n_;
};

}  // namespace

FlatProgram::FlatProgram(const QuadraticProgram& qp) {
  const SparseBlock& b = *qp.block;
  const std::size_t n = qp.c.size(), nb = static_cast<std::size_t>(b.n);
  op_ = std::make_unique<BlockDiagonal>(*qp.Q, b.hessian);
  program.Q = op_.get();
  program.c = qp.c;
  program.c.resize(n + nb, 0.0);
  const auto extend = [&](std::vector<double> v, double fill) {
    if (v.empty()) v.assign(n, fill);
    v.resize(n + nb, fill);
    return v;
  };
  program.lower = extend(qp.lower, -kInf);
  program.upper = extend(qp.upper, kInf);
  if (!qp.x0.empty()) program.x0 = extend(qp.x0, 0.0);
  program.disks = qp.disks;
  program.equalities = qp.equalities;
  for (auto& eq : program.equalities) eq.a.resize(n + nb, 0.0);
  const Eigen::MatrixXd rows(b.rows);
  for (Eigen::Index r = 0; r < rows.rows(); ++r) {
    LinearEquality eq;
    eq.a.resize(n + nb);
    for (Eigen::Index c = 0; c < rows.cols(); ++c) eq.a[static_cast<std::size_t>(c)] = rows(r, c);
    program.equalities.push_back(std::move(eq));
  }
  n_ = n;
  n_eq_ = qp.equalities.size();
}

SolveOutcome FlatProgram::split(SolveOutcome flat) const {
  SolveOutcome out = std::move(flat);
  if (out.x.size() > n_) {
    out.block_x.assign(out.x.begin() + static_cast<std::ptrdiff_t>(n_), out.x.end());
    out.x.resize(n_);
  }
  if (out.equality_multipliers.size() > n_eq_) out.equality_multipliers.resize(n_eq_);
  return out;
}

}  // namespace dc
