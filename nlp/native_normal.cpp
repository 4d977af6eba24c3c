// Bound-constrained preconditioned conjugate gradients for the normal problem (4.7) (native
// backend): the active-set CG of Polonsky & Keer (Wear 231, 1999) with the FFT preconditioner
// and the safeguards of Vollebregt's NormCG (J. Comput. Phys. 257, 2014). docs/solvers.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include "interrupt.hpp"
#include "native_solvers.hpp"
#include "solver_report.hpp"

namespace dc {

NormalQpForm read_normal_qp(const QuadraticProgram& qp) {
  NormalQpForm form;
  read_normal_qp(qp, form);
  return form;
}

void read_normal_qp(const QuadraticProgram& qp, NormalQpForm& form) {
  form.n_free = 0;
  form.force_control = false;
  form.a0 = form.total = 0.0;
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
}

void load_lowest_elements(const QuadraticProgram& qp, const NormalQpForm& form, std::vector<double>& x) {
  // The total spread evenly over the lowest tenth of the gap's range: the elements first to
  // touch (CONTACT's NormCG starts the same way).
  double c_min = kInf, c_max = -kInf;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (form.free[i]) {
      c_min = std::min(c_min, qp.c[i]);
      c_max = std::max(c_max, qp.c[i]);
    }
  const double threshold = c_min + 0.1 * (c_max - c_min);
  std::size_t count = 0;
  for (std::size_t i = 0; i < x.size(); ++i) count += form.free[i] && qp.c[i] <= threshold;
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = form.free[i] && qp.c[i] <= threshold ? form.total / static_cast<double>(count) : 0.0;
}

std::vector<double> normal_start(const QuadraticProgram& qp, const NormalQpForm& form) {
  std::vector<double> x;
  normal_start(qp, form, x);
  return x;
}

void normal_start(const QuadraticProgram& qp, const NormalQpForm& form, std::vector<double>& x) {
  const std::size_t n = qp.c.size();
  x.assign(n, 0.0);
  if (qp.x0.size() == n)
    for (std::size_t i = 0; i < n; ++i) x[i] = form.free[i] ? std::max(qp.x0[i], 0.0) : 0.0;
  if (!form.force_control) return;
  const double sum_x = std::accumulate(x.begin(), x.end(), 0.0);
  if (sum_x > 0.0) {
    for (double& v : x) v *= form.total / sum_x;
  } else {
    load_lowest_elements(qp, form, x);
  }
}

namespace {
/// Mean of v over the contact set (0 when it is empty).
double set_mean(const std::vector<double>& v, const std::vector<char>& in_set, std::size_t n_set) {
  if (n_set == 0) return 0.0;
  double s = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (in_set[i]) s += v[i];
  return s / static_cast<double>(n_set);
}

/// Keeps the iteration history bounded: every iteration up to 20, then every 10th (and the last,
/// added by the caller), so a report of 1000 iterations holds about 120 records.
void record(std::vector<IterationRecord>& history, const IterationRecord& r) {
  if (r.iteration <= 20 || r.iteration % 10 == 0) history.push_back(r);
}
}  // namespace

// The contact set I is kept explicitly. Each iteration takes one CG step on I
// (z = M^-1 r, v = z + beta v with Polak-Ribiere's beta bounded below by 0, so a direction
// survives a change of I instead of restarting; under force control r, z and v are projected
// on sum x = const and the mean gap over I is the approach), then moves the elements whose
// pressure went negative out of I (pressure 0, the force restored by scaling) and lets the
// elements outside I that overlap enter with pressure 0 (their residual, the overlap, pulls
// them up in the next step). Stops when the relative change of x is below options.tol and I
// did not change. w = Q x is updated with the step's image while no element leaves.
SolveOutcome solve_normal_native(const QuadraticProgram& qp, const SolveOptions& options,
                                 const NormalPreconditioner* preconditioner, double scale) {
  NativeNormalWorkspace work;
  SolveOutcome out;
  solve_normal_native(qp, options, preconditioner, scale, work, out);
  return out;
}

void solve_normal_native(const QuadraticProgram& qp, const SolveOptions& options,
                         const NormalPreconditioner* preconditioner, double scale, NativeNormalWorkspace& work,
                         SolveOutcome& out) {
  const std::size_t n = qp.c.size();
  NormalQpForm& form = work.form;
  read_normal_qp(qp, form);
  if (form.n_free == 0) {
    out.x.assign(n, 0.0);
    out.message = "no element can carry load";
    return;
  }
  std::vector<double>& x = work.x;
  normal_start(qp, form, x);
  std::vector<double>&w = work.w, &g = work.g, &r = work.r, &r_prev = work.r_prev, &z = work.z, &v = work.v,
                      &q = work.q;
  for (std::vector<double>* u : {&w, &g, &z, &q}) u->resize(n);
  for (std::vector<double>* u : {&r, &r_prev, &v}) u->assign(n, 0.0);
  std::vector<char>& in_set = work.in_set;
  in_set.resize(n);
  std::size_t n_set = 0;
  for (std::size_t i = 0; i < n; ++i) {
    in_set[i] = form.free[i] && x[i] > 0.0;
    n_set += in_set[i];
  }
  qp.Q->apply(x.data(), w.data());
  constexpr int kRefresh = 25;  // recompute w = Q x at least this often (round-off)
  int since_refresh = 0;
  double rz_old = 0.0, shift = 0.0;
  bool step_converged = false, first = true;
  int iteration = 0;
  IterationRecord last;
  for (;;) {
    throw_if_interrupted();
    // The gap g = Q x + c (minus the approach under force control) and the residual on I.
    for (std::size_t i = 0; i < n; ++i) g[i] = w[i] + qp.c[i];
    shift = form.force_control ? set_mean(g, in_set, n_set) : 0.0;
    std::size_t entered = 0;
    for (std::size_t i = 0; i < n; ++i) {
      g[i] -= shift;
      if (in_set[i]) {
        r[i] = -g[i];
      } else if (form.free[i] && g[i] < 0.0) {  // overlap outside I: enter with pressure 0
        in_set[i] = 1;
        r[i] = -g[i];
        v[i] = 0.0;
        ++entered;
      } else {
        r[i] = 0.0;
      }
    }
    n_set += entered;
    last.entered = entered;
    if (step_converged && entered == 0) {
      out.success = true;
      char change[32];
      std::snprintf(change, sizeof change, "%.3g", last.change);  // format_number's, without a temporary
      out.message.assign("converged (relative change ");
      out.message.append(change);
      out.message.append(")");
      break;
    }
    if (n_set == 0) {  // approach control: nothing overlaps
      out.success = true;
      out.message = "no contact";
      break;
    }
    if (iteration == options.max_iter) break;
    out.iterations = ++iteration;

    if (preconditioner) {
      preconditioner->apply(r.data(), in_set.data(), scale, z.data());
    } else {
      for (std::size_t i = 0; i < n; ++i) z[i] = r[i];
    }
    if (form.force_control) {
      const double m = set_mean(z, in_set, n_set);
      for (std::size_t i = 0; i < n; ++i)
        if (in_set[i]) z[i] -= m;
    }
    double rz = 0.0, z_rprev = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (in_set[i]) {
        rz += r[i] * z[i];
        z_rprev += z[i] * r_prev[i];
      }
    const double beta = (first || !(rz_old > 0.0)) ? 0.0 : std::max(0.0, (rz - z_rprev) / rz_old);
    first = false;
    rz_old = rz;
    for (std::size_t i = 0; i < n; ++i) v[i] = in_set[i] ? z[i] + beta * v[i] : 0.0;
    if (form.force_control) {  // elements that left I took their share of v with them
      const double m = set_mean(v, in_set, n_set);
      for (std::size_t i = 0; i < n; ++i)
        if (in_set[i]) v[i] -= m;
    }
    qp.Q->apply(v.data(), q.data());
    double rv = 0.0, vq = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (in_set[i]) {
        rv += r[i] * v[i];
        vq += v[i] * q[i];
      }
    double alpha = 0.0;
    if (vq > 0.0) {
      alpha = rv / vq;
    } else if (rz != 0.0) {
      out.message = "non-positive curvature along the search direction";
      break;
    }
    // The step, the elements leaving I, and the relative change of x.
    double change = 0.0, sum_x = 0.0;
    std::size_t left = 0;
    for (std::size_t i = 0; i < n; ++i) {
      r_prev[i] = r[i];
      if (!in_set[i]) continue;
      const double before = x[i];
      x[i] += alpha * v[i];
      if (x[i] < 0.0) {
        x[i] = 0.0;
        in_set[i] = 0;
        v[i] = 0.0;
        r_prev[i] = 0.0;
        ++left;
      }
      change += std::abs(x[i] - before);
      sum_x += x[i];
    }
    n_set -= left;
    if (form.force_control && left > 0 && n_set == 0) {
      // Everything left: start again from the elements of deepest overlap.
      load_lowest_elements(qp, form, x);
      for (std::size_t i = 0; i < n; ++i) n_set += (in_set[i] = form.free[i] && x[i] > 0.0);
      sum_x = form.total;
      first = true;
    } else if (form.force_control && left > 0 && sum_x > 0.0) {
      const double rescale = form.total / sum_x;
      for (double& value : x) value *= rescale;
      sum_x = form.total;
    }
    if (left > 0 || since_refresh >= kRefresh) {
      qp.Q->apply(x.data(), w.data());
      since_refresh = 0;
    } else {
      for (std::size_t i = 0; i < n; ++i) w[i] += alpha * q[i];
      ++since_refresh;
    }
    const double rel = sum_x > 0.0 ? change / sum_x : 0.0;
    last = {iteration, rel, n_set, last.entered, left};
    record(out.history, last);
    if (options.progress) options.progress({iteration, 0.0, rel, options.tol});
    step_converged = rel < options.tol && left == 0;
  }
  if (!out.history.empty() && out.history.back().iteration != last.iteration && last.iteration > 0)
    out.history.push_back(last);
  if (!out.success && out.message.empty()) out.message = "iteration limit reached";
  out.x.assign(x.begin(), x.end());
  out.objective = qp.gradient(out.x.data(), g.data());  // the objective; g is free by now
  if (form.force_control) out.equality_multipliers.assign(1, shift / form.a0);
}

}  // namespace dc
