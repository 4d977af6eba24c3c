#include "anderson_mixing.hpp"

namespace dc {

void AndersonMixing::reset() {
  last_g_.clear();
  last_r_.clear();
  start_ = count_ = 0;
}

std::vector<double> AndersonMixing::next(const std::vector<double>& x, const std::vector<double>& g) {
  std::vector<double> out;
  next(x, g, out);
  return out;
}

void AndersonMixing::next(const std::vector<double>& x, const std::vector<double>& g, std::vector<double>& out) {
  const std::size_t n = x.size();
  r_.resize(n);
  for (std::size_t i = 0; i < n; ++i) r_[i] = g[i] - x[i];
  if (last_r_.size() == n) {
    if (dg_.size() != static_cast<std::size_t>(memory_)) {
      dg_.resize(memory_);
      dr_.resize(memory_);
    }
    // The newest difference goes after the others; beyond memory_ the oldest is dropped.
    int slot = (start_ + count_) % memory_;
    if (count_ == memory_) start_ = (start_ + 1) % memory_;
    else ++count_;
    std::vector<double>&dg = dg_[slot], &dr = dr_[slot];
    dg.resize(n);
    dr.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      dg[i] = g[i] - last_g_[i];
      dr[i] = r_[i] - last_r_[i];
    }
  }
  last_g_.assign(g.begin(), g.end());
  last_r_.assign(r_.begin(), r_.end());
  const int m = count_;
  if (m == 0 || !least_squares(n, m)) {
    if (m > 0) start_ = count_ = 0;  // the history no longer spans new directions: start it again
    out.assign(g.begin(), g.end());
    return;
  }
  // x_next = g - dG gamma.
  next_.assign(g.begin(), g.end());
  for (int k = 0; k < m; ++k) {
    const std::vector<double>& dg = dg_[(start_ + k) % memory_];
    for (std::size_t i = 0; i < n; ++i) next_[i] -= gamma_[k] * dg[i];
  }
  out.assign(next_.begin(), next_.end());
}

bool AndersonMixing::least_squares(std::size_t n, int m) {
  const auto rows = static_cast<Eigen::Index>(n);
  if (dR_.size() != static_cast<std::size_t>(memory_) || (dR_[0].rows() != rows)) {
    dR_.assign(memory_, Eigen::MatrixXd());
    qr_.clear();
    for (int k = 1; k <= memory_; ++k) {
      dR_[k - 1].resize(rows, k);
      qr_.emplace_back(rows, k);
    }
    c_.resize(rows);
  }
  Eigen::MatrixXd& dR = dR_[m - 1];
  for (int k = 0; k < m; ++k) dR.col(k) = Eigen::Map<const Eigen::VectorXd>(dr_[(start_ + k) % memory_].data(), rows);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd>& qr = qr_[m - 1];
  qr.setThreshold(1e-10);
  qr.compute(dR);
  if (qr.rank() < m) return false;
  // qr.solve(r) without its temporary (ColPivHouseholderQR::_solve_impl, step by step): c = Q' r,
  // R c = c on the pivots, gamma = P c.
  c_ = Eigen::Map<const Eigen::VectorXd>(r_.data(), rows);
  const Eigen::Index pivots = qr.nonzeroPivots();
  gamma_.assign(m, 0.0);
  if (pivots == 0) return true;
  // c = Q' c: the reflectors H_0, ..., H_{pivots-1} in turn, each as Eigen's
  // applyHouseholderOnTheLeft on one column (whose outer-product temporary this avoids).
  const Eigen::MatrixXd& factors = qr.matrixQR();
  for (Eigen::Index k = 0; k < pivots; ++k) {
    const double tau = qr.hCoeffs()(k);
    const Eigen::Index length = rows - k;
    auto v = c_.tail(length);
    if (length == 1) {
      v(0) *= 1.0 - tau;
    } else if (tau != 0.0) {
      const auto essential = factors.col(k).tail(length - 1);
      double t = essential.dot(v.tail(length - 1));
      t += v(0);
      v(0) -= tau * t;
      v.tail(length - 1) -= (tau * essential) * t;
    }
  }
  qr.matrixQR().topLeftCorner(pivots, pivots).template triangularView<Eigen::Upper>().solveInPlace(c_.topRows(pivots));
  for (Eigen::Index i = 0; i < pivots; ++i) gamma_[qr.colsPermutation().indices().coeff(i)] = c_(i);
  return true;
}

}  // namespace dc
