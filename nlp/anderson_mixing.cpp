#include "anderson_mixing.hpp"

#include <Eigen/Dense>

namespace dc {

void AndersonMixing::reset() {
  last_g_.clear();
  last_r_.clear();
  dg_.clear();
  dr_.clear();
}

std::vector<double> AndersonMixing::next(const std::vector<double>& x, const std::vector<double>& g) {
  const std::size_t n = x.size();
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = g[i] - x[i];
  if (last_r_.size() == n) {
    std::vector<double> dg(n), dr(n);
    for (std::size_t i = 0; i < n; ++i) {
      dg[i] = g[i] - last_g_[i];
      dr[i] = r[i] - last_r_[i];
    }
    dg_.push_back(std::move(dg));
    dr_.push_back(std::move(dr));
    if (static_cast<int>(dr_.size()) > memory_) {
      dg_.pop_front();
      dr_.pop_front();
    }
  }
  last_g_ = g;
  last_r_ = r;
  const int m = static_cast<int>(dr_.size());
  if (m == 0) return g;
  // gamma = argmin |r - dR gamma|, then x_next = g - dG gamma.
  Eigen::MatrixXd dR(n, m);
  for (int k = 0; k < m; ++k) dR.col(k) = Eigen::Map<const Eigen::VectorXd>(dr_[k].data(), n);
  const Eigen::Map<const Eigen::VectorXd> rv(r.data(), n);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(dR);
  qr.setThreshold(1e-10);
  if (qr.rank() < m) {  // the history no longer spans new directions: start it again
    dg_.clear();
    dr_.clear();
    return g;
  }
  const Eigen::VectorXd gamma = qr.solve(rv);
  std::vector<double> next(g);
  for (int k = 0; k < m; ++k)
    for (std::size_t i = 0; i < n; ++i) next[i] -= gamma[k] * dg_[k][i];
  return next;
}

}  // namespace dc
