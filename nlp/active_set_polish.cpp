#include "active_set_polish.hpp"
#include "vector_ops.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include <Eigen/Dense>

namespace dc {
namespace {

using Vec = std::vector<double>;

/// The program's bounds and disk membership, with empty bounds expanded to +-infinity.
struct Sets {
  Vec lower, upper;
  std::vector<int> disk_of;  ///< per variable: index of its disk, or -1
  explicit Sets(const QuadraticProgram& qp) {
    const std::size_t n = qp.c.size();
    if (qp.lower.empty()) lower.assign(n, -kInf); else lower = qp.lower;
    if (qp.upper.empty()) upper.assign(n, kInf); else upper = qp.upper;
    disk_of.assign(n, -1);
    for (std::size_t d = 0; d < qp.disks.size(); ++d) {
      disk_of[static_cast<std::size_t>(qp.disks[d].ix)] = static_cast<int>(d);
      disk_of[static_cast<std::size_t>(qp.disks[d].iy)] = static_cast<int>(d);
    }
  }
};

/// h = Qx + c - A'lambda.
void reduced_gradient(const QuadraticProgram& qp, const Vec& x, const Vec& lambda, Vec& h) {
  h.resize(x.size());
  qp.gradient(x.data(), h.data());
  for (std::size_t k = 0; k < qp.equalities.size() && k < lambda.size(); ++k)
    for (std::size_t i = 0; i < x.size(); ++i) h[i] -= lambda[k] * qp.equalities[k].a[i];
}

/// Pi_D(w): bounds for box variables, the disk for disk pairs.
void project(const QuadraticProgram& qp, const Sets& sets, const Vec& w, Vec& y) {
  y.resize(w.size());
  for (std::size_t i = 0; i < w.size(); ++i)
    y[i] = sets.disk_of[i] >= 0 ? w[i] : std::clamp(w[i], sets.lower[i], sets.upper[i]);
  for (const auto& d : qp.disks) {
    y[d.ix] = w[d.ix];
    y[d.iy] = w[d.iy];
    project_onto_disk(y[d.ix], y[d.iy], d.radius);
  }
}

bool feasible(const QuadraticProgram& qp, const Sets& sets, const Vec& x) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) return false;
    if (sets.disk_of[i] < 0 && (x[i] < sets.lower[i] || x[i] > sets.upper[i])) return false;
  }
  for (const auto& d : qp.disks)
    if (std::hypot(x[d.ix], x[d.iy]) > d.radius * (1.0 + 1e-12)) return false;
  return true;
}

/// Conjugate gradients on Q restricted to the free variables (Q symmetric positive definite
/// there): Q_FF y = r, y zero off F. Stops at |residual| <= 1e-13 |r| or after `max_iter`.
int cg_on_face(const QuadraticProgram& qp, const std::vector<char>& free, const Vec& r, Vec& y, int max_iter) {
  const std::size_t n = r.size();
  y.assign(n, 0.0);
  Vec res(n), p(n), q(n);
  for (std::size_t i = 0; i < n; ++i) res[i] = free[i] ? r[i] : 0.0;
  p = res;
  double rr = dot(res, res);
  const double stop = 1e-26 * rr;
  int it = 0;
  for (; it < max_iter && rr > stop && rr > 0.0; ++it) {
    qp.Q->apply(p.data(), q.data());
    for (std::size_t i = 0; i < n; ++i)
      if (!free[i]) q[i] = 0.0;
    const double pq = dot(p, q);
    if (!(pq > 0.0)) break;
    const double alpha = rr / pq;
    for (std::size_t i = 0; i < n; ++i) {
      y[i] += alpha * p[i];
      res[i] -= alpha * q[i];
    }
    const double rr_new = dot(res, res);
    const double beta = rr_new / rr;
    rr = rr_new;
    for (std::size_t i = 0; i < n; ++i) p[i] = res[i] + beta * p[i];
  }
  return it;
}

}  // namespace

double kkt_residual(const QuadraticProgram& qp, const Vec& x, const Vec& lambda) {
  if (x.size() != qp.c.size() || x.empty()) return kInf;
  const Sets sets(qp);
  Vec h, w(x.size()), y;
  reduced_gradient(qp, x, lambda, h);
  for (std::size_t i = 0; i < x.size(); ++i) w[i] = x[i] - h[i];
  project(qp, sets, w, y);
  double res = 0.0, size = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    res = std::max(res, std::abs(x[i] - y[i]));
    size = std::max({size, std::abs(x[i]), std::abs(y[i])});
  }
  double worst = size > 0.0 ? res / size : (res > 0.0 ? kInf : 0.0);
  for (const auto& eq : qp.equalities) {
    double ax = 0.0, terms = std::abs(eq.b);
    for (std::size_t i = 0; i < x.size(); ++i) {
      ax += eq.a[i] * x[i];
      terms += std::abs(eq.a[i] * x[i]);
    }
    const double miss = std::abs(ax - eq.b);
    worst = std::max(worst, terms > 0.0 ? miss / terms : (miss > 0.0 ? kInf : 0.0));
  }
  return worst;
}

PolishResult polish_on_active_set(const QuadraticProgram& qp, Vec& x, Vec& lambda, double target) {
  PolishResult result;
  const std::size_t n = qp.c.size(), m = qp.equalities.size();
  lambda.resize(m, 0.0);
  result.before = result.after = kkt_residual(qp, x, lambda);
  if (n == 0 || qp.Q == nullptr || !(result.before > 0.0)) return result;
  const Sets sets(qp);
  const int cg_max = static_cast<int>(std::min<std::size_t>(2 * n + 10, 2000));
  Vec cur = x, cur_lambda = lambda, h, w(n), held(n), r(n), qh(n), y0;
  std::vector<Vec> y(m);
  std::vector<char> free(n), last_free;
  for (int round = 0; round < 12; ++round) {
    // Active set from w = x - h: held values where w leaves the set.
    reduced_gradient(qp, cur, cur_lambda, h);
    for (std::size_t i = 0; i < n; ++i) w[i] = cur[i] - h[i];
    std::fill(held.begin(), held.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      free[i] = 1;
      if (sets.disk_of[i] >= 0) continue;
      if (sets.lower[i] == sets.upper[i] || w[i] <= sets.lower[i]) {
        free[i] = 0;
        held[i] = sets.lower[i];
      } else if (w[i] >= sets.upper[i]) {
        free[i] = 0;
        held[i] = sets.upper[i];
      }
    }
    for (const auto& d : qp.disks) {
      const double norm = std::hypot(w[d.ix], w[d.iy]);
      if (norm <= d.radius) continue;
      free[d.ix] = free[d.iy] = 0;  // slip: on the circle, along w
      held[d.ix] = d.radius * w[d.ix] / norm;
      held[d.iy] = d.radius * w[d.iy] / norm;
    }
    // The same set again: its solution is the last one (disks: the held direction moves, go on).
    if (round > 0 && free == last_free && qp.disks.empty()) break;
    last_free = free;
    ++result.rounds;
    // Right-hand side -(c + Q x_H) on F; one solve for it and one per equality row.
    qp.Q->apply(held.data(), qh.data());
    ++result.applies;
    for (std::size_t i = 0; i < n; ++i) r[i] = -(qp.c[i] + qh[i]);
    result.applies += cg_on_face(qp, free, r, y0, cg_max);
    Eigen::MatrixXd s(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(m));
    for (std::size_t k = 0; k < m; ++k) result.applies += cg_on_face(qp, free, qp.equalities[k].a, y[k], cg_max);
    for (std::size_t k = 0; k < m; ++k) {
      const Vec& a = qp.equalities[k].a;
      double rk = qp.equalities[k].b;
      for (std::size_t i = 0; i < n; ++i) rk -= a[i] * (free[i] ? y0[i] : held[i]);
      rhs(static_cast<Eigen::Index>(k)) = rk;
      for (std::size_t l = 0; l < m; ++l) {
        double sk = 0.0;
        for (std::size_t i = 0; i < n; ++i)
          if (free[i]) sk += a[i] * y[l][i];
        s(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l)) = sk;
      }
    }
    Vec next_lambda = cur_lambda;
    if (m > 0 && s.cwiseAbs().maxCoeff() > 0.0) {
      const Eigen::VectorXd mu = s.completeOrthogonalDecomposition().solve(rhs);
      for (std::size_t k = 0; k < m; ++k) next_lambda[k] = mu(static_cast<Eigen::Index>(k));
    }
    Vec next(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!free[i]) {
        next[i] = held[i];
        continue;
      }
      double v = y0[i];
      for (std::size_t k = 0; k < m; ++k) v += next_lambda[k] * y[k][i];
      next[i] = v;
    }
    cur = next;
    cur_lambda = next_lambda;
    if (!feasible(qp, sets, cur)) continue;  // the next active set holds what left the set
    const double res = kkt_residual(qp, cur, cur_lambda);
    if (res < result.after) {
      result.after = res;
      result.improved = true;
      x = cur;
      lambda = cur_lambda;
    }
    if (result.after <= std::max(target, 1e-15)) break;
  }
  return result;
}

std::string polish_summary(const PolishResult& polish) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "active-set polish: KKT residual %.3g -> %.3g (%d sets, %d applies)", polish.before,
                polish.after, polish.rounds, polish.applies);
  return buf;
}

}  // namespace dc
