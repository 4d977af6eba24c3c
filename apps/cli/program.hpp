#pragma once
// The command line as a function: `dyncontact ARGS` (main.cpp), and the test-only program that
// injects faults (tests/support/program_with_faults.cpp). Returns the exit code.

namespace dc::cli {

int run_program(int argc, char** argv);

}  // namespace dc::cli
