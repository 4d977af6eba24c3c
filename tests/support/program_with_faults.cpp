// The test-only program `dyncontact_with_faults`: `dyncontact` with the tests' fault source
// installed (fault_from_environment.hpp: DYNCONTACT_FAULT), for the command-line tests of what
// the program does when a backend fails. The program itself never reads DYNCONTACT_FAULT.
#include "fault_from_environment.hpp"
#include "process_tuning.hpp"
#include "program.hpp"

int main(int argc, char** argv) {
  dc::test::install_faults_from_environment();
  dc::install_process_tuning();
  return dc::cli::run_program(argc, argv);
}
