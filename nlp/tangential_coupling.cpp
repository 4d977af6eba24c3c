// TangentialProblem::Impl: the outer loop (4.26)-(4.27) / (3.31)-(3.32), normal and tangential
// problems alternated with Anderson mixing of the gap shift kappa B32 tau, the cached normal
// solve, and one quasi-static or convected step (3.8) with W of (4.27) around it.
#include <algorithm>
#include <cmath>
#include <utility>

#include "anderson_mixing.hpp"
#include "errors.hpp"
#include "fault_injection.hpp"
#include "tangential_problem_impl.hpp"
#include "vector_ops.hpp"

namespace dc {

using tangential_internal::relative_change;

/// The normal problem at the heights h, from the cache when it was solved for the same.
const NormalSolution& TangentialProblem::Impl::solve_normal(const std::vector<double>& h, const NormalSpec& load,
                                                            const SolverOptions& solver) {
  if (normal_cache && normal_cache_load.control == load.control && normal_cache_load.value == load.value &&
      normal_cache_tol == solver.tol &&
      normal_cache_heights == h)
    return *normal_cache;
  normal->set_heights(h);
  normal->set_native_first(native_first || native_first_always);
  normal_cache_heights.clear();  // no key while the cache is being written (a throw leaves it unmatched)
  if (!normal_cache) normal_cache.emplace();
  if (sparse)
    *normal_cache = sparse->normal(h, load, solver);
  else
    normal->solve(load, solver, *normal_cache);  // into the cache's own storage
  // A failed solve is not kept: the same call (after reset(), or once a backend recovers) tries again.
  if (normal_cache->report.status == SolveStatus::failed) return *normal_cache;
  normal_cache_heights = h;
  normal_cache_load = load;
  normal_cache_tol = solver.tol;
  return *normal_cache;
}

/// The outer loop (4.26)-(4.27) / (3.31)-(3.32) around an inner tangential solve: the pressure
/// with the gap shifted by kappa B32 tau of the previous iterate, the bound f(p), then
/// `inner(p, f, tau)` updates tau (false: it gave up, the loop stops and returns false).
/// kappa = 0: p does not depend on tau, so f(p) is final after one pass.
/// kappa != 0: the alternation is a fixed point s = G(s) of the gap shift s = kappa B32 tau fed
/// to (4.26), accelerated by Anderson mixing of s (N values, in the units of the stopping
/// test; one B32 apply per pass); both problems start from the previous step's solution (warm).
/// It stops on the certificate: the pressure was solved with kappa B32 tau_in, and the new
/// tau moves that gap by kappa B32 (tau - tau_in); once this is below a hundredth of
/// certificate_tol (in the certificate's units, gap / C_00 / max p), the pressure is certified
/// again with the final tau (certify_with_final_traction), so p and tau certify together.
/// `inexact` (the inner solve honours the pass's SolverOptions): while the coupling residual is
/// large, both problems are solved only to a tenth of it (at most 1e-3, at least solver.tol):
/// the next pass changes their data by about that residual anyway. The loop stops only after
/// a pass at solver.tol, so the answer and its certificate are those of exact solves.
/// The mixing's history holds exact passes only: a loose pass's pair is not a point of G (a
/// warm start within its tolerance comes back unchanged, a residual of 0 that Anderson would
/// steer back to), so the history starts again at the first exact pass. A stall (p and tau
/// unchanged while the residual is above coupling_tol) ends the loop only after a plain step.
bool TangentialProblem::Impl::outer_loop(TangentialSolution& sol, const NormalSpec& normal_load,
                                         const SolverOptions& solver, std::vector<double>& tau, std::vector<double>& f,
                                         bool inexact, const InnerSolve& inner) {
  // The gap shift kappa B32 tau_in fed to (4.26) and the one of the new tau (the loop's work
  // vectors are the Impl's: a dynamic run's steps allocate none of them).
  std::vector<double>&p_old = loop_p_old, &tau_old = loop_tau_old, &shift_in = loop_shift_in,
                      &shift_out = loop_shift_out;
  p_old.clear();
  tau_old.clear();
  f.assign(N, 0.0);
  const bool stall = injected_fault("outer") != Fault::none;  // test-only: a loop that never settles
  const int max_outer = coupled ? (stall ? 3 : 100) : 1;
  const double outer_tol = std::max(1e-9, 10.0 * solver.tol);
  const double c0 = C->diagonal(0);
  const double coupling_tol = 0.01 * solver.certificate_tol;
  AndersonMixing& mixer = loop_mixer;
  mixer.reset();
  SolverOptions pass = solver;
  // A start from a solve at nearby data (set_near_start) is within a loose pass's tolerance:
  // such a pass would return it unchanged, so the first pass is exact.
  if (coupled && inexact && !near_start) pass = loose_pass(solver, 1e-3);
  near_start = false;
  double last_gap = 0.0;
  int pairs = 0;           // passes in the mixing's history
  bool mixed = false;      // shift_in came from the mixing of two or more passes
  bool was_exact = false;  // the previous pass was exact
  // kappa B32 of the start: kept from the last loop when the start is its final traction (the
  // next Newton trial or step of a dynamic run).
  if (coupled) {
    if (tau == shift_source) shift_in = shift_of_source;
    else B32->apply(tau, shift_in);
  }
  for (int m = 1; m <= max_outer; ++m) {
    std::vector<double>& h = pass_heights;  // (4.26)
    h = heights;
    if (coupled)
      for (std::size_t i = 0; i < N; ++i) h[i] += shift_in[i];
    const bool exact_pass = pass.tol == solver.tol;
    sol.normal = solve_normal(h, normal_load, pass);
    if (sol.normal.report.status == SolveStatus::failed)
      throw SolverFailure("the normal problem failed, so the tangential one cannot be set up: " +
                          sol.normal.report.message);
    const std::vector<double>& p = sol.normal.pressure;
    // (3.32): the friction bound from this pressure; noise-level pressures carry none.
    const double p_cut = 1e-9 * max_abs(p);
    for (std::size_t e = 0; e < N; ++e) f[e] = p[e] > p_cut ? friction.bound(p[e]) : 0.0;
    if (!inner(p, f, tau, pass)) return false;
    tau_warm = tau;
    const double change = std::max(relative_change(p, p_old), relative_change(tau, tau_old));
    sol.outer.iterations = m;
    sol.outer.last_change = m == 1 ? 0.0 : change;
    p_old = p;
    tau_old = tau;
    if (max_outer == 1) break;
    // The gap error the last tau leaves in the pressure's problem (certificate units).
    B32->apply(tau, shift_out);
    double gap_error = 0.0;
    for (std::size_t i = 0; i < N; ++i)
      if (std::isfinite(heights[i])) gap_error = std::max(gap_error, std::abs(shift_out[i] - shift_in[i]));
    const double p_max = max_abs(p);
    gap_error /= c0 * (p_max > 0.0 ? p_max : 1.0);
    sol.outer.coupling_residual = gap_error;
    if (m == 1) sol.outer.first_residual = gap_error;
    shift_source = tau;  // shift_out = kappa B32 tau
    shift_of_source = shift_out;
    const bool stalled = m > 1 && change < outer_tol;
    if (!stall && exact_pass && (gap_error <= coupling_tol || (stalled && !mixed))) {
      certify_with_final_traction(sol, shift_out, normal_load);
      break;
    }
    if (m == max_outer) {
      sol.outer.converged = false;
      sol.outer.last_change = change;
      break;
    }
    if (exact_pass && (!was_exact || stalled)) {
      mixer.reset();
      pairs = 0;
    }
    was_exact = exact_pass;
    mixed = ++pairs > 1;
    mixer.next(shift_in, shift_out, shift_in);
    // The next pass is exact once it is expected to end the loop (the residual contracts by
    // the last pass's factor), and so is the last pass allowed: an unsettled loop reports
    // exact solves' last iterate.
    const double contraction = std::clamp(m > 1 ? gap_error / last_gap : 0.5, 0.01, 1.0);
    last_gap = gap_error;
    if (!exact_pass)
      pass = gap_error * contraction <= coupling_tol || m + 1 == max_outer ? solver
                                                                           : loose_pass(solver, 0.1 * gap_error);
  }
  return true;
}

/// kappa != 0: the pressure was solved with the gap shifted by kappa B32 tau_in; its
/// certificate becomes that of the gap (4.26) with the final tau (shift_out = kappa B32 tau),
/// so that the coupling residual is measured, not assumed (one apply of C).
void TangentialProblem::Impl::certify_with_final_traction(TangentialSolution& sol, const std::vector<double>& shift_out,
                                                          const NormalSpec& normal_load) {
  std::vector<double>& h = final_heights_work;
  h = heights;
  for (std::size_t i = 0; i < N; ++i) h[i] += shift_out[i];
  normal->set_heights(h);
  const Certificate c = normal->certify(sol.normal.pressure, sol.normal.approach, normal_load);
  Certificate& cert = sol.normal.report.certificate;
  cert.complementarity = c.complementarity;
  cert.gap_violation = c.gap_violation;
  normal->set_heights(normal_cache_heights);  // the heights of the last solve, as the cache says
}

/// The solver of an inexact alternation: tolerance `tol` (between solver.tol and 1e-3), and a
/// certificate tolerance that such a solve can meet (the backends fall back on it).
SolverOptions TangentialProblem::Impl::loose_pass(const SolverOptions& solver, double tol) {
  SolverOptions pass = solver;
  pass.tol = std::clamp(tol, solver.tol, std::max(solver.tol, 1e-3));
  pass.certificate_tol = std::max(solver.certificate_tol, 100.0 * pass.tol);
  return pass;
}

/// One step with the outer loop (4.26)-(4.27) / (3.31)-(3.32); rigid slips are increments.
/// `shift` (elements along x and y) is the travel of the step: (0, 0) quasi-static, (1, 0) a
/// marching step. It enters through W alone (the previous displacement at the upstream point),
/// so the slip ds = W + rigid + Ct tau and the gap function (4.24)-(4.25) of the certificate
/// are those of the convected step.
void TangentialProblem::Impl::solve_step(const NormalSpec& normal_load, const std::array<ModeControl, 3>& modes,
                                         const std::array<double, 3>& given_increment,
                                         const std::array<double, 2>& shift, const SolverOptions& solver,
                                         const ProgressCallback& progress, TangentialSolution& sol) {
  const std::size_t n = comps * N;
  reset_keeping_storage(sol);
  // The step's vectors are the Impl's (no allocation once sized).
  std::vector<double>&u_prev = step_u_prev, &W = step_W, &w21 = step_w21, &f = step_f;
  const bool marching = shift[0] == 1.0 && shift[1] == 0.0 && Ct_up;
  if (marching) {
    memory_beyond_grid.clear();
    displacement(p_prev, tau_prev, u_prev, *Ct_up, B21_up.get());
  } else {
    convected_displacement(shift[0], shift[1], u_prev);
  }

  std::vector<double>& tau = step_tau;
  if (tau_warm.size() == n) tau = tau_warm;
  else tau.assign(n, 0.0);
  W.resize(n);
  InnerResult& inner = step_inner;
  // What the inner solve reads, behind one pointer (a closure of two pointers is held by
  // std::function without an allocation).
  struct Pass {
    const std::array<ModeControl, 3>& modes;
    const std::array<double, 3>& given_increment;
    const std::array<double, 2>& shift;
    const ProgressCallback& progress;
  } pass_data{modes, given_increment, shift, progress};
  outer_loop(sol, normal_load, solver, tau, f, true,
             [this, &pass_data](const std::vector<double>& p, const std::vector<double>& bound, std::vector<double>& t,
                           const SolverOptions& pass) {
               std::vector<double>&u = step_u_prev, &Wp = step_W, &w = step_w21;
               const std::size_t m = comps * N;
               // Where friction acts, the memory must be exact: an element whose interpolated
               // memory needed a value beyond the grid's edge takes the apply's.
               if (!memory_beyond_grid.empty() &&
                   std::any_of(memory_beyond_grid.begin(), memory_beyond_grid.end(),
                               [&](std::size_t e) { return bound[e] > 0.0; }))
                 convected_displacement(pass_data.shift[0], pass_data.shift[1], u, true);
               // (4.27): W = kappa B21 p - u_prev.
               for (std::size_t i = 0; i < m; ++i) Wp[i] = -u[i];
               if (coupled) {
                 B21->apply(p, w);
                 for (std::size_t i = 0; i < m; ++i) Wp[i] += w[i];
               }
               solve_tangential(Wp, bound, pass_data.modes, pass_data.given_increment, pass, pass_data.progress, step_inner);
               t = step_inner.tau;
               return true;
             });
  // Results: slip increment ds = W + rigid + Ct tau (3.8), certificate, states.
  std::vector<double>& ds = step_ds;
  slip_increment(W, tau, inner.increment, ds, displacement_prev);
  sol.report = inner.report;
  sol.shift_undetermined = inner.shift_undetermined;
  finish(sol, tau, ds, f, modes, solver);
  // Remember the state for the next step, with its relative displacement kappa B21 p + B22 tau
  // (Ct tau from the slip and the last pass's kappa B21 p, of the final pressure): the next
  // step's convected memory.
  tau_prev = tau;
  p_prev = sol.normal.pressure;
  if (coupled)
    for (std::size_t i = 0; i < n; ++i) displacement_prev[i] += w21[i];
  sol.amplitudes = inner.increment;
}

}  // namespace dc
