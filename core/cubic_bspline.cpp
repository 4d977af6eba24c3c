#include "cubic_bspline.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dc {

CubicBSplineBasis::CubicBSplineBasis(std::vector<double> breakpoints) : breakpoints_(std::move(breakpoints)) {
  if (breakpoints_.size() < 2) throw std::invalid_argument("cubic B-splines: at least 2 breakpoints needed");
  for (std::size_t k = 0; k < breakpoints_.size(); ++k) {
    if (!std::isfinite(breakpoints_[k])) throw std::invalid_argument("cubic B-splines: non-finite breakpoint");
    if (k > 0 && !(breakpoints_[k] > breakpoints_[k - 1]))
      throw std::invalid_argument("cubic B-splines: breakpoints must increase strictly");
  }
  knots_.assign(3, breakpoints_.front());
  knots_.insert(knots_.end(), breakpoints_.begin(), breakpoints_.end());
  knots_.insert(knots_.end(), 3, breakpoints_.back());
}

CubicBSplineBasis::Local CubicBSplineBasis::evaluate(double t) const {
  constexpr int p = 3;
  const int n_basis = size();
  t = std::clamp(t, breakpoints_.front(), breakpoints_.back());
  // A2.1: the span [knots_[span], knots_[span + 1]) holding t; the last span at the right end.
  int span = n_basis - 1;
  if (t < knots_[static_cast<std::size_t>(n_basis)]) {
    const auto it = std::upper_bound(knots_.begin() + p, knots_.begin() + n_basis + 1, t);
    span = static_cast<int>(it - knots_.begin()) - 1;
  }
  const auto knot = [&](int k) { return knots_[static_cast<std::size_t>(k)]; };
  // A2.3: ndu holds the basis functions (upper triangle) and the knot differences (lower).
  double ndu[p + 1][p + 1], left[p + 1], right[p + 1];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - knot(span + 1 - j);
    right[j] = knot(span + j) - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  Local out;
  out.first = span - p;
  for (int j = 0; j <= p; ++j) out.derivative[0][static_cast<std::size_t>(j)] = ndu[j][p];
  double a[2][p + 1];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= 2; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = r - 1 <= pk ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      out.derivative[static_cast<std::size_t>(k)][static_cast<std::size_t>(r)] = d;
      std::swap(s1, s2);
    }
  }
  // Multiply through by p! / (p - k)!.
  for (int r = 0; r <= p; ++r) {
    out.derivative[1][static_cast<std::size_t>(r)] *= p;
    out.derivative[2][static_cast<std::size_t>(r)] *= p * (p - 1);
  }
  return out;
}

}  // namespace dc
