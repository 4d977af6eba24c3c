#include "resource_estimate.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "linear_operator.hpp"

namespace dc::runs {

ResourceEstimate estimate_resources(const Case& c) { return estimate_resources(c, c.grid); }

ResourceEstimate estimate_resources(const Case& c, const Grid& grid) {
  ResourceEstimate e;
  const double n = static_cast<double>(grid.size());
  const bool tangential = c.problem == ProblemKind::tangential;
  const bool three_d = c.dimension == 3;
  // Unknowns per element of the largest operator: p (normal); tau_x, tau_y (3-D tangential).
  const double k = tangential && three_d ? 2.0 : 1.0;
  const double entries = (k * n) * (k * n);
  bool dense = entries <= static_cast<double>(kDenseAutoLimit);
  if (c.solver.operator_kind == OperatorKind::dense) dense = true;
  if (c.solver.operator_kind == OperatorKind::fft) dense = false;
  e.operator_kind = dense ? "dense" : "fft";
  // The padded transform size (2 nx x 2 ny, rounded to fast lengths: ~4n in 3-D, ~2n in 2-D).
  const double m = three_d ? 4.0 * n : 2.0 * n;
  const double blocks = tangential ? (three_d ? 4.0 : 2.0) : 1.0;  // normal + tangential kernels
  double flops_per_apply = 0.0;
  if (dense) {
    e.memory_bytes = 8.0 * (n * n + (tangential ? entries + 2.0 * k * n * n : 0.0));
    flops_per_apply = 2.0 * entries;
  } else {
    e.memory_bytes = blocks * 16.0 * m;  // complex kernel spectra
    flops_per_apply = 2.0 * 5.0 * m * std::log2(std::max(m, 2.0)) * k;  // forward + inverse transforms
  }
  e.memory_bytes += 8.0 * 30.0 * k * n;  // the solver's work vectors and the output fields
  // About 100 operator applications per certified normal solve and 300 per tangential one
  // (the native solvers' typical counts), at about 2e9 floating-point operations per second
  // (measured: a 64 x 64 Hertz sphere, 40 FFT applications in 0.03 s).
  const double applies = 100.0 + (tangential ? 300.0 : 0.0);
  e.seconds = applies * flops_per_apply / 2e9;
  if (tangential && c.tangential) {
    const auto& t = *c.tangential;
    e.solves = static_cast<int>(t.has_history ? t.history.size() + t.rolling_history.size() : 1);
  }
  e.basis = std::string(dense ? "dense matrix: 8 bytes per entry, 2 flops per entry and application"
                              : "zero-padded FFT: 16 bytes per padded complex coefficient per kernel, 10 m log2 m "
                                "flops per application") +
            "; ~" + std::to_string(static_cast<int>(applies)) +
            " applications per solve at ~2e9 flop/s (this machine: within a factor of a few); Ipopt's exact Hessian instead grows as N^3";
  return e;
}

double available_memory_bytes() {
  double available = std::numeric_limits<double>::infinity();
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream in(line.substr(13));
    double kb = 0.0;
    if (in >> kb) available = kb * 1024.0;
  }
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    available = std::min(available, static_cast<double>(limit.rlim_cur));
  return available;
}

bool grid_fits_in_memory(const Case& c, const Grid& grid, double available_bytes) {
  return 2.0 * estimate_resources(c, grid).memory_bytes <= available_bytes;
}

}  // namespace dc::runs
