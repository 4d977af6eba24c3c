#include "grid.hpp"

#include <cmath>
#include <string>

#include "errors.hpp"

namespace dc {

Grid Grid::make(int dimension, int nx, int ny, double x_min, double x_max, double y_min,
                double y_max) {
  if (dimension != 2 && dimension != 3)
    throw InputError("dimension", "must be 2 or 3, got " + std::to_string(dimension));
  if (nx < 1) throw InputError("grid.nx", "must be at least 1, got " + std::to_string(nx));
  if (dimension == 2) ny = 1;
  if (ny < 1) throw InputError("grid.ny", "must be at least 1, got " + std::to_string(ny));
  if (!(std::isfinite(x_min) && std::isfinite(x_max)) || !(x_max > x_min))
    throw InputError("grid.x", "needs two finite bounds with x_min < x_max");
  Grid g;
  g.dimension = dimension;
  g.nx = nx;
  g.ny = ny;
  g.x0 = x_min;
  g.dx = (x_max - x_min) / nx;
  if (dimension == 3) {
    if (!(std::isfinite(y_min) && std::isfinite(y_max)) || !(y_max > y_min))
      throw InputError("grid.y", "needs two finite bounds with y_min < y_max");
    g.y0 = y_min;
    g.dy = (y_max - y_min) / ny;
  } else {
    g.y0 = -0.5;
    g.dy = 1.0;
  }
  return g;
}

}  // namespace dc
