#include "fft_planning.hpp"

#include <algorithm>
#include <cstdlib>
#include <thread>

#include <fftw3.h>

namespace dc {

std::mutex& fft_planner_mutex() {
  static std::mutex m;
  return m;
}

int fft_threads() {
  static const int threads = [] {
    fftw_init_threads();
    int n = static_cast<int>(std::thread::hardware_concurrency());
    if (const char* env = std::getenv("DYNCONTACT_THREADS")) n = std::atoi(env);
    return std::max(1, n);
  }();
  return threads;
}

int fft_threads_for(std::size_t points) {
  // Below ~128^2 points a transform takes tens of microseconds: waking threads costs more.
  constexpr std::size_t kThreadedTransform = 128u * 128u;
  const int threads = fft_threads();  // also initialises FFTW's threads once
  return points >= kThreadedTransform ? threads : 1;
}

int fft_good_size(int n) {
  for (int m = std::max(n, 1);; ++m) {
    int r = m;
    for (int p : {2, 3, 5})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

}  // namespace dc
