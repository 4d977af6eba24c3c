#include "blas_threads.hpp"

#include <dlfcn.h>

#include <cstdlib>

namespace dc {

void use_one_blas_thread() {
  if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("OMP_NUM_THREADS")) return;
  // Looked up at run time: the BLAS behind libblas.so.3 is the system's choice (Debian's
  // alternatives), reference BLAS has no such call.
  using SetThreads = void (*)(int);
  if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
}

}  // namespace dc
