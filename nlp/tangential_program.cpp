// TangentialProblem::Impl: the convex program of one step (3.25)/(4.8), min 1/2 tau'Ct tau + W'tau
// over |tau| <= f (4.4)-(4.6) with the resultant-controlled modes as equality rows, scaled and
// windowed, and its certified solve: backends in order, polish, fallback to the condensed program.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "active_set_polish.hpp"
#include "backend_choice.hpp"
#include "certified_solve.hpp"
#include "errors.hpp"
#include "native_solvers.hpp"
#include "scaled_operator.hpp"
#include "sparse_block.hpp"
#include "support_window.hpp"
#include "tangential_problem_impl.hpp"
#include "vector_ops.hpp"

namespace dc {

/// The largest resultant of mode k that friction can carry: sum_e f_e |m_k(e)| A.
double TangentialProblem::Impl::resultant_capacity(int k, const std::vector<double>& f) const {
  double capacity = 0.0;
  for (std::size_t e = 0; e < N; ++e) {
    double m2 = 0.0;
    for (int c = 0; c < comps; ++c) m2 += mode(k, e, c) * mode(k, e, c);
    capacity += f[e] * std::sqrt(m2) * grid.area();
  }
  return capacity;
}

/// Prescribed resultants must stay below what friction can carry, each alone and the force
/// (F_x, F_y) together; reaching it is gross sliding (no quasi-static or steady solution).
void TangentialProblem::Impl::check_resultants(const std::vector<double>& f,
                                               const std::array<ModeControl, 3>& modes) const {
  static const char* names[] = {"tangential.force[0]", "tangential.force[1]", "tangential.moment"};
  auto sliding = [](const char* key, double value, double capacity) {
    throw InputError(key, "the prescribed resultant " + format_number(value) + " reaches the friction limit " +
                              format_number(capacity) + ": gross sliding, no quasi-static or steady solution");
  };
  if (std::none_of(modes.begin(), modes.begin() + n_modes(),
                   [](const ModeControl& m) { return m.kind == ModeControl::Kind::resultant; }))
    return;
  double total = 0.0;
  for (std::size_t e = 0; e < N; ++e) total += f[e] * grid.area();
  if (!(total > 0.0)) {  // frictionless (mu = 0) or unloaded: only zero resultants have a solution
    for (int k = 0; k < n_modes(); ++k)
      if (modes[k].kind == ModeControl::Kind::resultant && modes[k].value != 0.0)
        throw InputError(names[k], "the prescribed resultant " + format_number(modes[k].value) +
                                       " cannot be carried: the friction bound f(p) is 0 over the whole contact "
                                       "(mu = 0 or no load), so any tangential load is gross sliding, no "
                                       "quasi-static or steady solution");
    return;
  }
  for (int k = 0; k < n_modes(); ++k) {
    if (modes[k].kind != ModeControl::Kind::resultant) continue;
    const double capacity = resultant_capacity(k, f);
    if (std::abs(modes[k].value) >= capacity * (1.0 - 1e-12)) sliding(names[k], modes[k].value, capacity);
  }
  if (n_modes() == 3 && modes[0].kind == ModeControl::Kind::resultant && modes[1].kind == ModeControl::Kind::resultant) {
    const double F = std::hypot(modes[0].value, modes[1].value);
    if (F >= total * (1.0 - 1e-12)) sliding("tangential.force", F, total);
  }
}

/// The convex program of one step: min 1/2 tau'Ct tau + W'tau over |tau| <= f, with the
/// resultant-controlled modes as equality rows; W excludes the resultant-controlled modes.
/// The program, the attempts and their results are the Impl's (program_work), filled again:
/// a solve repeated at every step of a run allocates nothing once they are sized.
void TangentialProblem::Impl::solve_tangential(const std::vector<double>& W, const std::vector<double>& f,
                                               const std::array<ModeControl, 3>& modes,
                                               const std::array<double, 3>& given_increment,
                                               const SolverOptions& solver, const ProgressCallback& progress,
                                               InnerResult& result) {
  ProgramWork& work = program_work;
  const double A = grid.area();
  const double ct0 = Ct->diagonal(0);
  const double f_ref = std::max(max_abs(f), 1e-300);
  const std::size_t n = comps * N;
  // The program's elements: the grid, or a window of it that holds f > 0 (the same program:
  // tau is 0 wherever f is). The sparse form: Q the half-space's share, the body's in the
  // block's rows.
  SupportWindow window;
  if (windowing && half_space && !sparse) window = support_window(grid, f);
  const bool windowed = window.nx > 0;
  if (windowed && !windows) windows.emplace(grid, materials, kind);
  const std::size_t Nw = windowed ? window.size() : N, nw = comps * Nw;
  const auto element = [&](std::size_t l) { return windowed ? window.global(grid, l) : l; };
  const WindowOperators* ops = windowed ? &windows->operators(window) : nullptr;
  ScaledOperator Q(ops ? *ops->compliance : sparse ? *sparse->halfspace : *Ct, 1.0 / ct0);
  // The FFT preconditioner of the half-space's own compliance (Q^-1 = ct0 B22^-1).
  const TangentialPreconditioner* preconditioner = ops ? ops->preconditioner.get() : grid_preconditioner();
  std::optional<ScaledOperator> Q_inverse;
  if (preconditioner) Q_inverse.emplace(*preconditioner, ct0);
  QuadraticProgram& qp = work.qp;
  qp.Q = &Q;
  qp.preconditioner = Q_inverse ? &*Q_inverse : nullptr;
  qp.block = nullptr;
  qp.c.resize(nw);
  qp.lower.assign(nw, -kInf);
  qp.upper.assign(nw, kInf);
  qp.disks.clear();
  qp.equalities.clear();
  qp.x0.clear();
  for (std::size_t l = 0; l < Nw; ++l) {
    const std::size_t e = element(l);
    for (int c = 0; c < comps; ++c) {
      double w = W[c * N + e];
      for (int k = 0; k < n_modes(); ++k)
        if (modes[k].kind == ModeControl::Kind::amplitude) w += given_increment[k] * mode(k, e, c);
      qp.c[c * Nw + l] = w / (ct0 * f_ref);
    }
    const double r = f[e] / f_ref;
    if (r <= 0.0) {
      for (int c = 0; c < comps; ++c) qp.lower[c * Nw + l] = qp.upper[c * Nw + l] = 0.0;
    } else if (comps == 1) {
      qp.lower[l] = -r;
      qp.upper[l] = r;
    } else {
      qp.disks.push_back({static_cast<int>(l), static_cast<int>(Nw + l), r});
    }
  }
  check_resultants(f, modes);
  std::vector<int> row_mode;
  std::vector<double> row_scale;
  for (int k = 0; k < n_modes(); ++k) {
    if (modes[k].kind != ModeControl::Kind::resultant) continue;
    // Row sum_e mode_k . tau A = R_k, scaled by the largest resultant friction can carry.
    const double capacity = resultant_capacity(k, f);
    LinearEquality eq;
    eq.a.assign(nw, 0.0);
    for (std::size_t l = 0; l < Nw; ++l)
      for (int c = 0; c < comps; ++c) eq.a[c * Nw + l] = mode(k, element(l), c) * A * f_ref / capacity;
    eq.b = modes[k].value / capacity;
    qp.equalities.push_back(std::move(eq));
    row_mode.push_back(k);
    row_scale.push_back(capacity);
  }
  if (tau_warm.size() == n) {
    qp.x0.resize(nw);
    for (std::size_t l = 0; l < Nw; ++l)
      for (int c = 0; c < comps; ++c) qp.x0[c * Nw + l] = tau_warm[c * N + element(l)] / f_ref;
  }
  SolveOptions options = solve_options(solver, progress);
  if (exact_hessian_limit > 0) options.exact_hessian_limit = exact_hessian_limit;
  std::optional<SparseBlock> body_rows;  // only the sparse form has them (an empty block allocates)
  if (sparse) {
    const double n_active = static_cast<double>(std::count_if(f.begin(), f.end(), [](double b) { return b > 0.0; }));
    body_rows = sparse->body_rows(f_ref, A * ct0 * f_ref * f_ref, f_ref * A * std::max(1.0, 0.25 * n_active));
    qp.block = &*body_rows;
    options.exact_hessian_limit = sparse->exact_hessian_limit;
  }
  if (std::all_of(f.begin(), f.end(), [](double b) { return b <= 0.0; })) {
    result = frictionless(given_increment, modes, solver);
    return;
  }

  InnerResult& first = work.first;
  first.tau.clear();
  first.shift_undetermined = false;
  reset_keeping_storage(first.report);
  first.report.requested = to_string(solver.backend);
  first.report.operator_kind = sparse ? "sparse+" + sparse->halfspace->kind() : Ct->kind();
  first.increment = given_increment;
  AttemptLedger<InnerResult>& ledger = work.ledger;
  ledger.restart(first);
  // The condensed program: the same program with the body's rows eliminated (Q the condensed
  // compliance, no block); the program itself when it has no block (no copy).
  ScaledOperator condensed_q(*Ct, 1.0 / ct0);
  QuadraticProgram sparse_condensed;
  if (sparse) {
    sparse_condensed = qp;
    sparse_condensed.Q = &condensed_q;
    sparse_condensed.block = nullptr;
    sparse_condensed.preconditioner = nullptr;
  }
  const QuadraticProgram& condensed = sparse ? sparse_condensed : qp;
  // A point of the program (x, its equality multipliers) as tractions and rigid increments,
  // certified on the condensed compliances.
  const auto certify_point = [&](const std::vector<double>& x, const std::vector<double>& multipliers,
                                 InnerResult& trial) {
    SolverReport& rep = trial.report;
    trial.increment = given_increment;
    trial.tau.assign(n, 0.0);
    for (std::size_t l = 0; l < Nw; ++l)
      for (int c = 0; c < comps; ++c) trial.tau[c * N + element(l)] = x[c * Nw + l] * f_ref;
    // Project onto the friction set (interior-point iterates may sit a hair outside).
    for (std::size_t e = 0; e < N; ++e) {
      double m2 = 0.0;
      for (int c = 0; c < comps; ++c) m2 += trial.tau[c * N + e] * trial.tau[c * N + e];
      const double mag = std::sqrt(m2);
      if (mag > f[e])
        for (int c = 0; c < comps; ++c) trial.tau[c * N + e] *= f[e] > 0.0 ? f[e] / mag : 0.0;
    }
    for (std::size_t r = 0; r < row_mode.size() && r < multipliers.size(); ++r)
      // Stationarity: (Ct tau + W)/(ct0 f_ref) + alpha m/(ct0 f_ref) = lambda a, a = m A f_ref / S
      trial.increment[row_mode[r]] = -multipliers[r] * A * f_ref * f_ref * ct0 / row_scale[r];
    // Our own certificate decides, as for the normal problem: `auto` falls back on it.
    // On a window the slip is computed there alone: tau = 0 and f = 0 outside, where the
    // certificate does not look at the slip (certify_friction).
    if (ops)
      windowed_slip_increment(W, trial.tau, window, *ops->compliance, trial.increment, work.ds);
    else
      slip_increment(W, trial.tau, trial.increment, work.ds, work.ct_tau);
    rep.certificate = step_certificate(trial.tau, work.ds, f, modes);
    const bool certified = rep.certificate.worst() <= solver.certificate_tol;
    rep.status = certified ? SolveStatus::converged : SolveStatus::not_converged;
  };
  // One backend on a program (the sparse form's or the condensed one), certified; the ledger
  // keeps the first certified result, else the best certificate.
  const auto attempt = [&](const std::string& backend, const QuadraticProgram& program, bool fallback,
                           const std::string& label) {
    TimedOutcome& run = work.run;
    run_backend(backend, program, options, native_solver, run);
    const SolveOutcome& out = run.outcome;
    InnerResult& trial = work.trial;
    trial = first;
    SolverReport& rep = trial.report;
    rep.operator_kind = program.block ? "sparse+" + sparse->halfspace->kind() : Ct->kind();
    rep.backend = label;
    rep.fallback_used = fallback;
    rep.message = out.message;
    rep.iterations = out.iterations;
    rep.polished = out.polished;
    rep.time_s = run.time_s;
    rep.objective = out.objective * ct0 * f_ref * f_ref * A;
    rep.status = SolveStatus::failed;
    const bool has_point = out.x.size() == nw;
    if (has_point) {
      certify_point(out.x, out.equality_multipliers, trial);
      // Polished on the condensed program: its KKT residual is the friction law's (the same
      // compliance ct0 and level f_ref); each active set's solves cost some hundred applies,
      // each a pair of triangular solves on a finite body.
      const auto polished = finish_backend_point(backend, out, condensed, solver.certificate_tol, trial, certify_point);
      if (polished) rep.objective = condensed.objective(polished->data()) * ct0 * f_ref * f_ref * A;
    }
    ledger.record_swapping(trial, has_point, out.history);
  };
  std::vector<std::string>& order = work.order;
  if (sparse)
    order = sparse->backends(solver.backend, solver.fallback);
  else
    backend_order(solver.backend, native_first || native_first_always ? std::numeric_limits<std::size_t>::max() : n,
                  solver.fallback, order);
  for (std::size_t k = 0; k < order.size() && !ledger.converged(); ++k) attempt(order[k], qp, k > 0, order[k]);
  // The sparse form failed with `auto`: the same program with the body's rows eliminated (Q the
  // condensed compliance, no block), as for the normal problem (FiniteContact::solve_sparse).
  if (sparse && sparse->condensed_fallback && !ledger.converged() && solver.backend == Backend::automatic &&
      solver.fallback) {
    for (const char* backend : {"native", "nlopt"}) {
      attempt(backend, condensed, true, std::string(backend) + " (condensed program)");
      if (ledger.converged()) break;
    }
  }
  ledger.finish_into(result);
  if (result.tau.empty()) result.tau.assign(n, 0.0);  // every backend failed: nothing to keep
}

/// No friction anywhere (f(p) = 0: mu = 0): nothing to solve, tau = 0. Only zero resultants
/// reach here (check_resultants); the rigid increment of a resultant-controlled mode is then
/// undetermined (any shift leaves tau = 0) and reported as 0.
TangentialProblem::Impl::InnerResult TangentialProblem::Impl::frictionless(const std::array<double, 3>& given_increment,
                                                                    const std::array<ModeControl, 3>& modes,
                                                                    const SolverOptions& solver) const {
  InnerResult r;
  r.tau.assign(comps * N, 0.0);
  r.increment = given_increment;
  r.report.backend = "none";
  r.report.requested = to_string(solver.backend);
  r.report.operator_kind = Ct->kind();
  r.report.status = SolveStatus::converged;
  r.report.message = "no friction (f(p) = 0 over the whole contact): zero traction, nothing to solve";
  r.shift_undetermined = std::any_of(modes.begin(), modes.begin() + n_modes(), [](const ModeControl& m) {
    return m.kind == ModeControl::Kind::resultant;
  });
  if (r.shift_undetermined)
    r.report.message += "; the rigid shift is undetermined (any shift leaves the traction at 0; reported as 0)";
  return r;
}

}  // namespace dc
