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
  // OpenBLAS starts its worker threads when it is loaded, before main, with every signal open:
  // they would take the SIGINT/SIGTERM the command line leaves to its watchdog
  // (apps/runs/interrupt_handler.hpp). With one thread they are idle: stopped here (a later
  // multi-threaded call starts them again, from the calling thread).
  using Shutdown = int (*)();
  if (auto stop = reinterpret_cast<Shutdown>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"))) stop();
}

}  // namespace dc
