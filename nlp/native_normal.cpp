#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "native_solvers.hpp"
#include "solver_report.hpp"
#include "interrupt.hpp"

namespace dc {

SolveOutcome solve_normal_native(const QuadraticProgram& qp, const SolveOptions& options) {
  const std::size_t n = qp.c.size();
  const NormalQpForm form = read_normal_qp(qp);
  const bool force_control = form.force_control;
  const std::vector<char>& free = form.free;
  const std::size_t n_free = form.n_free;
  SolveOutcome out;
  if (n_free == 0) {
    out.x.assign(n, 0.0);
    out.message = "no element can carry load";
    return out;
  }
  const double total = form.total;  // sum x required under force control
  std::vector<double> x = normal_start(qp, form), g(n), t(n, 0.0), r(n), x_old(n);
  double sum_x = 0.0;

  double g_norm_old = 1.0, shift = 0.0;
  bool restart = true;
  for (int it = 1; it <= options.max_iter; ++it) {
    throw_if_interrupted();
    out.iterations = it;
    qp.Q->apply(x.data(), g.data());
    for (std::size_t i = 0; i < n; ++i) g[i] += qp.c[i];
    // Mean gap over the contact set: the unknown approach under force control.
    std::size_t n_contact = 0;
    double g_sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (free[i] && x[i] > 0.0) {
        g_sum += g[i];
        ++n_contact;
      }
    shift = (force_control && n_contact > 0) ? g_sum / n_contact : 0.0;
    for (double& v : g) v -= shift;

    double g_norm = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (free[i] && x[i] > 0.0) g_norm += g[i] * g[i];
    const double beta = restart ? 0.0 : g_norm / g_norm_old;
    g_norm_old = g_norm;
    for (std::size_t i = 0; i < n; ++i) t[i] = (free[i] && x[i] > 0.0) ? g[i] + beta * t[i] : 0.0;

    double step = 1.0;  // Q has unit diagonal: a Jacobi step when the contact set is empty
    if (n_contact > 0) {
      qp.Q->apply(t.data(), r.data());
      double r_mean = 0.0;
      if (force_control) {
        for (std::size_t i = 0; i < n; ++i)
          if (free[i] && x[i] > 0.0) r_mean += r[i];
        r_mean /= n_contact;
      }
      double num = 0.0, den = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (free[i] && x[i] > 0.0) {
          num += g[i] * t[i];
          den += (r[i] - r_mean) * t[i];
        }
      if (!(den > 0.0)) {
        if (g_norm == 0.0) {
          out.success = true;
          out.message = "exact solution";
          break;
        }
        out.message = "non-positive curvature along the search direction";
        break;
      }
      step = num / den;
    }
    x_old = x;
    bool entered = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (!free[i]) continue;
      if (x[i] > 0.0) {
        x[i] = std::max(x[i] - step * t[i], 0.0);
      } else if (g[i] < 0.0) {  // overlap outside the contact set: let it enter
        x[i] = -step * g[i];
        entered = true;
      }
    }
    restart = entered;
    sum_x = std::accumulate(x.begin(), x.end(), 0.0);
    if (force_control && sum_x > 0.0)
      for (double& v : x) v *= total / sum_x;
    double change = 0.0;
    sum_x = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      change += std::abs(x[i] - x_old[i]);
      sum_x += x[i];
    }
    const double rel = sum_x > 0.0 ? change / sum_x : 0.0;
    if (options.progress) options.progress({it, 0.0, rel, options.tol});
    if (sum_x == 0.0 && !force_control) {  // no overlap anywhere: p = 0 is the solution
      out.success = n_contact == 0 && !entered;
      if (out.success) {
        out.message = "no contact";
        break;
      }
    }
    if (rel < options.tol) {
      out.success = true;
      out.message = "converged (relative change " + format_number(rel) + ")";
      break;
    }
  }
  if (!out.success && out.message.empty()) out.message = "iteration limit reached";
  out.x = std::move(x);
  out.objective = qp.objective(out.x.data());
  if (force_control) out.equality_multipliers = {shift / form.a0};
  return out;
}

}  // namespace dc
