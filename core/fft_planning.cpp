#include "fft_planning.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>
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

namespace {
/// power = the exponents of 2, 3 and 5 in m; false when m has another prime factor.
bool smooth_235(int m, int (&power)[3]) {
  const int primes[3] = {2, 3, 5};
  for (int k = 0; k < 3; ++k) {
    power[k] = 0;
    while (m % primes[k] == 0) {
      m /= primes[k];
      ++power[k];
    }
  }
  return m == 1;
}
}  // namespace

int fft_good_size(int n) {
  int power[3];
  for (int m = std::max(n, 1);; ++m)
    if (smooth_235(m, power)) return m;
}

int fft_fast_size(int n) {
  n = std::max(n, 1);
  if (n <= 2) return n;
  int best = fft_good_size(n);
  double best_cost = std::numeric_limits<double>::infinity();
  int power[3];
  for (int m = n; m <= 2 * n; ++m) {
    if (!smooth_235(m, power)) continue;
    const double cost = m * (power[0] == 0 ? 2.0 : 1.0) * (1.0 + 0.2 * std::min(power[1], 3)) *
                        (1.0 + 0.1 * std::max(power[2] - 2, 0));
    if (cost < best_cost) {
      best_cost = cost;
      best = m;
    }
  }
  return best;
}

}  // namespace dc
