// TangentialProblem::Impl: steady rolling (2.19), solved directly by Newton's method inside the
// outer loop (steady_rolling_solver.hpp), and rolling by marching in time, each step one program
// (3.8)/(4.4)-(4.6) with the previous displacement taken upstream ((2.14), B* of (4.6)).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "backend_choice.hpp"
#include "errors.hpp"
#include "steady_rolling_solver.hpp"
#include "tangential_problem_impl.hpp"

namespace dc {

using tangential_internal::relative_change;

/// Steady rolling solved directly (steady_rolling_solver.hpp) inside the outer loop; the
/// slip per step of travel dx is ds = dx v_rigid + (C - S C) tau (+ kappa (B21 - S B21) p).
/// Into `sol` (its storage kept, as the program's, the outcome's and the solver's: a dynamic
/// run's steady model solves at every step); false when Newton's method gives up (why_not; the
/// caller then marches).
bool TangentialProblem::Impl::steady_rolling_direct(const RollingLoad& load,
                                                    const std::array<double, 3>& given_increment,
                                                    const SolverOptions& solver, const ProgressCallback& progress,
                                                    std::string& why_not, TangentialSolution& sol) {
  if (!D_conv) D_conv = half_space->tangential_convective(1, kind);
  if (coupled && !B21_up) B21_up = half_space->tangential_from_normal_shifted(1, 0, kind);
  const std::size_t n = comps * N;
  reset_keeping_storage(sol);
  SteadyWork& work = steady_work;
  SteadyRollingProgram& program = work.program;
  program.D = D_conv.get();
  program.comps = comps;
  program.area = grid.area();
  program.modes.clear();
  program.resultants.clear();
  std::vector<int>& unknown_modes = work.unknown_modes;
  unknown_modes.clear();
  for (int k = 0; k < n_modes(); ++k) {
    if (load.modes[k].kind != ModeControl::Kind::resultant) continue;
    std::vector<double> m(n);
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c) m[c * N + e] = mode(k, e, c);
    program.modes.push_back(std::move(m));
    program.resultants.push_back(load.modes[k].value);
    unknown_modes.push_back(k);
  }
  SolveOptions options = solve_options(solver, progress);
  options.max_iter = std::min(solver.max_iter, 200);
  std::vector<double>& tau = step_tau;
  if (load.warm_start.size() == n) tau = load.warm_start;
  else tau.assign(n, 0.0);
  std::vector<double>& f = step_f;
  SteadyRollingOutcome& outcome = work.outcome;
  outcome.message.clear();
  int newton = 0, applies = 0;
  const auto start = std::chrono::steady_clock::now();
  // What the inner solve reads, behind one pointer (a closure of two pointers is held by
  // std::function without an allocation).
  struct Pass {
    const RollingLoad& load;
    const std::array<double, 3>& given_increment;
    const SolveOptions& options;
    int& newton;
    int& applies;
  } pass_data{load, given_increment, options, newton, applies};
  const bool ok = outer_loop(
      sol, load.normal, solver, tau, f, false,
      [this, &pass_data](const std::vector<double>& p, const std::vector<double>& bound, std::vector<double>& t,
                         const SolverOptions&) {
        SteadyRollingProgram& prog = steady_work.program;
        SteadyRollingOutcome& out = steady_work.outcome;
        const std::size_t m = comps * N;
        prog.b.assign(m, 0.0);
        for (std::size_t e = 0; e < N; ++e)
          for (int c = 0; c < comps; ++c)
            for (int k = 0; k < n_modes(); ++k) prog.b[c * N + e] += pass_data.given_increment[k] * mode(k, e, c);
        if (coupled) {
          std::vector<double>&w_here = steady_work.w_here, &w_up = steady_work.w_up;
          B21->apply(p, w_here);
          B21_up->apply(p, w_up);
          for (std::size_t i = 0; i < m; ++i) prog.b[i] += w_here[i] - w_up[i];
        }
        check_resultants(bound, pass_data.load.modes);
        if (std::all_of(bound.begin(), bound.end(), [](double b) { return b <= 0.0; })) {
          out.message = "no friction (f(p) = 0 over the whole contact)";
          return false;
        }
        prog.bound = bound;
        prog.tau0 = t;
        solve_steady_rolling(prog, pass_data.options, steady_work.solver, out);
        pass_data.newton += out.newton_iterations;
        pass_data.applies += out.operator_applies;
        if (!out.success) return false;
        t = out.tau;
        return true;
      });
  if (!ok) {
    why_not = outcome.message;
    return false;
  }
  std::array<double, 3> amplitudes = given_increment;
  for (std::size_t r = 0; r < unknown_modes.size(); ++r) amplitudes[unknown_modes[r]] = outcome.amplitudes[r];
  std::vector<double>& ds = step_ds;
  D_conv->apply(tau, ds);
  // The elastic part of the slip: D tau and the kappa term (in b with the given rigid slip).
  double elastic_work = 0.0;
  for (std::size_t e = 0; e < N; ++e)
    for (int c = 0; c < comps; ++c) {
      double given = 0.0;
      for (int k = 0; k < n_modes(); ++k) given += given_increment[k] * mode(k, e, c);
      elastic_work += tau[c * N + e] * (ds[c * N + e] + program.b[c * N + e] - given);
    }
  for (std::size_t i = 0; i < n; ++i) ds[i] += program.b[i];
  for (std::size_t r = 0; r < program.modes.size(); ++r)
    for (std::size_t i = 0; i < n; ++i) ds[i] += outcome.amplitudes[r] * program.modes[r][i];
  sol.report.requested = to_string(solver.backend);
  sol.report.backend = "native";
  sol.report.operator_kind = D_conv->kind();
  sol.report.status = SolveStatus::converged;
  sol.report.iterations = applies;
  sol.newton_iterations = newton;
  sol.report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char message[96];
  std::snprintf(message, sizeof message, "steady rolling by Newton: %d iterations, %d operator applies", newton,
                applies);
  sol.report.message.assign(message);
  finish(sol, tau, ds, f, load.modes, solver);
  tau_prev = tau;
  p_prev = sol.normal.pressure;
  displacement_prev.clear();  // not computed here: a later convected step applies the operators
  sol.amplitudes = amplitudes;
  sol.convective_elastic_work = elastic_work * grid.area();
  return true;
}

/// Rolling in +x from the current state: up to `max_steps` marching steps of dx (dt = dx / V).
/// Each step is one program (3.8)/(4.4)-(4.6): the convective term dt (V . grad)(u+ - u-) of
/// (2.14) is the difference between the displacement here and the previous one taken at the
/// upstream material point (B* of (4.6) through Ct_up, the kappa term of (4.5) through B21_up).
/// Stops after a step that changes tau by less than `steady_tol` (0: never), or fails. The
/// total rigid slip accumulates in amplitude_prev.
TangentialProblem::Impl::March TangentialProblem::Impl::march(const RollingLoad& load, int max_steps, double steady_tol,
                                                       const SolverOptions& solver, const ProgressCallback& progress) {
  if (!(load.velocity > 0.0)) throw InputError("tangential.velocity", "the rolling speed must be positive");
  // Rolling in +x: the material now at x was at x + dx one step (dt = dx / V) earlier.
  if (!Ct_up) {
    Ct_up = half_space->tangential_shifted(1, 0, kind);
    if (coupled) B21_up = half_space->tangential_from_normal_shifted(1, 0, kind);
  }
  // Per step the rigid slip is v dt = dx (creepage - phi y, eta + phi x): increments dx * mode.
  std::array<double, 3> increment{};
  for (int k = 0; k < 3; ++k)
    if (load.modes[k].kind == ModeControl::Kind::amplitude) increment[k] = grid.dx * load.modes[k].value;
  // auto: every step is one warm-started program, where the native solver is much the
  // fastest at any size (the others remain its fallbacks).
  const SolverOptions& step_solver = solver;
  native_first = true;
  struct Restore {
    bool& flag;
    ~Restore() { flag = false; }
  } restore{native_first};
  March m;
  for (m.steps = 1; m.steps <= max_steps; ++m.steps) {
    const std::vector<double> input = tau_prev;
    solve_step(load.normal, load.modes, increment, {1.0, 0.0}, step_solver, {}, m.sol);
    if (m.sol.report.status != SolveStatus::converged && m.first_unconverged == 0) m.first_unconverged = m.steps;
    if (m.sol.report.status == SolveStatus::failed) break;
    m.frictional_work += frictional_work(m.sol, grid.area());
    for (int k = 0; k < 3; ++k) amplitude_prev[k] += m.sol.amplitudes[k];
    const double change = relative_change(tau_prev, input);
    if (progress) progress({m.steps, 0.0, change, steady_tol});
    if (steady_tol > 0.0 && m.steps > 1 && change < steady_tol) {
      m.steady = true;
      break;
    }
  }
  m.steps = std::min(m.steps, max_steps);
  return m;
}

}  // namespace dc
