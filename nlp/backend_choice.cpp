#include "backend_choice.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "fault_injection.hpp"
#include "interrupt.hpp"
#include "kept_storage.hpp"

namespace dc {

std::vector<std::string> backend_order(Backend requested, std::size_t unknowns, bool fallback) {
  std::vector<std::string> order;
  backend_order(requested, unknowns, fallback, order);
  return order;
}

void backend_order(Backend requested, std::size_t unknowns, bool fallback, std::vector<std::string>& order) {
  order.clear();
  if (requested != Backend::automatic) {
    order.emplace_back(to_string(requested));  // asked for by name: never replaced silently by another backend
    return;
  }
  for (const char* name : unknowns <= kAutoIpoptLimit ? std::array<const char*, 3>{"ipopt", "native", "nlopt"}
                                                      : std::array<const char*, 3>{"native", "ipopt", "nlopt"}) {
    order.emplace_back(name);
    if (!fallback) break;
  }
}

SolveOptions solve_options(const SolverOptions& solver, const ProgressCallback& progress) {
  SolveOptions options;
  options.tol = solver.tol;
  options.max_iter = solver.max_iter;
  options.hessian = solver.hessian;
  options.progress = progress;
  return options;
}

TimedOutcome run_backend(const std::string& backend, const QuadraticProgram& qp, const SolveOptions& options,
                         NativeSolver native) {
  TimedOutcome timed;
  run_backend(
      backend, qp, options,
      [&native](const QuadraticProgram& q, const SolveOptions& o, SolveOutcome& out) { out = native(q, o); }, timed);
  return timed;
}

void reset_keeping_storage(SolveOutcome& outcome) {
  reset_keeping_members(outcome, &SolveOutcome::x, &SolveOutcome::equality_multipliers, &SolveOutcome::block_x,
                        &SolveOutcome::message, &SolveOutcome::history);
}

void run_backend(const std::string& backend, const QuadraticProgram& qp, const SolveOptions& options,
                 const NativeSolverInto& native, TimedOutcome& timed) {
  SolveOutcome& out = timed.outcome;
  reset_keeping_storage(out);
  timed.time_s = 0.0;
  throw_if_interrupted();
  const auto start = std::chrono::steady_clock::now();
  const Fault fault = injected_fault(backend);
  try {
    if (fault == Fault::fail) {
      out.message = backend + ": failure injected (a test's fault source)";
    } else if (fault == Fault::stall) {  // no progress from the start
      out.x = qp.x0.size() == static_cast<std::size_t>(qp.n()) ? qp.x0 : std::vector<double>(qp.c.size(), 0.0);
      out.equality_multipliers.assign(qp.equalities.size(), 0.0);
      out.message = backend + ": stall injected (a test's fault source)";
    } else if (backend == "native") {
      if (qp.block) throw std::invalid_argument("the native solvers take no sparse rows");
      native(qp, options, out);
    } else if (backend == "ipopt") {
      out = solve_with_ipopt(qp, options);
    } else {
      out = solve_with_nlopt(qp, options);
    }
    if (fault == Fault::nan && !out.x.empty()) out.x[out.x.size() / 2] = std::numeric_limits<double>::quiet_NaN();
  } catch (const std::exception& e) {
    out = SolveOutcome{};
    out.message = std::string("exception: ") + e.what();
  }
  // A non-finite value is never a result (it would pass comparisons and reach the files).
  if (std::any_of(out.x.begin(), out.x.end(), [](double v) { return !std::isfinite(v); })) {
    out.x.clear();
    out.success = false;
    out.message += " [returned non-finite values: discarded]";
  }
  throw_if_interrupted();  // a backend stopped by the interrupt reports no result of its own
  timed.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace dc
