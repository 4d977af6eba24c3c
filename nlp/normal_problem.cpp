#include "normal_problem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "active_set_polish.hpp"
#include "backend_choice.hpp"
#include "certified_solve.hpp"
#include "errors.hpp"
#include "kept_storage.hpp"
#include "native_solvers.hpp"
#include "scaled_operator.hpp"

namespace dc {
namespace {

/// The scales of the QP of (4.7): x = p / p_ref, Q = C / c0 (unit diagonal),
/// c = (h - delta) / (c0 p_ref); under force control one row (sum x) / n_ref = 1.
struct ScaledNormalProgram {
  double c0 = 1.0, p_ref = 1.0, n_ref = 1.0;
};


}  // namespace

NormalProblem::NormalProblem(const Grid& grid, const MaterialPair& materials, std::vector<double> heights,
                             OperatorKind kind)
    : NormalProblem(std::shared_ptr<const LinearOperator>(HalfSpace(grid, materials).normal(kind)), grid,
                    std::move(heights)) {}

NormalProblem::NormalProblem(std::shared_ptr<const LinearOperator> compliance, const Grid& grid,
                             std::vector<double> heights)
    : compliance_(std::move(compliance)), grid_(grid) {
  set_heights(std::move(heights));
  if (compliance_->rows() != grid_.size() || compliance_->cols() != grid_.size())
    throw std::invalid_argument("normal problem: operator and grid sizes differ");
  if (!(compliance_->diagonal(0) > 0.0))
    throw std::invalid_argument("normal problem: the compliance must have a positive diagonal");
}

void NormalProblem::set_heights(const std::vector<double>& heights) {
  if (heights.size() != grid_.size()) throw std::invalid_argument("normal problem: one height per element");
  heights_.assign(heights.begin(), heights.end());  // reuses the buffer: no allocation per step
  if (std::none_of(heights_.begin(), heights_.end(), [](double h) { return std::isfinite(h); }))
    throw InputError("profile", "no element of the grid can touch the body");
}

void NormalProblem::set_warm_start(std::vector<double> pressure) {
  if (pressure.size() != grid_.size()) throw std::invalid_argument("normal problem: one warm-start pressure per element");
  warm_start_ = std::move(pressure);
}

void reset_keeping_storage(NormalSolution& solution) {
  reset_keeping_members(solution, &NormalSolution::pressure, &NormalSolution::gap, &NormalSolution::report);
}

Certificate NormalProblem::certify(const std::vector<double>& p, double approach, const NormalSpec& control) const {
  if (!std::isfinite(approach) || !all_finite(p)) return Certificate::not_finite();
  Certificate cert;
  const std::size_t n = grid_.size();
  std::vector<double>& w = certify_work_;  // no allocation per certificate once sized
  compliance_->apply(p, w);
  const double p_max = std::max(*std::max_element(p.begin(), p.end()), 0.0);
  double comp = 0.0, gap_neg = 0.0, p_neg = 0.0, force = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    force += p[i] * grid_.area();
    p_neg = std::max(p_neg, -p[i]);
    if (!std::isfinite(heights_[i])) continue;  // cannot touch: p is held at 0
    const double c0 = compliance_->diagonal(i);
    const double g = (w[i] + heights_[i] - approach) / c0;  // gap in pressure units
    comp = std::max(comp, std::abs(std::min(p[i], g)));
    gap_neg = std::max(gap_neg, -g);
  }
  const double scale = p_max > 0.0 ? p_max : 1.0;
  cert.complementarity = comp / scale;
  cert.gap_violation = gap_neg / scale;
  cert.pressure_violation = p_neg / scale;
  if (control.control == Control::force) cert.force_residual = std::abs(force - control.value) / control.value;
  return cert;
}

NormalSolution NormalProblem::solve(const NormalSpec& control, const SolverOptions& solver,
                                    const ProgressCallback& progress) {
  NormalSolution solution;
  solve_or_polish(control, solver, progress, nullptr, solution);
  return solution;
}

void NormalProblem::solve(const NormalSpec& control, const SolverOptions& solver, NormalSolution& solution,
                          const ProgressCallback& progress) {
  solve_or_polish(control, solver, progress, nullptr, solution);
}

NormalSolution NormalProblem::polish(const std::vector<double>& pressure, const NormalSpec& control,
                                     const SolverOptions& solver) {
  if (pressure.size() != grid_.size()) throw std::invalid_argument("normal problem: polish: one pressure per element");
  NormalSolution solution;
  solve_or_polish(control, solver, {}, &pressure, solution);
  return solution;
}

/// The program, the attempts and their results are work_'s, filled again (no allocation for a
/// solve repeated at every step once they are sized).
void NormalProblem::solve_or_polish(const NormalSpec& control, const SolverOptions& solver,
                                    const ProgressCallback& progress, const std::vector<double>* given,
                                    NormalSolution& result) {
  const std::size_t n = grid_.size();
  const double A = grid_.area();
  std::size_t n_free = 0;
  for (double h : heights_) n_free += std::isfinite(h) ? 1 : 0;

  // Scales: x = p / p_ref is O(1) in the contact; Q has unit diagonal.
  ScaledNormalProgram s;  // the scales; the program itself is work_.qp
  s.c0 = compliance_->diagonal(0);
  s.n_ref = std::max(1.0, 0.25 * static_cast<double>(n_free));
  const double delta = control.control == Control::approach ? control.value : 0.0;
  if (control.control == Control::force) {
    s.p_ref = control.value / (A * s.n_ref);
  } else {
    const double spread = grid_.dimension == 2 ? s.n_ref : std::sqrt(s.n_ref);
    s.p_ref = control.value / (s.c0 * spread);
  }
  ScaledOperator Q(*compliance_, 1.0 / s.c0);
  QuadraticProgram& qp = work_.qp;
  qp.Q = &Q;
  qp.c.resize(n);
  qp.lower.assign(n, 0.0);
  qp.upper.assign(n, kInf);
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isfinite(heights_[i])) {
      qp.c[i] = (heights_[i] - delta) / (s.c0 * s.p_ref);
    } else {
      qp.c[i] = 0.0;
      qp.upper[i] = 0.0;
    }
  }
  qp.equalities.resize(control.control == Control::force ? 1 : 0);  // the row's storage kept
  if (control.control == Control::force) {
    LinearEquality& eq = qp.equalities.front();
    eq.a.assign(n, 1.0 / s.n_ref);
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(heights_[i])) eq.a[i] = 0.0;
    eq.b = control.value / (A * s.p_ref * s.n_ref);
  }
  qp.x0.clear();
  if (warm_start_.size() == n) {
    qp.x0.resize(n);
    for (std::size_t i = 0; i < n; ++i) qp.x0[i] = warm_start_[i] / s.p_ref;
  }

  SolveOptions options = solve_options(solver, progress);
  if (exact_hessian_limit_ > 0) options.exact_hessian_limit = exact_hessian_limit_;

  NormalSolution& first = work_.first;
  reset_keeping_storage(first);
  first.report.requested = to_string(solver.backend);
  first.report.operator_kind = compliance_->kind();
  // A point x of the scaled program as pressure, approach, gap and energy, certified.
  const auto fill_solution = [&](const std::vector<double>& x, NormalSolution& sol) {
    sol.pressure.resize(n);
    for (std::size_t i = 0; i < n; ++i) sol.pressure[i] = std::max(x[i], 0.0) * s.p_ref;
    // The approach: given, or the pressure-weighted mean of C p + h over the contact (the
    // value that makes the gap vanish where p > 0); the backends' multipliers agree with it.
    std::vector<double>& w = work_.w;
    compliance_->apply(sol.pressure, w);
    if (control.control == Control::approach) {
      sol.approach = control.value;
    } else {
      double num = 0.0, den = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (sol.pressure[i] > 0.0) {
          num += sol.pressure[i] * (w[i] + heights_[i]);
          den += sol.pressure[i];
        }
      sol.approach = den > 0.0 ? num / den : 0.0;
    }
    sol.gap.resize(n);
    sol.force = 0.0;
    double energy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      sol.gap[i] = std::isfinite(heights_[i]) ? w[i] + heights_[i] - sol.approach : kInf;
      sol.force += sol.pressure[i] * A;
      if (std::isfinite(heights_[i])) energy += A * sol.pressure[i] * (0.5 * w[i] + heights_[i] - delta);
    }
    sol.report.objective = energy;  // the functional (4.7) in J (2-D: J/m)
    sol.report.certificate = certify(sol.pressure, sol.approach, control);
    sol.report.status =
        sol.report.certificate.worst() <= solver.certificate_tol ? SolveStatus::converged : SolveStatus::not_converged;
  };
  if (given) {
    NormalSolution& sol = result;
    reset_keeping_storage(sol);
    sol.report = first.report;
    sol.report.backend = "active-set polish";
    std::vector<double> x(n), lambda, g(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = std::max((*given)[i], 0.0) / s.p_ref;
    if (!qp.equalities.empty()) {
      // The force row's multiplier from the contact's reduced gradient: Qx + c = lambda a there.
      qp.gradient(x.data(), g.data());
      double sum = 0.0;
      int count = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (x[i] > 0.0 && qp.equalities[0].a[i] != 0.0) {
          sum += g[i] / qp.equalities[0].a[i];
          ++count;
        }
      lambda.assign(1, count > 0 ? sum / count : 0.0);
    }
    const auto start = std::chrono::steady_clock::now();
    const PolishResult polish = polish_on_active_set(qp, x, lambda, 1e-2 * solver.certificate_tol);
    fill_solution(x, sol);
    sol.report.polished = polish.improved;
    sol.report.message = polish_summary(polish);
    sol.report.iterations = polish.applies;
    sol.report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return;
  }
  std::vector<std::string>& order = work_.order;
  backend_order(solver.backend, native_first_ ? std::numeric_limits<std::size_t>::max() : n, solver.fallback, order);
  AttemptLedger<NormalSolution>& ledger = work_.ledger;
  ledger.restart(first);
  const double c0 = s.c0;
  const NativeSolverInto native = [this, c0](const QuadraticProgram& q, const SolveOptions& o, SolveOutcome& out) {
    solve_normal_native(q, o, preconditioner_.get(), c0, work_.native, out);
  };
  for (std::size_t k = 0; k < order.size() && !ledger.converged(); ++k) {
    const std::string& backend = order[k];
    if (backend == "native" && !preconditioner_)
      preconditioner_ = std::make_shared<NormalPreconditioner>(*compliance_, grid_);
    TimedOutcome& run = work_.run;
    run_backend(backend, qp, options, native, run);
    const SolveOutcome& outcome = run.outcome;
    NormalSolution& sol = work_.trial;
    sol = first;
    sol.report.backend = backend;
    sol.report.fallback_used = k > 0;
    sol.report.message = outcome.message;
    sol.report.iterations = outcome.iterations;
    sol.report.polished = outcome.polished;
    sol.report.time_s = run.time_s;
    const bool has_point = outcome.x.size() == n;
    if (has_point) {
      fill_solution(outcome.x, sol);
      finish_backend_point(backend, outcome, qp, solver.certificate_tol, sol,
                           [&](const std::vector<double>& x, const std::vector<double>&, NormalSolution& polished) {
                             fill_solution(x, polished);
                           });
    } else {
      sol.report.status = SolveStatus::failed;
    }
    ledger.record_swapping(sol, has_point, outcome.history);
  }
  ledger.finish_into(result);
  if (result.report.status == SolveStatus::converged) warm_start_.assign(result.pressure.begin(), result.pressure.end());
}

}  // namespace dc
