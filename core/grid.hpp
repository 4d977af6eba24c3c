#pragma once
// Uniform rectangular grid of contact elements in the plane z = 0.
// 3-D: nx * ny rectangles dx * dy. 2-D (plane strain, per unit length): ny = 1 strips of width dx.
#include <cstddef>

namespace dc {

struct Grid {
  int dimension = 3;  ///< 3, or 2 for plane strain
  int nx = 0, ny = 1;
  double x0 = 0.0, y0 = 0.0;  ///< lower-left corner of the grid
  double dx = 0.0, dy = 1.0;  ///< element size (2-D: dy = 1, unit length)

  /// Builds a grid covering [x_min, x_max] x [y_min, y_max]; validates (key prefix "grid").
  static Grid make(int dimension, int nx, int ny, double x_min, double x_max, double y_min,
                   double y_max);

  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j; }
  double xc(int i) const { return x0 + (i + 0.5) * dx; }
  double yc(int j) const { return dimension == 2 ? 0.0 : y0 + (j + 0.5) * dy; }
  /// Element area (m^2); in 2-D the strip width dx (per unit length).
  double area() const { return dimension == 2 ? dx : dx * dy; }
  double x_max() const { return x0 + nx * dx; }
  double y_max() const { return y0 + ny * dy; }
};

}  // namespace dc
