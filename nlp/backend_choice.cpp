#include "backend_choice.hpp"

#include <algorithm>
#include <chrono>

#include "errors.hpp"
#include "interrupt.hpp"

namespace dc {

std::vector<std::string> backend_order(const std::string& requested, std::size_t unknowns, bool fallback) {
  std::vector<std::string> order;
  if (requested == "auto") {
    order = unknowns <= kAutoIpoptLimit ? std::vector<std::string>{"ipopt", "native", "nlopt"}
                                        : std::vector<std::string>{"native", "ipopt", "nlopt"};
  } else if (requested == "ipopt" || requested == "nlopt" || requested == "native") {
    order = {requested};
    for (const char* other : {"native", "ipopt", "nlopt"})
      if (requested != other) order.emplace_back(other);
  } else {
    throw InputError("solver.backend", "unknown backend '" + requested + "' (auto, ipopt, nlopt, native)");
  }
  if (!fallback) order.resize(1);
  return order;
}

SolveOptions solve_options(const SolverSpec& solver, const ProgressCallback& progress) {
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
  throw_if_interrupted();
  const auto start = std::chrono::steady_clock::now();
  try {
    if (backend == "native") timed.outcome = native(qp, options);
    else if (backend == "ipopt") timed.outcome = solve_with_ipopt(qp, options);
    else timed.outcome = solve_with_nlopt(qp, options);
  } catch (const std::exception& e) {
    timed.outcome = SolveOutcome{};
    timed.outcome.message = std::string("exception: ") + e.what();
  }
  throw_if_interrupted();  // a backend stopped by the interrupt reports no result of its own
  timed.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return timed;
}

}  // namespace dc
