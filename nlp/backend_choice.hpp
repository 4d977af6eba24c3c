#pragma once
// Which backends to try, in order, for a requested backend name and problem size.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "case_model.hpp"
#include "quadratic_program.hpp"

namespace dc {

/// Problems up to this many unknowns go to Ipopt first under `auto` (exact Hessian, ~0.1 s);
/// larger ones to the native FFT solver (measured: Ipopt needs ~1 s at 32^2 with L-BFGS and
/// ~5 s with the exact Hessian, the native solver ~0.01 s).
inline constexpr std::size_t kAutoIpoptLimit = 256;

/// "auto": by size, then the others as fallbacks (when `fallback`); a named backend: that one,
/// then the others when `fallback`. Throws InputError("solver.backend") for an unknown name.
std::vector<std::string> backend_order(const std::string& requested, std::size_t unknowns, bool fallback);

/// The backend options of a case's solver block.
SolveOptions solve_options(const SolverSpec& solver, const ProgressCallback& progress);

/// One backend run: its outcome (an exception becomes a failed outcome with the message)
/// and the wall time. `native` is the problem's specialist solver.
struct TimedOutcome {
  SolveOutcome outcome;
  double time_s = 0.0;
};
using NativeSolver = std::function<SolveOutcome(const QuadraticProgram&, const SolveOptions&)>;
TimedOutcome run_backend(const std::string& backend, const QuadraticProgram& qp, const SolveOptions& options,
                         NativeSolver native);

}  // namespace dc
