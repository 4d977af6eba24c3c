#include "quadratic_program.hpp"

#include <vector>

namespace dc {

double QuadraticProgram::objective(const double* x) const {
  std::vector<double> g(c.size());
  return gradient(x, g.data());
}

double QuadraticProgram::gradient(const double* x, double* g) const {
  Q->apply(x, g);
  double f = 0.0;
  const std::size_t n = c.size();
  for (std::size_t i = 0; i < n; ++i) {
    f += x[i] * (0.5 * g[i] + c[i]);
    g[i] += c[i];
  }
  return f;
}

}  // namespace dc
