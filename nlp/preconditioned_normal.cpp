// Preconditioned projected conjugate gradients for the normal problem (4.7) (native backend).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "interrupt.hpp"
#include "native_solvers.hpp"

namespace dc {

NormalQpForm read_normal_qp(const QuadraticProgram& qp) {
  NormalQpForm form;
  const std::size_t n = qp.c.size();
  if (qp.equalities.size() > 1 || !qp.disks.empty())
    throw std::invalid_argument("native normal solver: at most one equality and no disks");
  form.force_control = qp.equalities.size() == 1;
  form.free.assign(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    if (!qp.lower.empty() && qp.lower[i] != 0.0)
      throw std::invalid_argument("native normal solver: lower bounds must be 0");
    if (!qp.upper.empty() && qp.upper[i] <= 0.0) form.free[i] = 0;
  }
  form.n_free = static_cast<std::size_t>(std::count(form.free.begin(), form.free.end(), 1));
  if (form.force_control && form.n_free > 0) {
    const auto& eq = qp.equalities.front();
    for (std::size_t i = 0; i < n; ++i)
      if (form.free[i]) {
        if (form.a0 == 0.0) form.a0 = eq.a[i];
        if (std::abs(eq.a[i] - form.a0) > 1e-12 * std::abs(form.a0))
          throw std::invalid_argument("native normal solver: equality weights must be equal");
      }
    form.total = eq.b / form.a0;
    if (!(form.total > 0.0)) throw std::invalid_argument("native normal solver: the load must be positive");
  }
  return form;
}

std::vector<double> normal_start(const QuadraticProgram& qp, const NormalQpForm& form) {
  const std::size_t n = qp.c.size();
  std::vector<double> x(n, 0.0);
  if (qp.x0.size() == n)
    for (std::size_t i = 0; i < n; ++i) x[i] = form.free[i] ? std::max(qp.x0[i], 0.0) : 0.0;
  if (form.force_control) {
    const double sum_x = std::accumulate(x.begin(), x.end(), 0.0);
    if (sum_x <= 0.0) {
      for (std::size_t i = 0; i < n; ++i) x[i] = form.free[i] ? form.total / form.n_free : 0.0;
    } else {
      for (double& v : x) v *= form.total / sum_x;
    }
  }
  return x;
}

namespace {
/// Mean of v over the active set (0 when it is empty).
double active_mean(const std::vector<double>& v, const std::vector<char>& active, std::size_t n_active) {
  if (n_active == 0) return 0.0;
  double s = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (active[i]) s += v[i];
  return s / static_cast<double>(n_active);
}
}  // namespace

// Conjugate gradients on the contact set I = {x > 0} with the preconditioner restricted to I
// (Polonsky & Keer's active-set iteration, preconditioned). Under force control the gradient
// and the preconditioned gradient are projected on sum x = const (P M^-1 P stays symmetric),
// and the mean gap over I is the multiplier. Elements outside I that overlap enter with a
// Jacobi step (Q has unit diagonal) and restart the recurrence. w = Q x is updated with the
// direction's image while no element enters or leaves, and recomputed otherwise.
SolveOutcome solve_normal_preconditioned(const QuadraticProgram& qp, const SolveOptions& options,
                                         const NormalPreconditioner& preconditioner, double scale) {
  const std::size_t n = qp.c.size();
  const NormalQpForm form = read_normal_qp(qp);
  SolveOutcome out;
  if (form.n_free == 0) {
    out.x.assign(n, 0.0);
    out.message = "no element can carry load";
    return out;
  }
  std::vector<double> x = normal_start(qp, form);
  std::vector<double> w(n), g(n), z(n), d(n, 0.0), r(n);
  std::vector<char> active(n);
  qp.Q->apply(x.data(), w.data());
  bool w_current = true, restart = true;
  double gz_old = 1.0, shift = 0.0;
  constexpr int kRefresh = 25;  // recompute w = Q x at least this often (round-off)
  int since_refresh = 0;
  for (int it = 1; it <= options.max_iter; ++it) {
    throw_if_interrupted();
    out.iterations = it;
    if (!w_current || since_refresh >= kRefresh) {
      qp.Q->apply(x.data(), w.data());
      since_refresh = 0;
    }
    std::size_t n_active = 0;
    for (std::size_t i = 0; i < n; ++i) {
      g[i] = w[i] + qp.c[i];
      active[i] = form.free[i] && x[i] > 0.0;
      n_active += active[i];
    }
    // The mean gap over the contact set: the unknown approach under force control.
    shift = form.force_control ? active_mean(g, active, n_active) : 0.0;
    for (double& v : g) v -= shift;

    if (n_active == 0) {  // approach control with nothing in contact: a Jacobi step
      bool entered = false;
      for (std::size_t i = 0; i < n; ++i)
        if (form.free[i] && g[i] < 0.0) {
          x[i] = -g[i];
          entered = true;
        }
      if (!entered) {
        out.success = true;
        out.message = "no contact";
        break;
      }
      w_current = false;
      restart = true;
      continue;
    }

    preconditioner.apply(g.data(), active.data(), scale, z.data());
    if (form.force_control) {
      const double m = active_mean(z, active, n_active);
      for (std::size_t i = 0; i < n; ++i)
        if (active[i]) z[i] -= m;
    }
    double gz = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (active[i]) gz += g[i] * z[i];
    const double beta = restart ? 0.0 : gz / gz_old;
    gz_old = gz;
    for (std::size_t i = 0; i < n; ++i) d[i] = active[i] ? z[i] + beta * d[i] : 0.0;
    if (form.force_control) {  // elements that left I took their share of d with them
      const double m = active_mean(d, active, n_active);
      for (std::size_t i = 0; i < n; ++i)
        if (active[i]) d[i] -= m;
    }
    qp.Q->apply(d.data(), r.data());
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (active[i]) {
        num += g[i] * d[i];
        den += r[i] * d[i];
      }
    if (!(den > 0.0)) {
      if (gz == 0.0) {
        out.success = true;
        out.message = "exact solution";
        break;
      }
      out.message = "non-positive curvature along the search direction";
      break;
    }
    const double alpha = num / den;
    double change = 0.0, sum_x = 0.0;
    bool clipped = false, entered = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (!form.free[i]) continue;
      const double before = x[i];
      if (active[i]) {
        x[i] -= alpha * d[i];
        if (x[i] < 0.0) {
          x[i] = 0.0;
          clipped = true;
        }
      } else if (g[i] < 0.0) {  // overlap outside the contact set: let it enter
        x[i] = -g[i];
        entered = true;
      }
      change += std::abs(x[i] - before);
      sum_x += x[i];
    }
    double rescale = 1.0;
    if (form.force_control && sum_x > 0.0 && (clipped || entered)) {
      rescale = form.total / sum_x;
      for (double& v : x) v *= rescale;
    }
    restart = entered;
    w_current = !(clipped || entered);
    if (w_current) {
      for (std::size_t i = 0; i < n; ++i) w[i] -= alpha * r[i];
      ++since_refresh;
    }
    const double rel = sum_x > 0.0 ? change / sum_x : 0.0;
    if (options.progress) options.progress({it, 0.0, rel, options.tol});
    if (rel < options.tol && !entered) {
      out.success = true;
      out.message = "converged (relative change " + std::to_string(rel) + ")";
      break;
    }
  }
  if (!out.success && out.message.empty()) out.message = "iteration limit reached";
  out.x = std::move(x);
  out.objective = qp.objective(out.x.data());
  if (form.force_control) out.equality_multipliers = {shift / form.a0};
  return out;
}

}  // namespace dc
