// Compiled into every test program (tests/CMakeLists.txt, dyncontact_add_tests): the solvers run
// as in `dyncontact`, with the process-wide tuning of the sparse solves installed
// (nlp/process_tuning/process_tuning.hpp), which test_finite_sparse_tangential checks is taken.
#include "process_tuning.hpp"

namespace {
const bool process_tuning_installed = (dc::install_process_tuning(), true);
}  // namespace
