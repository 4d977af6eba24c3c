#pragma once
// The smallest ball enclosing a set of points p_1..p_n in R^d, and its weighted form: the
// centre c minimising the largest power distance
//   F(c) = max_i ( |c - p_i|^2 - w_i )                                                  (1)
// (w = 0: the smallest enclosing ball, radius sqrt(min F)). Each term is |c|^2 plus an affine
// function of c, so (1) is a strictly convex LP-type problem of combinatorial dimension d + 1:
// its minimiser is the ball through at most d + 1 support points, found exactly (up to
// rounding) by Welzl's algorithm in its move-to-front form (E. Welzl, "Smallest enclosing disks
// (balls and ellipsoids)", LNCS 555, 1991; B. Gaertner, "Fast and robust smallest enclosing
// balls", ESA 1999, LNCS 1643). Used by the Dang Van criterion (core/dang_van.hpp: 5-D
// deviatoric paths, w = 0) and by the shakedown program's per-depth cross-check
// (nlp/shakedown_by_depth.hpp: the intersection of disks |y - c_i|^2 <= w_i is non-empty iff
// min F <= 0).
//
// Certificate (the program's own, from the KKT conditions of min t s.t. |c - p_i|^2 - w_i <= t):
// multipliers mu_k >= 0 on the support, sum mu_k = 1, and c = sum_k mu_k p_k (the centre lies in
// the convex hull of its support points). For any mu in the simplex the Lagrange dual value
//   D(mu) = sum_k mu_k ( |c_mu - p_k|^2 - w_k ),   c_mu = sum_k mu_k p_k,                (2)
// is a lower bound on min F, and F(c) an upper bound: F(c) - D(mu) >= 0 bounds the error of the
// returned optimum (0 at the exact solution).
#include <vector>

#include <Eigen/Core>

namespace dc {

struct EnclosingBall {
  Eigen::VectorXd centre;          ///< c
  double value = 0.0;              ///< F(c), over every point (the squared radius when w = 0)
  std::vector<int> support;        ///< indices of the support points (at most d + 1)
  std::vector<double> multipliers; ///< mu_k on the support: c = sum mu_k p_k, sum mu_k = 1
  // The certificate.
  double dual_value = 0.0;     ///< D(mu) of (2) with mu clipped to >= 0 and renormalised
  double min_multiplier = 0.0; ///< the smallest mu_k (negative: the centre is outside the support's hull)
  double hull_residual = 0.0;  ///< |c - sum mu_k p_k| with the clipped mu
  /// The data's scale for relative tolerances: the largest squared distance of a point from the
  /// first plus the spread of the weights (0 when every point coincides and the weights agree).
  double scale = 0.0;

  /// sqrt(max(value, 0)): the radius of the smallest enclosing ball (w = 0).
  double radius() const;
  /// (value - dual_value) / scale (0 when scale is 0): the relative duality gap.
  double relative_gap() const;
  /// True when min_multiplier >= -tol, hull_residual <= tol * sqrt(scale) and relative_gap() <= tol.
  bool certified(double tol = 1e-9) const;
};

/// The smallest ball enclosing the columns of `points` (d x n, n >= 1, every entry finite).
EnclosingBall smallest_enclosing_ball(const Eigen::MatrixXd& points);

/// The minimiser of the largest power distance (1), `weights` of size n (finite). Throws
/// std::invalid_argument for empty or non-finite input or mismatched sizes.
EnclosingBall minimax_power_distance(const Eigen::MatrixXd& points, const Eigen::VectorXd& weights);

}  // namespace dc
