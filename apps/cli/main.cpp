// dyncontact: the program. The process-wide tuning of the finite body's sparse solves, which the
// library leaves to programs (nlp/process_tuning/process_tuning.hpp), then the command line.
#include "process_tuning.hpp"
#include "program.hpp"

int main(int argc, char** argv) {
  dc::install_process_tuning();
  return dc::cli::run_program(argc, argv);
}
