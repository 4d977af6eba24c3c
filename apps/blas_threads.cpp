#include "blas_threads.hpp"

#include <dlfcn.h>

namespace dc::cli {

void use_one_blas_thread() {
  using SetThreads = void (*)(int);
  // The BLAS is chosen by the system (Debian's alternatives), not at link time: look it up.
  if (void* f = dlsym(RTLD_DEFAULT, "openblas_set_num_threads")) reinterpret_cast<SetThreads>(f)(1);
}

}  // namespace dc::cli
