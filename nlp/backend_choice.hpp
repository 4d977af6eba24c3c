#pragma once
// Which backends to try, in order, for a requested backend name and problem size.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "quadratic_program.hpp"
#include "solver_options.hpp"

namespace dc {

/// Problems up to this many unknowns go to Ipopt first under `auto` (exact Hessian, ~0.1 s);
/// larger ones to the native FFT solver (measured: Ipopt needs ~1 s at 32^2 with L-BFGS and
/// ~5 s with the exact Hessian, the native solver ~0.01 s).
inline constexpr std::size_t kAutoIpoptLimit = 256;

/// The names of the backends to run: for automatic, by size, then the others as fallbacks (when
/// `fallback`); a named backend: that one only (it reports its own failure, never replaced silently).
std::vector<std::string> backend_order(Backend requested, std::size_t unknowns, bool fallback);
/// The same into `order` (its storage kept: the names fit in a string's own buffer).
void backend_order(Backend requested, std::size_t unknowns, bool fallback, std::vector<std::string>& order);

/// The backend options of a case's solver block.
SolveOptions solve_options(const SolverOptions& solver, const ProgressCallback& progress);

/// One backend run: its outcome (an exception becomes a failed outcome with the message; a
/// non-finite value discards the result) and the wall time. `native` is the problem's specialist
/// solver. Faults injected for tests (fault_injection.hpp) act here.
struct TimedOutcome {
  SolveOutcome outcome;
  double time_s = 0.0;
};
using NativeSolver = std::function<SolveOutcome(const QuadraticProgram&, const SolveOptions&)>;
TimedOutcome run_backend(const std::string& backend, const QuadraticProgram& qp, const SolveOptions& options,
                         NativeSolver native);
/// The same into `timed`, whose outcome's storage the native solver fills again (no allocation
/// for a solve repeated at every step): `native` writes its outcome into the one it is given.
using NativeSolverInto = std::function<void(const QuadraticProgram&, const SolveOptions&, SolveOutcome&)>;
void run_backend(const std::string& backend, const QuadraticProgram& qp, const SolveOptions& options,
                 const NativeSolverInto& native, TimedOutcome& timed);
/// Back to a default outcome, the storage of its vectors and message kept.
void reset_keeping_storage(SolveOutcome& outcome);

}  // namespace dc
