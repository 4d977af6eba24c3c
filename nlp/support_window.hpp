#pragma once
// The tangential program of a step lives where friction can act (f(p) > 0); elsewhere tau is
// held at 0. The half-space compliance is translation invariant, so its restriction to a
// rectangle of the grid is the compliance of a grid of that rectangle's size (same element,
// same 2-D reference length): the program posed on a rectangle holding the support is the same
// program, with a smaller transform. A loading history whose contact grows, or a grid chosen
// for the largest contact of a run, then pays for the contact it has.
#include <cstddef>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "grid.hpp"
#include "linear_operator.hpp"
#include "material.hpp"
#include "tangential_preconditioner.hpp"

namespace dc {

/// A rectangle of the grid: elements i0 .. i0 + nx - 1 along x, j0 .. j0 + ny - 1 along y.
struct SupportWindow {
  int i0 = 0, j0 = 0, nx = 0, ny = 0;
  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  /// The grid's element index of the window's element `local` (x fastest).
  std::size_t global(const Grid& grid, std::size_t local) const {
    const auto wx = static_cast<std::size_t>(nx);
    return grid.index(i0 + static_cast<int>(local % wx), j0 + static_cast<int>(local / wx));
  }
  /// The grid of the window (the same elements, its own corner).
  Grid grid_of(const Grid& grid) const;
};

/// The smallest window that holds every element with f > 0, each side widened to the widest one
/// with the same FFT box (fft_fast_size(2 n - 1)): what the transform pays for anyway, and few
/// sizes (about one per 25 % of growth), which a history reuses; within the grid; empty (nx = 0) when it would cover more than `max_fraction`
/// of the grid or the support is empty.
SupportWindow support_window(const Grid& grid, const std::vector<double>& f, double max_fraction = 0.9);

/// A window's tangential compliance (B22) and its FFT preconditioner.
struct WindowOperators {
  std::unique_ptr<LinearOperator> compliance;
  std::unique_ptr<TangentialPreconditioner> preconditioner;
};

/// The operators of windows of one grid and material pair, built once per window size and
/// kept (at most `capacity` sizes and three grids' elements in all; the oldest are dropped).
class WindowedCompliance {
 public:
  WindowedCompliance(const Grid& grid, const MaterialPair& materials, OperatorKind kind, std::size_t capacity = 12);
  const WindowOperators& operators(const SupportWindow& window);
  const LinearOperator& tangential(const SupportWindow& window) { return *operators(window).compliance; }
  /// Elements of the windows whose operators are kept (all sizes together).
  std::size_t elements_kept() const;

 private:
  Grid grid_;
  MaterialPair materials_;
  OperatorKind kind_;
  std::size_t capacity_;
  std::map<std::pair<int, int>, WindowOperators> operators_;
  std::vector<std::pair<int, int>> order_;  ///< sizes in the order they were built
};

}  // namespace dc
