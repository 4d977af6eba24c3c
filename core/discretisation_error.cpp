#include "discretisation_error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dc {
namespace {

/// Relative to the value, or to the scale where the value is smaller.
double relative_to(double error, double value, double scale) {
  const double denominator = std::max(std::abs(value), scale);
  return denominator > 0.0 ? error / denominator : (error > 0.0 ? HUGE_VAL : 0.0);
}

DiscretisationError band(const std::vector<GridValue>& v, const ErrorEstimateOptions& o) {
  DiscretisationError e;
  e.value = e.extrapolated = v[0].value;
  e.method = "band";
  // First order on average, by whole elements: the finer change, or the coarser change reduced by
  // one order, with Roache's factors (docs/accuracy.md "Whole-element quantities").
  const double r = v[1].h / v[0].h;
  const double fine = std::abs(v[0].value - v[1].value) / (r - 1.0);
  if (v.size() < 3) {
    e.error = o.safety_two_grids * fine;
  } else {
    const double r2 = v[2].h / v[1].h;
    const double coarse = std::abs(v[1].value - v[2].value) / ((r2 - 1.0) * r);
    e.error = o.safety_three_grids * std::max(fine, coarse);
  }
  if (o.band_at_least_largest_change)
    for (std::size_t k = 1; k < v.size() && k < 3; ++k) e.error = std::max(e.error, std::abs(v[k].value - v[k - 1].value));
  e.relative_error = relative_to(e.error, e.value, o.scale);
  return e;
}

/// A smooth quantity whose values are not monotone: the last change, or the coarser change
/// reduced by the expected order, whichever is larger (measured on the 2-D peak pressure, whose
/// error depends on where the contact edge falls in an element: docs/accuracy.md).
DiscretisationError not_monotone(const std::vector<GridValue>& v, const ErrorEstimateOptions& o) {
  DiscretisationError e;
  e.value = e.extrapolated = v[0].value;
  e.method = "band";
  e.error = std::max(std::abs(v[0].value - v[1].value),
                     std::abs(v[1].value - v[2].value) / std::pow(v[2].h / v[1].h, o.expected_order));
  e.relative_error = relative_to(e.error, e.value, o.scale);
  return e;
}

/// Three values changing in one direction by steps that grow faster than r^0.25 (observed order
/// below -0.25): a peak at a singular edge (h^-1/2 gives -0.5).
bool diverges(const std::vector<GridValue>& v) {
  if (v.size() < 3) return false;
  const double d1 = v[0].value - v[1].value, d2 = v[1].value - v[2].value;
  return d1 * d2 > 0.0 && std::abs(d1) > std::abs(d2) * std::pow(v[1].h / v[0].h, 0.25);
}

}  // namespace

DiscretisationError estimate_discretisation_error(const std::vector<GridValue>& values, Convergence kind,
                                                  const ErrorEstimateOptions& options) {
  if (values.size() < 2) throw std::invalid_argument("a discretisation error needs the values of two grids at least");
  for (std::size_t k = 1; k < values.size(); ++k)
    if (!(values[k].h > values[k - 1].h))
      throw std::invalid_argument("grid sizes must increase from the finest grid");
  const bool peak = kind == Convergence::peak || kind == Convergence::rim_peak;
  if (peak && diverges(values)) {
    DiscretisationError e;
    e.value = e.extrapolated = values[0].value;
    e.method = "diverging";
    e.error = e.relative_error = HUGE_VAL;
    return e;
  }
  if (kind == Convergence::band || kind == Convergence::rim_peak) return band(values, options);

  const double r = values[1].h / values[0].h;
  const double q0 = values[0].value, q1 = values[1].value;
  const double d1 = q0 - q1;
  DiscretisationError e;
  e.value = q0;
  double p = options.expected_order;
  double safety = options.safety_two_grids;
  double coarse_pair = 0.0;  // the error of Q_0 predicted from the coarser pair
  e.method = "assumed_order";
  if (values.size() >= 3) {
    const double r2 = values[2].h / values[1].h;
    const double d2 = q1 - values[2].value;
    // Monotone and contracting: an observed order (ratios that differ a little are taken at
    // their mean; the grids here halve, or nearly so for odd element counts).
    if (d1 * d2 > 0.0 && std::abs(d1) < std::abs(d2)) {
      const double observed = std::log(d2 / d1) / std::log(std::sqrt(r * r2));
      e.order = observed;
      e.method = "richardson";
      p = std::clamp(observed, std::min(options.smallest_order, options.expected_order), options.expected_order);
      safety = options.safety_three_grids;
    } else if (options.order_bound_when_not_monotone) {
      // No extrapolation; the bound of the differences at the expected order.
      e.method = "band";
      e.extrapolated = q0;
      e.error = options.safety_three_grids *
                std::max(std::abs(d1) / (std::pow(r, p) - 1.0), std::abs(d2) / ((std::pow(r2, p) - 1.0) * std::pow(r, p)));
      e.relative_error = relative_to(e.error, e.value, options.scale);
      return e;
    } else {
      return not_monotone(values, options);  // not in the asymptotic range: no extrapolation
    }
    coarse_pair = std::abs(d2) / ((std::pow(r2, p) - 1.0) * std::pow(r, p));
  }
  const double fine_pair = std::abs(d1) / (std::pow(r, p) - 1.0);
  // Q* by the observed order where there is one (within [1, 3]: beyond, three grids do not fix
  // it), else by the expected one; the error bound above by the conservative order.
  const double p_extrapolation = e.order ? std::clamp(*e.order, 1.0, 3.0) : p;
  e.extrapolated = q0 + d1 / (std::pow(r, p_extrapolation) - 1.0);
  e.error = std::max({e.error, safety * std::max(fine_pair, coarse_pair)});
  e.relative_error = relative_to(e.error, e.value, options.scale);
  return e;
}

DiscretisationError estimate_discretisation_error_shifted(const std::vector<ShiftedGridValue>& values,
                                                          Convergence kind, const ErrorEstimateOptions& options) {
  std::vector<GridValue> own;
  for (const ShiftedGridValue& v : values) own.push_back({v.h, v.value});
  if (values.size() < 3) return estimate_discretisation_error(own, kind, options);
  const double r = values[1].h / values[0].h, r2 = values[2].h / values[1].h;
  const double m0 = values[0].shifted_mean, m1 = values[1].shifted_mean, m2 = values[2].shifted_mean;
  const double d1 = m0 - m1, d2 = m1 - m2;
  if (!(d1 * d2 > 0.0 && std::abs(d1) < std::abs(d2))) return estimate_discretisation_error(own, kind, options);
  const double observed = std::log(d2 / d1) / std::log(std::sqrt(r * r2));
  const double p = std::clamp(observed, 1.0, 3.0);
  const double q_fine = m0 + d1 / (std::pow(r, p) - 1.0), q_coarse = m1 + d2 / (std::pow(r2, p) - 1.0);
  DiscretisationError e;
  e.value = values[0].value;
  e.extrapolated = q_fine;
  e.order = observed;
  e.method = "richardson_shifted";
  constexpr double kSafety = 2.0;
  e.error = kSafety * (std::abs(e.value - q_fine) + std::abs(q_fine - q_coarse));
  e.relative_error = relative_to(e.error, e.value, options.scale);
  return e;
}

}  // namespace dc
