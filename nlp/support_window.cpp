#include "support_window.hpp"

#include <algorithm>

#include "fft_planning.hpp"
#include "influence.hpp"

namespace dc {

Grid SupportWindow::grid_of(const Grid& grid) const {
  Grid g = grid;
  g.nx = nx;
  g.ny = ny;
  g.x0 = grid.x0 + i0 * grid.dx;
  if (grid.dimension != 2) g.y0 = grid.y0 + j0 * grid.dy;
  return g;
}

namespace {

/// [lo, hi] widened within [0, n), centred on the range, to the widest side whose zero-padded
/// transform has the length the range's own would have (fft_fast_size(2 w - 1)): the window
/// costs what its support costs, and its sides take few values (8, 10, 12, 16, 20, 25, 32, 40,
/// 50, 64, ...: about one per 25 % of growth), which a history's windows reuse. At least 8
/// elements (or n).
std::pair<int, int> rounded_range(int lo, int hi, int n) {
  const int extent = std::max(hi - lo + 1, std::min(8, n));
  const int width = std::min(n, (fft_fast_size(2 * extent - 1) + 1) / 2);
  const int start = std::clamp(lo - (width - (hi - lo + 1)) / 2, 0, n - width);
  return {start, width};
}

}  // namespace

SupportWindow support_window(const Grid& grid, const std::vector<double>& f, double max_fraction) {
  int ilo = grid.nx, ihi = -1, jlo = grid.ny, jhi = -1;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      if (f[grid.index(i, j)] > 0.0) {
        ilo = std::min(ilo, i);
        ihi = std::max(ihi, i);
        jlo = std::min(jlo, j);
        jhi = std::max(jhi, j);
      }
  SupportWindow w;
  if (ihi < 0) return w;
  const auto [i0, nx] = rounded_range(ilo, ihi, grid.nx);
  const auto [j0, ny] = rounded_range(jlo, jhi, grid.ny);
  if (static_cast<double>(nx) * ny > max_fraction * static_cast<double>(grid.size())) return w;
  w.i0 = i0;
  w.j0 = j0;
  w.nx = nx;
  w.ny = ny;
  return w;
}

WindowedCompliance::WindowedCompliance(const Grid& grid, const MaterialPair& materials, OperatorKind kind,
                                       std::size_t capacity)
    : grid_(grid), materials_(materials), kind_(kind), capacity_(std::max<std::size_t>(capacity, 1)) {}

std::size_t WindowedCompliance::elements_kept() const {
  std::size_t kept = 0;
  for (const auto& size : order_) kept += static_cast<std::size_t>(size.first) * size.second;
  return kept;
}

const WindowOperators& WindowedCompliance::operators(const SupportWindow& window) {
  const std::pair<int, int> key{window.nx, window.ny};
  auto it = operators_.find(key);
  if (it != operators_.end()) return it->second;
  // Room for the new size: the oldest are dropped while more than `capacity` sizes, or windows
  // of more than three grids' elements in all, would be kept.
  const std::size_t added = static_cast<std::size_t>(key.first) * key.second;
  while (!order_.empty() && (order_.size() >= capacity_ || elements_kept() + added > 3 * grid_.size())) {
    operators_.erase(order_.front());
    order_.erase(order_.begin());
  }
  // The 2-D logarithmic kernels vanish at the whole grid's length, as on the grid itself.
  InfluenceOptions options;
  options.reference_length = grid_.nx * grid_.dx;
  const Grid grid = window.grid_of(grid_);
  const HalfSpace half_space(grid, materials_, options);
  WindowOperators ops;
  ops.compliance = half_space.tangential(kind_);
  ops.preconditioner = std::make_unique<TangentialPreconditioner>(*ops.compliance, grid);
  order_.push_back(key);
  return operators_[key] = std::move(ops);
}

}  // namespace dc
