// dyncontact_fft_bench: the cost of one operator apply on the FFT path (core/padded_fft,
// core/linear_operator), one thread: the normal compliance (1 block), the tangential one
// (2 x 2 blocks) and the kappa term B21 (2 x 1) of a dissimilar pair on n x n grids, and their
// set-up (kernel tables, spectra, plans). Times are the thread's CPU time (less sensitive to a
// loaded machine than the wall clock): set-up once, apply the fastest of 5 batches.
//   dyncontact_fft_bench [--sizes 45,91,152,304,512]
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "fft_planning.hpp"
#include "grid.hpp"
#include "linear_operator.hpp"
#include "material.hpp"

namespace {

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Set-up time (s) and the fastest apply (s) of the operator `make` builds.
template <class Make>
void measure(const char* name, int n, Make&& make) {
  const double t0 = thread_seconds();
  const std::unique_ptr<dc::LinearOperator> op = make();
  const double setup = thread_seconds() - t0;
  std::vector<double> x(op->cols()), y(op->rows());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 + 0.5 * std::sin(0.37 * static_cast<double>(i));
  op->apply(x.data(), y.data());  // first touch of the buffers
  const double once = std::max(thread_seconds() - t0 - setup, 1e-7);
  const int reps = std::clamp(static_cast<int>(0.05 / once), 1, 2000);
  double best = 1e300;
  for (int batch = 0; batch < 5; ++batch) {
    const double t = thread_seconds();
    for (int r = 0; r < reps; ++r) op->apply(x.data(), y.data());
    best = std::min(best, (thread_seconds() - t) / reps);
  }
  const int m = dc::fft_fast_size(2 * n - 1);
  std::printf("%-12s %5d^2  box %5d^2  set-up %9.2f ms  apply %10.1f us\n", name, n, m, 1e3 * setup, 1e6 * best);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dyncontact_fft_bench: one operator apply on the FFT path, one thread"};
  std::vector<int> sizes{45, 91, 152, 304, 512};
  app.add_option("--sizes", sizes, "grid sizes n (n x n elements)")->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  setenv("DYNCONTACT_THREADS", "1", 1);
  dc::MaterialPair materials;  // a dissimilar pair: kappa != 0, as in Spence's problem
  materials.body = dc::Elastic::from_E_nu(7e10, 0.0, "materials.body");
  materials.base = dc::Elastic::make_rigid();
  for (int n : sizes) {
    if (n < 2) continue;
    const dc::Grid grid = dc::Grid::make(3, n, n, -1e-3, 1e-3, -1e-3, 1e-3);
    const dc::HalfSpace half_space(grid, materials);
    const auto fft = dc::OperatorKind::fft;
    measure("normal", n, [&] { return half_space.normal(fft); });
    measure("tangential", n, [&] { return half_space.tangential(fft); });
    measure("kappa B21", n, [&] { return half_space.tangential_from_normal(fft); });
  }
  return 0;
}
