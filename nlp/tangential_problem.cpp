// TangentialProblem (tangential_problem.hpp): the public API over TangentialProblem::Impl
// (tangential_problem_impl.hpp) and the loading history: quasi-static steps (4.8) with the
// proportional predictor, steady rolling and rolling over a distance, convected steps,
// memory / restore, the compliances.
#include "tangential_problem.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "errors.hpp"
#include "kept_storage.hpp"
#include "tangential_problem_impl.hpp"

namespace dc {

void TangentialProblem::Impl::reset() {
  tau_prev.assign(comps * N, 0.0);
  p_prev.assign(N, 0.0);
  amplitude_prev = {0.0, 0.0, 0.0};
  displacement_prev.assign(comps * N, 0.0);  // of no traction
  tau_warm.clear();
  predictor.clear();
}

TangentialProblem::TangentialProblem(const Grid& grid, const MaterialPair& materials, std::vector<double> heights,
                                     FrictionLaw friction, OperatorKind kind)
    : impl_(std::make_shared<Impl>(grid, materials, std::move(heights), std::move(friction), kind)), grid_(grid) {}

void TangentialProblem::forget_starting_points() {
  impl_->tau_warm.clear();
  impl_->predictor.clear();
  impl_->normal->clear_warm_start();
  impl_->normal_cache.reset();
}

TangentialProblem::TangentialProblem(const Grid& grid, std::shared_ptr<const LinearOperator> normal_compliance,
                                     std::shared_ptr<const LinearOperator> tangential_compliance,
                                     std::vector<double> heights, FrictionLaw friction)
    : impl_(std::make_shared<Impl>(grid, std::move(normal_compliance), std::move(tangential_compliance),
                                   std::move(heights), std::move(friction))),
      grid_(grid) {}

void TangentialProblem::reset() { impl_->reset(); }

void TangentialProblem::set_extrapolation(bool on) { impl_->extrapolate = on; }

void TangentialProblem::set_windowing(bool on) { impl_->windowing = on; }

void TangentialProblem::set_native_first(bool on) { impl_->native_first_always = on; }

void TangentialProblem::set_exact_hessian_limit(int elements) {
  impl_->exact_hessian_limit = impl_->comps * elements;
  impl_->normal->set_exact_hessian_limit(elements);
}

void TangentialProblem::use_sparse_form(SparseTangentialForm form) {
  if (!impl_->given_operators) throw std::logic_error("tangential problem: the sparse form needs given compliances");
  impl_->sparse = std::move(form);
  impl_->normal_cache.reset();
}

TangentialSolution TangentialProblem::step(const TangentialLoad& load, const SolverOptions& solver,
                                           const ProgressCallback& progress) {
  Impl& s = *impl_;
  if (s.grid.dimension == 2)
    for (int k = 1; k < 3; ++k)
      if (load.modes[k].value != 0.0)
        throw InputError("tangential", "a 2-D problem has no y shift and no rotation about z");
  std::array<double, 3> increment{};
  for (int k = 0; k < 3; ++k)
    if (load.modes[k].kind == ModeControl::Kind::amplitude) increment[k] = load.modes[k].value - s.amplitude_prev[k];
  // kappa != 0: a history loaded in proportion starts its alternation from the extrapolated state.
  ProportionalPredictor::Load key;
  key.values.push_back(load.normal.value);
  key.kinds.push_back(static_cast<int>(load.normal.control));
  for (int k = 0; k < 3; ++k) {
    key.values.push_back(load.modes[k].value);
    key.kinds.push_back(static_cast<int>(load.modes[k].kind));
  }
  std::vector<double> tau_start, p_start;
  if (s.coupled && s.extrapolate && s.predictor.predict(key, tau_start, p_start)) {
    s.tau_warm = std::move(tau_start);
    s.normal->set_warm_start(std::move(p_start));
  }
  TangentialSolution sol;
  s.solve_step(load.normal, load.modes, increment, {0.0, 0.0}, solver, progress, sol);
  for (int k = 0; k < 3; ++k) sol.amplitudes[k] += s.amplitude_prev[k];
  s.amplitude_prev = sol.amplitudes;
  if (s.coupled && sol.report.status == SolveStatus::converged)
    s.predictor.record(key, s.tau_prev, s.p_prev);
  else
    s.predictor.clear();
  return sol;
}

TangentialSolution TangentialProblem::steady_rolling(const RollingLoad& load, const SolverOptions& solver,
                                                     const ProgressCallback& progress) {
  TangentialSolution solution;
  steady_rolling(load, solver, solution, progress);
  return solution;
}

void TangentialProblem::steady_rolling(const RollingLoad& load, const SolverOptions& solver, TangentialSolution& out,
                                       const ProgressCallback& progress) {
  Impl& s = *impl_;
  if (s.given_operators) throw InputError("tangential.regime", "rolling is not available for a finite body");
  s.reset();
  if (!(load.velocity > 0.0)) throw InputError("tangential.velocity", "the rolling speed must be positive");
  // auto / native: the steady state directly (Newton); the convex-program backends, or Newton
  // giving up, march in time. Per step of travel dx the rigid slip is dx (creepage - phi y,
  // eta + phi x): increments dx * mode.
  using Method = RollingLoad::Method;
  std::string direct_failure;
  const bool newton = load.method == Method::newton ||
                      (load.method == Method::automatic &&
                       (solver.backend == Backend::automatic || solver.backend == Backend::native));
  if (newton) {
    std::array<double, 3> increment{};
    for (int k = 0; k < 3; ++k)
      if (load.modes[k].kind == ModeControl::Kind::amplitude) increment[k] = s.grid.dx * load.modes[k].value;
    // Into `out`'s own storage (a dynamic run's steady model solves at every step).
    const bool direct = s.steady_rolling_direct(load, increment, solver, progress, direct_failure, out);
    if (direct || load.method == Method::newton) {
      if (!direct) {
        reset_keeping_storage(out);
        out.report.status = SolveStatus::failed;
        out.report.message = "steady rolling by Newton failed: " + direct_failure;
      }
      for (int k = 0; k < 3; ++k) out.amplitudes[k] /= s.grid.dx;
      out.rolling = true;
      return;
    }
    s.reset();
  }
  const int max_steps = load.max_steps > 0 ? load.max_steps : 10 * s.grid.nx;
  // Marching (the previous traction taken upstream) converges geometrically to the steady
  // state; stop when a step changes tau by less than the certificate tolerance, then prove the
  // steady state with the certificate of the steady slip ds = dx v + (C - S C) tau (2.19).
  const double steady_tol = std::max(0.01 * solver.certificate_tol, 10.0 * solver.tol);
  Impl::March march = s.march(load, max_steps, steady_tol, solver, progress);
  TangentialSolution& sol = march.sol;
  const int steps = march.steps;
  const bool steady = march.steady;
  if (sol.report.status != SolveStatus::failed) {
    // Steady slip with the same tau upstream and here (no lag): certificate of (2.19).
    std::vector<double> u_here, u_up;
    s.displacement(s.p_prev, s.tau_prev, u_here, *s.Ct, s.B21.get());
    s.displacement(s.p_prev, s.tau_prev, u_up, *s.Ct_up, s.B21_up.get());
    const std::size_t N = s.N;
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < s.comps; ++c) {
        double rigid = 0.0;
        for (int k = 0; k < s.n_modes(); ++k) rigid += sol.amplitudes[k] * s.mode(k, e, c);
        const double ds = rigid + u_here[c * N + e] - u_up[c * N + e];
        (c == 0 ? sol.sx : sol.sy)[e] = ds;
      }
    sol.convective_elastic_work = 0.0;
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < s.comps; ++c)
        sol.convective_elastic_work +=
            (c == 0 ? sol.tx : sol.ty)[e] * (u_here[c * N + e] - u_up[c * N + e]) * s.grid.area();
    const Certificate steady_cert =
        certify_friction(s.grid, sol.tx, sol.ty, sol.sx, sol.sy, sol.bound, s.Ct->diagonal(0));
    sol.report.certificate.friction_law = steady_cert.friction_law;
    sol.report.certificate.gap_function = steady_cert.gap_function;
    const bool certified = sol.report.certificate.worst() <= solver.certificate_tol;
    if (sol.report.status == SolveStatus::converged && !certified) {
      sol.report.status = SolveStatus::not_converged;
      sol.report.message += " [steady-state certificate " + format_number(sol.report.certificate.worst()) +
                            " exceeds the tolerance]";
    }
  }
  sol.marching_steps = std::min(steps, max_steps);
  sol.rolling = true;
  if (!direct_failure.empty()) {
    sol.report.fallback_used = true;
    sol.report.message += " [steady Newton gave up (" + direct_failure + "): marched instead]";
  }
  // Amplitudes as creepages / spin (per unit rolling distance).
  for (int k = 0; k < 3; ++k) sol.amplitudes[k] /= s.grid.dx;
  if (!steady && sol.report.status == SolveStatus::converged) {
    sol.report.status = SolveStatus::not_converged;
    sol.report.message += " [rolling did not reach a steady state in " + std::to_string(max_steps) + " steps]";
  }
  out = std::move(sol);
}

double frictional_work(const TangentialSolution& s, double area) {
  double work = 0.0;
  for (std::size_t e = 0; e < s.tx.size(); ++e) {
    double power = s.tx[e] * (e < s.sx.size() ? s.sx[e] : 0.0);
    if (e < s.ty.size() && e < s.sy.size()) power += s.ty[e] * s.sy[e];
    work -= power;
  }
  return work * area;
}

TangentialSolution TangentialProblem::roll(const RollingLoad& load, double distance, const SolverOptions& solver,
                                           const ProgressCallback& progress) {
  Impl& s = *impl_;
  if (s.given_operators) throw InputError("tangential.regime", "rolling is not available for a finite body");
  if (!std::isfinite(distance) || distance < 0.0)
    throw InputError("tangential.distance", "the rolling distance must be a finite length >= 0 (m)");
  s.predictor.clear();  // rolling continues no quasi-static history
  if (distance == 0.0) {
    // No travel, no convective term: the quasi-static step (2.16) of the same controls; a
    // creepage applies no rigid slip over zero distance, a prescribed force is carried by a shift.
    if (!(load.velocity > 0.0)) throw InputError("tangential.velocity", "the rolling speed must be positive");
    TangentialSolution sol;
    s.solve_step(load.normal, load.modes, {0.0, 0.0, 0.0}, {0.0, 0.0}, solver, progress, sol);
    for (int k = 0; k < 3; ++k) s.amplitude_prev[k] += sol.amplitudes[k];
    return sol;  // amplitudes: the rigid shift (m, m, rad) of this step; marching_steps = 0
  }
  // At least one marching step; otherwise the nearest whole number of elements.
  const double steps = std::max(1.0, std::round(distance / s.grid.dx));
  if (steps > 1e8) throw InputError("tangential.distance", "over 1e8 marching steps of one element each");
  const int n = static_cast<int>(steps);
  Impl::March march = s.march(load, n, 0.0, solver, progress);
  TangentialSolution& sol = march.sol;
  sol.marching_steps = march.steps;
  sol.rolling = true;
  sol.distance = march.steps * s.grid.dx;
  sol.marched_frictional_work = march.frictional_work;
  // The path matters in a transient: one uncertified step leaves the result uncertified.
  if (march.first_unconverged > 0 && sol.report.status == SolveStatus::converged) {
    sol.report.status = SolveStatus::not_converged;
    sol.report.message += " [marching step " + std::to_string(march.first_unconverged) + " of " +
                          std::to_string(n) + " was not converged]";
  }
  if (sol.report.status == SolveStatus::failed)
    sol.report.message += " [rolling stopped after " + std::to_string(march.steps) + " of " + std::to_string(n) +
                          " marching steps]";
  // Amplitudes as creepages / spin of the last step (per unit rolling distance).
  for (int k = 0; k < 3; ++k) sol.amplitudes[k] /= s.grid.dx;
  return sol;
}

TangentialSolution TangentialProblem::convected_step(const NormalSpec& normal, const std::array<double, 3>& increment,
                                                   const std::array<double, 2>& travel, const SolverOptions& solver) {
  TangentialSolution sol;
  convected_step(normal, increment, travel, solver, sol);
  return sol;
}

void TangentialProblem::convected_step(const NormalSpec& normal, const std::array<double, 3>& increment,
                                       const std::array<double, 2>& travel, const SolverOptions& solver,
                                       TangentialSolution& sol) {
  Impl& s = *impl_;
  if (!std::isfinite(travel[0]) || !std::isfinite(travel[1])) throw InputError("travel", "must be finite");
  // 2-D (plane strain): there is no y direction to travel along, so a y travel is a caller's
  // error, rejected rather than ignored.
  if (s.grid.dimension == 2 && travel[1] != 0.0)
    throw InputError("travel", "a 2-D contact has no y direction: the travel along y must be 0");
  if (s.given_operators && (travel[0] != 0.0 || travel[1] != 0.0))
    throw InputError("travel", "a finite body's contact is not convected (no shifted compliances)");
  std::array<ModeControl, 3> modes{};
  for (int k = 0; k < 3; ++k) modes[k].value = increment[k];
  s.predictor.clear();  // a convected step continues no quasi-static history
  // auto: as for marching, native first at any size (the others remain its fallbacks).
  s.native_first = true;
  struct Restore {
    bool& flag;
    ~Restore() { flag = false; }
  } restore{s.native_first};
  double shift_y = s.grid.dimension == 3 ? travel[1] / s.grid.dy : 0.0;
  // A lateral travel below 1e-12 element (round-off in V_y of a body rolling along x) is not
  // convected: it would change the memory 1000 times less than the solver's tolerance, and cost
  // two more operator applies per step (and, below zero, the operators of the shift -1).
  if (std::abs(shift_y) < 1e-12) shift_y = 0.0;
  s.solve_step(normal, modes, increment, {travel[0] / s.grid.dx, shift_y}, solver, {}, sol);
  for (int k = 0; k < 3; ++k) s.amplitude_prev[k] += sol.amplitudes[k];
}

TangentialMemory TangentialProblem::memory() const {
  TangentialMemory m;
  save_memory(m);
  return m;
}

void TangentialProblem::save_memory(TangentialMemory& into) const {
  const Impl& s = *impl_;
  into.tau.assign(s.tau_prev.begin(), s.tau_prev.end());
  into.pressure.assign(s.p_prev.begin(), s.p_prev.end());
  into.warm_start.assign(s.tau_warm.begin(), s.tau_warm.end());
  into.amplitudes = s.amplitude_prev;
  into.displacement.assign(s.displacement_prev.begin(), s.displacement_prev.end());
}

void TangentialProblem::restore(const TangentialMemory& m) {
  restore_history(m);
  impl_->tau_warm = m.warm_start;
}

void TangentialProblem::restore_history(const TangentialMemory& m) {
  Impl& s = *impl_;
  s.tau_prev = m.tau;
  s.p_prev = m.pressure;
  s.amplitude_prev = m.amplitudes;
  // The relative displacement of (tau, pressure) when the memory carries one of this grid's
  // size; otherwise the next convected step applies the operators.
  if (m.displacement.size() == s.tau_prev.size() && m.tau.size() == s.tau_prev.size())
    s.displacement_prev = m.displacement;
  else
    s.displacement_prev.clear();
  s.predictor.clear();
}

void TangentialProblem::set_near_start(bool near) { impl_->near_start = near; }

void TangentialProblem::set_heights(const std::vector<double>& heights) {
  impl_->heights.assign(heights.begin(), heights.end());  // reuses the buffer: no allocation per step
  impl_->predictor.clear();                                // another profile: no load history to continue
}

const LinearOperator& TangentialProblem::tangential_compliance() const { return *impl_->Ct; }

const LinearOperator& TangentialProblem::normal_compliance() const { return *impl_->C; }

const LinearOperator* TangentialProblem::tangential_from_normal() const {
  return impl_->coupled ? impl_->B21.get() : nullptr;
}

const LinearOperator* TangentialProblem::normal_from_tangential() const {
  return impl_->coupled ? impl_->B32.get() : nullptr;
}

const LinearOperator& TangentialProblem::convective_compliance() {
  Impl& s = *impl_;
  if (!s.half_space) throw InputError("tangential.regime", "convection is not available for a finite body");
  if (!s.D_conv) s.D_conv = s.half_space->tangential_convective(1, s.kind);
  return *s.D_conv;
}

const LinearOperator* TangentialProblem::convective_from_normal() {
  Impl& s = *impl_;
  if (!s.coupled) return nullptr;
  if (!s.half_space) throw InputError("tangential.regime", "convection is not available for a finite body");
  if (!s.D21_conv) s.D21_conv = s.half_space->tangential_from_normal_convective(1, s.kind);
  return s.D21_conv.get();
}

void reset_keeping_storage(TangentialSolution& solution) {
  reset_keeping_members(solution, &TangentialSolution::normal, &TangentialSolution::report, &TangentialSolution::tx,
                        &TangentialSolution::ty, &TangentialSolution::sx, &TangentialSolution::sy,
                        &TangentialSolution::bound, &TangentialSolution::state);
}

std::vector<double> rolling_warm_start(const TangentialSolution& solution, int dimension) {
  std::vector<double> t;
  rolling_warm_start(solution, dimension, t);
  return t;
}

void rolling_warm_start(const TangentialSolution& solution, int dimension, std::vector<double>& start) {
  start.assign(solution.tx.begin(), solution.tx.end());
  if (dimension == 3) start.insert(start.end(), solution.ty.begin(), solution.ty.end());
}

}  // namespace dc
