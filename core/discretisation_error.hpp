#pragma once
// The discretisation error of a result from its values on a sequence of grids (docs/accuracy.md).
//
// Grids h_0 < h_1 < h_2 with the ratio r = h_1 / h_0 (= h_2 / h_1). For a quantity converging
// as Q_h = Q* + C h^p:
//   observed order      p = ln((Q_2 - Q_1) / (Q_1 - Q_0)) / ln r                (three grids)
//   Richardson          Q* = Q_0 + (Q_0 - Q_1) / (r^p - 1),  error of Q_0 = |Q_0 - Q*|
// The estimate must not fall below the true error (issue 28: in 9 cases of 10), so it is made
// conservative in three ways, each measured on the closed-form cases of docs/accuracy.md:
//   - the order used is min(observed, expected): an observed order above the expected one on a
//     coarse grid (the contact set still moving) would shrink the estimate; in 3-D at least
//     ErrorEstimateOptions::smallest_order (a low observed order is the contact set moving too);
//   - the error predicted from the coarser pair, |Q_1 - Q_2| / ((r^p - 1) r^p), is taken when it
//     is larger: a fine pair that agrees by chance (the contact set just gained an element) does
//     not make the estimate vanish;
//   - Roache's safety factor (1.25 with three grids, 3 with two).
// A quantity that does not converge monotonically (an element is in the contact or not: contact
// and stick areas, counts) gets a band instead: first order on average, by whole elements,
// safety x max(|Q_0 - Q_1| / (r - 1), |Q_1 - Q_2| / ((r - 1) r)) (three grids: 1.25; two: 3). A smooth
// quantity whose three values are not monotone gets the band max(|Q_0 - Q_1|, |Q_1 - Q_2| / r^p)
// (3-D: the bound of the differences at the expected order, order_bound_when_not_monotone).
#include <optional>
#include <string>
#include <vector>

namespace dc {

/// How a quantity converges with the element size.
enum class Convergence {
  smooth,  ///< Q_h = Q* + C h^p: Richardson extrapolation
  band,    ///< not monotone (whole elements in or out): a first-order band of the changes
  /// A local peak (the largest pressure): smooth where the solution is, but without a continuum
  /// value at a singular edge (a flat punch's rim: p ~ 1/sqrt(distance), the peak grows as
  /// h^-1/2). Three values that change in one direction by growing steps (observed order below
  /// -0.25) are "diverging": error infinite.
  peak,
  /// A peak on the contact's rim (a punch, a sharp profile edge): "diverging" as `peak`, else the
  /// band (one rim element's value: no O(h^2) to extrapolate).
  rim_peak
};

/// One quantity's value on one grid.
struct GridValue {
  double h = 0.0;  ///< element size (any consistent measure: the grids' ratio is what counts)
  double value = 0.0;
};

struct DiscretisationError {
  double value = 0.0;         ///< on the finest grid
  double extrapolated = 0.0;  ///< Richardson's Q* (band: the finest value)
  double error = 0.0;         ///< estimated |Q_0 - Q_continuum| (absolute)
  double relative_error = 0.0;  ///< error / max(|value|, scale): what targets are compared with
  std::optional<double> order;  ///< observed order used (three monotone grids); none otherwise
  std::string method;  ///< "richardson", "assumed_order" (two grids), "band", "diverging" (a peak)
};

struct ErrorEstimateOptions {
  /// The order a smooth quantity is credited with at most. Piecewise-constant elements give
  /// O(h^2) for the peak pressure, but the approach and the forces converge at 1.6-2 from grid
  /// to grid as the contact set moves (docs/accuracy.md): 1.75 keeps the estimate above the true
  /// error on the closed-form cases measured there.
  double expected_order = 1.75;
  /// The order a smooth quantity is credited with at least where three monotone grids observe a
  /// lower one (0: none). In 3-D the approach's observed order falls to 0.9-1.5 on some grids
  /// while it converges at O(h^2) overall: the contact set moving by whole elements, not the
  /// convergence. 1.5 brought its estimate within 1-3 x the true error on 70 % of 274 grids of
  /// spheres and ellipsoids (from 50 %, none more below: docs/accuracy.md).
  double smallest_order = 0.0;
  /// A smooth quantity whose three values are not monotone: the monotone bound at the expected
  /// order, safety x max(|Q_0 - Q_1| / (r^p - 1), |Q_1 - Q_2| / ((r^p - 1) r^p)), instead of the
  /// band of the last change (which measured 2-D's edge effects; in 3-D it was above 3 x the true
  /// error on 49 of 67 such grids of the approach, the bound on 9, neither below it).
  bool order_bound_when_not_monotone = false;
  double safety_three_grids = 1.25;  ///< Roache's factor with an observed order
  double safety_two_grids = 3.0;     ///< with an assumed order only
  /// The scale below which a value counts as zero for the relative error (e.g. the load): a
  /// quantity that is zero in the continuum (a tangential force at zero creepage) gets its
  /// error relative to this, not to its own round-off.
  double scale = 0.0;
  /// A band no smaller than the largest change between the grids: in 2-D, where the place of the
  /// contact edge within an element moves a result by up to 10 x its smooth error from grid to
  /// grid (Carter's creepage on 50 and 100 strips falls below the first-order band).
  bool band_at_least_largest_change = false;
};

/// One quantity on one element size: on the grid asked for, and its mean over that grid and the
/// grids shifted by fractions of an element (the contact edge at other places within an element).
struct ShiftedGridValue {
  double h = 0.0;
  double value = 0.0;       ///< on the unshifted grid
  double shifted_mean = 0.0;  ///< over the unshifted and shifted grids
};

/// With shifted grids (2-D, where a solve is cheap): where the contact edge falls in an element
/// changes a result by up to 10 x its smooth error, from grid to grid. Averaged over the shifts
/// that part cancels, and the means converge cleanly: Richardson on the means gives the
/// continuum value Q*, from the finer pair and from the coarser pair. The error of the grid's
/// own value is its distance to Q* plus the two extrapolations' difference, times 2.
/// Three element sizes, finest first; means not monotone: the estimate without them.
DiscretisationError estimate_discretisation_error_shifted(const std::vector<ShiftedGridValue>& values,
                                                          Convergence kind, const ErrorEstimateOptions& options = {});

/// The estimate from `values`, finest grid first (two or three grids; more are ignored).
/// Throws std::invalid_argument for fewer than two grids or grid sizes not increasing.
DiscretisationError estimate_discretisation_error(const std::vector<GridValue>& values, Convergence kind,
                                                  const ErrorEstimateOptions& options = {});

}  // namespace dc
