#pragma once
// The test builds' fault source (nlp/fault_injection.hpp), read from the environment variable
// DYNCONTACT_FAULT, e.g.
//   DYNCONTACT_FAULT="ipopt:fail,native:nan,outer:stall"
// targets: ipopt | nlopt | native | outer; kinds: fail | stall | nan; KIND@N applies to the N-th
// query of the target only (e.g. outer:stall@2: the second step's outer loop). Unset, it injects
// nothing; a malformed item is ignored with one warning on stderr. Installed by the tests that
// inject faults and by the test-only program tests/support/program_with_faults.cpp.

namespace dc::test {

/// Installs the DYNCONTACT_FAULT source for the process (idempotent).
void install_faults_from_environment();

}  // namespace dc::test
