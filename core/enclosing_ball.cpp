#include "enclosing_ball.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace dc {

double EnclosingBall::radius() const { return std::sqrt(std::max(value, 0.0)); }

double EnclosingBall::relative_gap() const { return scale > 0.0 ? (value - dual_value) / scale : 0.0; }

bool EnclosingBall::certified(double tol) const {
  return min_multiplier >= -tol && hull_residual <= tol * std::sqrt(scale) && relative_gap() <= tol;
}

namespace {

constexpr double kBallMinusInfinity = -std::numeric_limits<double>::infinity();

/// A support set's ball: the centre in the affine hull of the points S with equal power
/// distance t to each, and the barycentric coordinates mu of the centre.
struct SupportBall {
  Eigen::VectorXd centre;
  double value = kBallMinusInfinity;
  std::vector<double> mu;
};

class MoveToFront {
 public:
  MoveToFront(const Eigen::MatrixXd& points, const Eigen::VectorXd& weights, double scale)
      : p_(points), w_(weights), d_(static_cast<int>(points.rows())), n_(static_cast<int>(points.cols())),
        eps_(1e-13 * scale), order_(static_cast<std::size_t>(n_)) {
    std::iota(order_.begin(), order_.end(), 0);
    ball_.centre = Eigen::VectorXd::Zero(d_);
  }

  void run() {
    mtf(n_);
    // Gaertner's pivoting rounds: a point the rounding left outside is forced onto the
    // boundary and the recursion repeated, while the value grows (normally no round at all).
    for (int round = 0; round < 8 * (d_ + 2); ++round) {
      clean_support();
      const auto [pivot, e] = worst_point();
      if (e <= eps_) break;
      const double before = ball_.value;
      stack_.clear();
      if (!push(pivot)) break;
      mtf(n_);
      stack_.clear();
      move_to_front(pivot);
      if (!(ball_.value > before)) break;
    }
    clean_support();
  }

  const SupportBall& ball() const { return ball_; }
  const std::vector<int>& support() const { return support_; }

 private:
  double excess(int i) const {
    return (p_.col(i) - ball_.centre).squaredNorm() - w_(i) - ball_.value;
  }

  std::pair<int, double> worst_point() const {
    int worst = 0;
    double e = kBallMinusInfinity;
    for (int i = 0; i < n_; ++i)
      if (const double ei = excess(i); ei > e) {
        e = ei;
        worst = i;
      }
    return {worst, e};
  }

  void move_to_front(int point) {
    const auto it = std::find(order_.begin(), order_.end(), point);
    std::rotate(order_.begin(), it, it + 1);
  }

  /// The ball of the support set s (s[0] first); false when s is affinely dependent (to a
  /// relative 1e-10) or larger than d + 1.
  bool ball_through(const std::vector<int>& s, SupportBall& out) const {
    const int k = static_cast<int>(s.size()) - 1;
    const Eigen::VectorXd q0 = p_.col(s[0]);
    if (k == 0) {
      out.centre = q0;
      out.value = -w_(s[0]);
      out.mu.assign(1, 1.0);
      return true;
    }
    if (k > d_) return false;
    // V = [p_s1 - q0, ..., p_sk - q0] = Q R by modified Gram-Schmidt with one
    // re-orthogonalisation; a column within 1e-10 of the others' span is dependent.
    Eigen::MatrixXd q(d_, k), r = Eigen::MatrixXd::Zero(k, k);
    Eigen::VectorXd b(k);
    for (int l = 0; l < k; ++l) {
      const Eigen::VectorXd v_l = p_.col(s[static_cast<std::size_t>(l + 1)]) - q0;
      Eigen::VectorXd v = v_l;
      for (int pass = 0; pass < 2; ++pass)
        for (int m = 0; m < l; ++m) {
          const double c = q.col(m).dot(v);
          r(m, l) += c;
          v -= c * q.col(m);
        }
      const double norm = v.norm();
      if (!(norm > 1e-10 * v_l.norm())) return false;
      r(l, l) = norm;
      q.col(l) = v / norm;
      // Equal power distance to q0 and p_sl: 2 v_l.(c - q0) = |v_l|^2 - w_sl + w_s0.
      b(l) = 0.5 * (v_l.squaredNorm() - w_(s[static_cast<std::size_t>(l + 1)]) + w_(s[0]));
    }
    // V'V alpha = b: R'R alpha = b, y = R^-T b, c - q0 = V alpha = Q y.
    const Eigen::VectorXd y = r.transpose().triangularView<Eigen::Lower>().solve(b);
    const Eigen::VectorXd alpha = r.triangularView<Eigen::Upper>().solve(y);
    if (!alpha.allFinite()) return false;
    out.centre = q0 + q * y;
    out.value = y.squaredNorm() - w_(s[0]);
    out.mu.resize(static_cast<std::size_t>(k + 1));
    out.mu[0] = 1.0 - alpha.sum();
    for (int l = 0; l < k; ++l) out.mu[static_cast<std::size_t>(l + 1)] = alpha(l);
    return true;
  }

  bool push(int i) {
    std::vector<int> s = stack_;
    s.push_back(i);
    SupportBall b;
    if (!ball_through(s, b)) return false;
    ball_ = std::move(b);
    support_ = s;
    stack_.push_back(i);
    return true;
  }

  /// Welzl's recursion over the first `end` points of the order, the stack on the boundary.
  void mtf(int end) {
    if (static_cast<int>(stack_.size()) == d_ + 1) return;
    for (int k = 0; k < end; ++k) {
      const int i = order_[static_cast<std::size_t>(k)];
      if (excess(i) > eps_ && push(i)) {
        mtf(k);
        stack_.pop_back();
        std::rotate(order_.begin(), order_.begin() + k, order_.begin() + k + 1);
      }
    }
  }

  /// A support point with a negative multiplier (the rounding's doing) is dropped and the ball
  /// of the others taken: its value is no larger, and the pivoting rounds restore the rest.
  void clean_support() {
    for (int pass = 0; pass <= d_ && support_.size() > 1; ++pass) {
      const auto m = std::min_element(ball_.mu.begin(), ball_.mu.end());
      if (*m >= -1e-12) return;
      std::vector<int> s = support_;
      s.erase(s.begin() + (m - ball_.mu.begin()));
      SupportBall b;
      if (!ball_through(s, b)) return;
      ball_ = std::move(b);
      support_ = std::move(s);
    }
  }

  const Eigen::MatrixXd& p_;
  const Eigen::VectorXd& w_;
  int d_, n_;
  double eps_;
  std::vector<int> order_, stack_, support_;
  SupportBall ball_;
};

}  // namespace

EnclosingBall minimax_power_distance(const Eigen::MatrixXd& points, const Eigen::VectorXd& weights) {
  const int n = static_cast<int>(points.cols());
  if (n < 1 || points.rows() < 1) throw std::invalid_argument("enclosing ball: no points");
  if (weights.size() != n) throw std::invalid_argument("enclosing ball: one weight per point needed");
  if (!points.allFinite() || !weights.allFinite()) throw std::invalid_argument("enclosing ball: non-finite input");

  EnclosingBall out;
  double spread = 0.0;
  for (int i = 0; i < n; ++i) spread = std::max(spread, (points.col(i) - points.col(0)).squaredNorm());
  out.scale = spread + (weights.maxCoeff() - weights.minCoeff());

  MoveToFront solver(points, weights, out.scale);
  solver.run();
  out.centre = solver.ball().centre;
  out.support = solver.support();
  out.multipliers = solver.ball().mu;

  // The certificate, from the returned centre and multipliers alone.
  out.value = kBallMinusInfinity;
  for (int i = 0; i < n; ++i)
    out.value = std::max(out.value, (points.col(i) - out.centre).squaredNorm() - weights(i));
  out.min_multiplier = *std::min_element(out.multipliers.begin(), out.multipliers.end());
  std::vector<double> mu(out.multipliers.size());
  double total = 0.0;
  for (std::size_t k = 0; k < mu.size(); ++k) total += (mu[k] = std::max(out.multipliers[k], 0.0));
  Eigen::VectorXd c_mu = Eigen::VectorXd::Zero(points.rows());
  if (total > 0.0) {
    for (std::size_t k = 0; k < mu.size(); ++k) c_mu += (mu[k] /= total) * points.col(out.support[k]);
    out.dual_value = 0.0;
    for (std::size_t k = 0; k < mu.size(); ++k)
      out.dual_value += mu[k] * ((c_mu - points.col(out.support[k])).squaredNorm() - weights(out.support[k]));
    out.hull_residual = (out.centre - c_mu).norm();
  } else {
    out.dual_value = kBallMinusInfinity;
    out.hull_residual = std::numeric_limits<double>::infinity();
  }
  return out;
}

EnclosingBall smallest_enclosing_ball(const Eigen::MatrixXd& points) {
  return minimax_power_distance(points, Eigen::VectorXd::Zero(points.cols()));
}

}  // namespace dc
