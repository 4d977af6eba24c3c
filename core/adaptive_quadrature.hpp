#pragma once
// Adaptive Gauss-Kronrod quadrature (7-point Gauss, 15-point Kronrod) of a smooth scalar
// integrand on [a, b]: the difference of the Kronrod and Gauss estimates of an interval is its
// error estimate; the worst interval is halved until they sum to the tolerance (Piessens et al.,
// QUADPACK, 1983: the rule QK15 in the global scheme of QAG). Nodes and weights: QUADPACK's qk15.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace dc {

struct QuadratureTolerance {
  double relative = 1e-13;  ///< of the integral's first (whole-interval) estimate
  double absolute = 0.0;    ///< floor (the integrand's units times the interval's)
  int max_intervals = 200;  ///< subintervals at most (then the estimate is returned as it is)
};

namespace gauss_kronrod_15 {
inline constexpr std::array<double, 8> kNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
inline constexpr std::array<double, 8> kKronrod = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
/// Gauss weights of the nodes kNodes[1], [3], [5], [7].
inline constexpr std::array<double, 4> kGauss = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/// One rule on [a, b]: the Kronrod estimate and |Kronrod - Gauss|.
template <class F>
void rule(const F& f, double a, double b, double& kronrod, double& error) {
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  const double fc = f(centre);
  double k = kKronrod[7] * fc, g = kGauss[3] * fc;
  for (int n = 0; n < 7; ++n) {
    const double dx = half * kNodes[n];
    const double sum = f(centre - dx) + f(centre + dx);
    k += kKronrod[n] * sum;
    if (n % 2 == 1) g += kGauss[n / 2] * sum;
  }
  kronrod = k * half;
  error = std::abs((k - g) * half);
}

}  // namespace gauss_kronrod_15

/// The integral of f over [a, b] (a > b gives the negative). Globally adaptive: the interval
/// with the largest error estimate is halved until the estimates sum to the tolerance or
/// `max_intervals` are in use.
template <class F>
double integrate_adaptive(const F& f, double a, double b, const QuadratureTolerance& tolerance = {}) {
  if (a == b) return 0.0;
  struct Piece {
    double a, b, value, error;
  };
  std::vector<Piece> pieces;
  pieces.reserve(static_cast<std::size_t>(tolerance.max_intervals));
  Piece whole{a, b, 0.0, 0.0};
  gauss_kronrod_15::rule(f, a, b, whole.value, whole.error);
  const double tol = std::max(tolerance.relative * std::abs(whole.value), tolerance.absolute);
  double value = whole.value, error = whole.error;
  pieces.push_back(whole);
  const auto by_error = [](const Piece& l, const Piece& r) { return l.error < r.error; };
  while (error > tol && static_cast<int>(pieces.size()) < tolerance.max_intervals) {
    std::pop_heap(pieces.begin(), pieces.end(), by_error);
    const Piece worst = pieces.back();
    pieces.pop_back();
    const double mid = 0.5 * (worst.a + worst.b);
    Piece left{worst.a, mid, 0.0, 0.0}, right{mid, worst.b, 0.0, 0.0};
    gauss_kronrod_15::rule(f, left.a, left.b, left.value, left.error);
    gauss_kronrod_15::rule(f, right.a, right.b, right.value, right.error);
    value += left.value + right.value - worst.value;
    error += left.error + right.error - worst.error;
    pieces.push_back(left);
    std::push_heap(pieces.begin(), pieces.end(), by_error);
    pieces.push_back(right);
    std::push_heap(pieces.begin(), pieces.end(), by_error);
  }
  return value;
}

}  // namespace dc
