#pragma once
// The exit codes of the command line, which the runs that write their own files return too
// (0 success, 2 bad input, 3 not converged, 4 internal, 5 an output file not written).
namespace dc::runs {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 2;     ///< InputError, usage errors
inline constexpr int kExitUnconverged = 3;  ///< the solver did not converge
inline constexpr int kExitInternal = 4;     ///< anything unexpected
inline constexpr int kExitOutput = 5;       ///< OutputError: a result file could not be written

}  // namespace dc::runs
