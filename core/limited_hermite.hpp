#pragma once
// Interpolation of tabulated values along one axis: the cubic Hermite of the nodes' values and
// limited slopes. The slope at a node is the minmod (the smallest when all agree in sign, else 0)
// of the derivatives there of the parabolas through the three-node stencils containing it
// (centred, from the left, from the right; those the table has). Hence
//   - one slope per node: the interpolant's slope is continuous everywhere (C1), on noisy data
//     too. A kink of angle dθ under a contact makes the pressure log-singular there (as under a
//     wedge's apex, p ~ -(E* dθ / π) ln|x|), so a kinked table's peak pressure grows without
//     bound as the grid refines below the table's spacing;
//   - exact for a quadratic (every stencil gives its derivative), in the outer cells where its
//     vertex is not within two cells of the table's end (an outer node's one-sided slope is kept
//     within 3 x its cell's secant of the same sign);
//   - no overshoot at a step: a face's own stencil is flat, its slope 0 (monotone data give
//     interior slopes within 1.5 x the neighbouring secants, inside Fritsch and Carlson's
//     monotone region, and outer ones within 3 x);
//   - continuous in the values (minmod is), so interpolating the interpolated rows of a 2-D
//     table along the other axis stays continuous.
// Nodes need not be evenly spaced. Positions t beyond [0, 1] extend the outer cells' cubics.
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace dc {
namespace limited_hermite_detail {

/// The derivative at x of the parabola through (xa, va), (xb, vb), (xc, vc).
inline double parabola_slope(double xa, double xb, double xc, double va, double vb, double vc, double x) {
  const double d1 = (vb - va) / (xb - xa), d2 = (vc - vb) / (xc - xb);
  const double second = (d2 - d1) / (xc - xa);
  return d1 + second * ((x - xa) + (x - xb));
}

inline double minmod(double a, double b) { return a * b > 0.0 ? (std::abs(a) < std::abs(b) ? a : b) : 0.0; }

}  // namespace limited_hermite_detail

/// The value at position t (0 at node `cell`, 1 at node cell + 1) between nodes of an axis of n
/// nodes at positions x(k) with values v(k); x and v are called for k in [cell - 2, cell + 3]
/// only. Two nodes: linear.
template <class Position, class Value>
double limited_hermite(std::size_t n, std::size_t cell, double t, const Position& x, const Value& v) {
  using limited_hermite_detail::minmod;
  using limited_hermite_detail::parabola_slope;
  // The window of at most six nodes the two slopes need, read once.
  const std::size_t first = cell >= 2 ? cell - 2 : 0, last = std::min(n - 1, cell + 3);
  double xs[6], vs[6];
  for (std::size_t k = first; k <= last; ++k) xs[k - first] = x(k), vs[k - first] = v(k);
  const auto slope = [&](std::size_t node) {
    if (n == 2) return (vs[1] - vs[0]) / (xs[1] - xs[0]);
    const std::size_t w = node - first;  // the node in the window
    double s = 0.0;
    bool any = false;
    // Stencils (node - 2, node - 1, node), (node - 1, node, node + 1), (node, node + 1, node + 2).
    for (std::size_t a = (node >= 2 ? node - 2 : 0); a <= node && a + 2 < n; ++a) {
      if (a < first || a + 2 > last) continue;
      const std::size_t i = a - first;
      const double candidate =
          parabola_slope(xs[i], xs[i + 1], xs[i + 2], vs[i], vs[i + 1], vs[i + 2], xs[w]);
      s = any ? minmod(s, candidate) : candidate;
      any = true;
    }
    // An outer node has its one-sided stencil only: limited to 3 x its cell's secant (Fritsch and
    // Carlson's bound), so the outer cell stays monotone where the data are.
    if (node == 0) s = minmod(s, 3.0 * (vs[1] - vs[0]) / (xs[1] - xs[0]));
    if (node == n - 1) s = minmod(s, 3.0 * (vs[w] - vs[w - 1]) / (xs[w] - xs[w - 1]));
    return s;
  };
  const std::size_t w = cell - first;
  const double dx = xs[w + 1] - xs[w];
  const double s0 = slope(cell), s1 = slope(cell + 1);
  const double t2 = t * t, t3 = t2 * t;
  return (2.0 * t3 - 3.0 * t2 + 1.0) * vs[w] + (t3 - 2.0 * t2 + t) * dx * s0 + (3.0 * t2 - 2.0 * t3) * vs[w + 1] +
         (t3 - t2) * dx * s1;
}

}  // namespace dc
