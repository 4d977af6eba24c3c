#pragma once
// Test-only fault injection: makes a backend fail, stall or return NaN, or an outer loop stall,
// so that tests can show what the program does then (fallback, clear messages, exit 3, no NaN
// in any output file). Read from the environment variable DYNCONTACT_FAULT, e.g.
//   DYNCONTACT_FAULT="ipopt:fail,native:nan,outer:stall"
// targets: ipopt | nlopt | native | outer; kinds: fail | stall | nan; KIND@N applies to the N-th
// query of the target only (e.g. outer:stall@2: the second step's outer loop). Not for users: unset, it
// changes nothing; a malformed value is ignored with one warning on stderr.
#include <string>

namespace dc {

enum class Fault { none, fail, stall, nan };

/// The fault injected into `target` (a backend name or "outer"), from DYNCONTACT_FAULT (parsed
/// again when its value changes).
Fault injected_fault(const std::string& target);

}  // namespace dc
