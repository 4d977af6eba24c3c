#pragma once
// Which backends to try, in order, for a requested backend name and problem size.
#include <cstddef>
#include <string>
#include <vector>

namespace dc {

/// Problems up to this many unknowns go to Ipopt first under `auto`; larger ones to the
/// native FFT solver (Ipopt's dense operator costs O(n^2) memory and time per iteration).
inline constexpr std::size_t kAutoIpoptLimit = 1024;

/// "auto": by size, then the others as fallbacks (when `fallback`); a named backend: that one,
/// then the others when `fallback`. Throws InputError("solver.backend") for an unknown name.
std::vector<std::string> backend_order(const std::string& requested, std::size_t unknowns, bool fallback);

}  // namespace dc
