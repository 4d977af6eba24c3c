#pragma once
// Small reductions over the solvers' std::vector<double> fields (one home for them).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace dc {

/// Euclidean inner product a . b (a and b of equal length).
inline double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

/// Largest |v_i| (0 for an empty vector): the infinity norm.
inline double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace dc
