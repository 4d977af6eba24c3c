#pragma once
// The shakedown limit depth by depth: the cross-check of the program of shakedown_problem.hpp,
// with no Ipopt.
//
// Given lambda, program (1) separates by depth: depth j is safe at lambda iff some y satisfies
// |lambda u_ij + W y| <= 1 for every position i (nlp/shakedown_samples.hpp). With W = Q R
// (p independent columns) and u = Q Q'u + u_perp,
//   |lambda u + W y|^2 = lambda^2 |u_perp|^2 + |t - c_i|^2,   t = R y,  c_i = -lambda Q'u_i,
// so depth j is safe iff every w_i = 1 - lambda^2 |u_perp,i|^2 >= 0 and the disks
// |t - c_i|^2 <= w_i in R^p intersect:
//   p = 0: lambda max_i |u_i| <= 1;
//   p = 1: an interval intersection, max_i (c_i - sqrt w_i) <= min_i (c_i + sqrt w_i) (exact;
//          Tresca in the x-z plane with rho_xx, Johnson 1985 chapter 9);
//   p >= 2: min_t max_i (|t - c_i|^2 - w_i) <= 0, the weighted enclosing ball of
//          core/enclosing_ball.hpp (exact up to rounding; von Mises with rho_xx, rho_yy).
// Each depth's safe set is an interval [0, lambda_j] (convex, containing 0), found by bisection
// from the bracket [0, min(1 / max_i |u_perp,i|, 1 / R)], R the radius of the ball enclosing the
// Q'u_i (a safe lambda needs every c_i within 1 of a common t); lambda* = min_j lambda_j.
#include <vector>

#include "shakedown_input.hpp"
#include "shakedown_samples.hpp"
#include "yield_criterion.hpp"

namespace dc {

struct DepthShakedownLimits {
  /// lambda_j, the largest safe load factor of depth j found by bisection (a safe value, within
  /// the relative tolerance of the limit); +inf when the depth never limits lambda.
  std::vector<double> load_factor;
  double min_load_factor = 0.0;  ///< min_j lambda_j: the shakedown limit
  int critical_depth = -1;       ///< its depth index
  int bisection_steps = 0;       ///< the most steps one depth took
};

/// True when depth `depth` is safe at `load_factor` (an admissible residual exists).
bool depth_is_safe(const ShakedownSamples& samples, int depth, double load_factor);

/// Every depth's limit, bisected to `relative_tol` (in (0, 0.1]). Throws std::invalid_argument
/// for invalid input.
DepthShakedownLimits shakedown_by_depth(const StressHistory& history, const YieldCriterion& criterion,
                                        const ResidualModel& model = ResidualModel::line_contact(),
                                        double relative_tol = 1e-12);

}  // namespace dc
