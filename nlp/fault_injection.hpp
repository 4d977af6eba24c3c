#pragma once
// Fault injection for tests: a backend made to fail, stall or return NaN, or an outer loop made
// to stall, so that tests can show what the library and the program do then (fallback, clear
// messages, exit 3, no NaN in any output file). The library only asks; it never reads the
// environment. A test build installs a source (tests/support/fault_from_environment.hpp reads
// DYNCONTACT_FAULT); without one, injected_fault is always Fault::none.
#include <string>

namespace dc {

enum class Fault { none, fail, stall, nan };

/// The fault for `target` ("ipopt", "nlopt", "native" or "outer"), asked once per backend run or
/// outer loop.
using FaultSource = Fault (*)(const std::string& target);

/// Installs `source` for the whole process (nullptr: none). Tests only.
void set_fault_source(FaultSource source);

/// The fault injected into `target`: Fault::none unless a test installed a source.
Fault injected_fault(const std::string& target);

}  // namespace dc
