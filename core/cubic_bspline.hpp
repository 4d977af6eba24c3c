#pragma once
// Clamped cubic B-splines on strictly increasing breakpoints t_0 < t_1 < ... < t_{n-1} (n >= 2):
// the knot vector repeats each end four times,
//   (t_0, t_0, t_0, t_0, t_1, .., t_{n-2}, t_{n-1}, t_{n-1}, t_{n-1}, t_{n-1}),
// so there are n + 2 basis functions B_0 .. B_{n+1}, each a C^2 piecewise cubic, non-negative,
// summing to 1 on [t_0, t_{n-1}]. At the ends only the first (last) ones reach: at t_0,
// B_0 = 1 and the others vanish, only B_0 and B_1 have a first derivative (-/+ 3 / (t_1 - t_0)),
// only B_0, B_1, B_2 a second; so a spline sum c_a B_a vanishes at t_0 with its first derivative
// iff c_0 = c_1 = 0, and vanishes there iff c_0 = 0 (mirror at t_{n-1}).
// Evaluation: the Cox-de Boor recursion with derivatives, L. Piegl, W. Tiller, The NURBS Book,
// 2nd ed., Springer 1997, algorithms A2.1 (FindSpan) and A2.3 (DersBasisFuns), for degree 3 and
// derivatives up to 2.
#include <array>
#include <vector>

namespace dc {

class CubicBSplineBasis {
 public:
  /// Throws std::invalid_argument unless there are at least 2 finite, strictly increasing breakpoints.
  explicit CubicBSplineBasis(std::vector<double> breakpoints);

  int size() const { return static_cast<int>(breakpoints_.size()) + 2; }  ///< n + 2
  const std::vector<double>& breakpoints() const { return breakpoints_; }

  /// The four basis functions that may be nonzero at t (t clamped into [t_0, t_{n-1}]):
  /// B_{first + r} and its derivatives, derivative[d][r] for d = 0, 1, 2 (zero outside the
  /// interval: the derivatives are those of the clamped spline at the end it is clamped to).
  struct Local {
    int first = 0;
    std::array<std::array<double, 4>, 3> derivative{};
  };
  Local evaluate(double t) const;

 private:
  std::vector<double> breakpoints_;
  std::vector<double> knots_;  ///< n + 6 values
};

}  // namespace dc
