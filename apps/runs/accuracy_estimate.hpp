#pragma once
// The error estimates of a run's results from their values on a sequence of grids (finest
// first), for the static runs (accuracy_run.hpp) and the dynamic ones (dynamic_accuracy.hpp):
// which results are reported, and the "quantities" entries of summary.json's accuracy block.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_quantities.hpp"
#include "accuracy_spec.hpp"
#include "discretisation_error.hpp"
#include "grid.hpp"

namespace dc::runs {

/// The fewest elements across the contact a coarse grid may have for its answer to count: below
/// it the peak pressure is off by tens of per cent and the sequence is not asymptotic.
inline constexpr int kMinAcross3d = 6, kMinAcross2d = 8;

struct EstimatedQuantity {
  QuantityValue quantity;
  DiscretisationError error;
  std::vector<double> values;  ///< per grid, finest first
};

/// A measure of the element size: the grids' ratio is what the estimate uses.
double element_size(const Grid& g);

/// {"nx"} (3-D also "ny").
nlohmann::json grid_json(const Grid& g);

/// What the results are of: one contact solve (a static case, a problem's solve), or a dynamic
/// run's peaks, whose values also carry the time steps' error.
enum class EstimatedRun { contact, dynamic_peaks };

/// Each result of the finest grid (per_level[0]) estimated from its values on the grids of
/// `element_sizes`; with `shifted` (per level, the results of its shifted grids: 2-D) by the
/// shifted-grid estimate. A result the case prescribes (the same on every grid) or one that is
/// zero in the continuum (within its scale on every grid) is left out. In 2-D (`dimension`) a
/// band is no smaller than the largest change between the grids; a 3-D contact's smooth results
/// are credited with an order of 1.5 at least and bounded at the expected order when not monotone
/// (ErrorEstimateOptions: smallest_order, order_bound_when_not_monotone; measured on contact
/// solves, not on a dynamic run's peaks).
std::vector<EstimatedQuantity> estimate_quantities(
    const std::vector<double>& element_sizes, const std::vector<std::vector<QuantityValue>>& per_level,
    int dimension, const std::vector<std::vector<std::vector<QuantityValue>>>* shifted = nullptr,
    EstimatedRun run = EstimatedRun::contact);

/// The results of a grid whose heights vary on the scale of the coarser grid's elements (a
/// measured or wavy profile): `unresolved` (m) is the height detail the grid of twice the element
/// size does not carry (unresolved_height, core/height_restriction.hpp). A gap perturbed by that
/// much moves the approach by as much, which the grids' differences cannot tell from their
/// discretisation error (the coarse grids alias it), so the approach's error is taken no less (the
/// normal force's, under approach control, no less than the contact's stiffness times it): then
/// a band.
void floor_by_unresolved_height(std::vector<EstimatedQuantity>& quantities, double unresolved, double stiffness);
/// The normal stiffness dP/d delta of a contact of area A: 2 E* sqrt(A / pi) (Sneddon's result for
/// any axisymmetric profile, Pharr, Oliver & Brotzen 1992 for others to a few per cent): 3/2 P/delta
/// for Hertz, P/delta for a punch, more for a conformal contact.
double contact_stiffness(double e_star, double area);

/// The "quantities" object: name -> {value, values, extrapolated, error_estimate,
/// error_estimate_absolute, method, order}.
nlohmann::json quantities_json(const std::vector<EstimatedQuantity>& quantities);

/// One grid of an estimate and the time its run took.
struct GridTime {
  Grid grid;
  double seconds = 0.0;
  const nlohmann::json* summary = nullptr;  ///< the grid's summary: its status and certificate
};

/// summary.json's accuracy block (CASES.md) of `grids` (finest first): grid, grids, then the
/// quantities and the cost fraction (the other grids' time over the finest's; `coarse_seconds`),
/// or `unavailable` (why there is no estimate) when it is not empty; target, met (null).
nlohmann::json accuracy_block(const std::vector<GridTime>& grids, const std::string& unavailable,
                              const std::vector<EstimatedQuantity>& quantities, double coarse_seconds,
                              const AccuracySpec& spec);

/// The named result's relative error; 0 when it is not among them (the case prescribes it).
double named_error(const std::vector<EstimatedQuantity>& quantities, const std::string& name);
/// The named result's estimate, null when it is not among them.
const DiscretisationError* named_estimate(const std::vector<EstimatedQuantity>& quantities, const std::string& name);

/// The refinement a target asks for: the largest ratio of a named result's error to the target,
/// and the order to refine it by (a band: 1; else the observed within [1, 2]; none: 2). An
/// estimate from two grids (the order assumed, or a band of one change) does not meet a target:
/// it is below the true error too often (Mindlin's shift on 20^2: 0.8 x); it asks for one
/// refinement, after which three grids see the quantity.
struct TargetGap {
  double worst = 0.0;  ///< <= 1: met; HUGE_VAL: a named result has no estimate
  double order = 2.0;
};
TargetGap target_gap(const std::vector<EstimatedQuantity>& quantities, bool available,
                     const std::vector<std::string>& names, double target);

/// The refinement factor (2 or 4) that brings `gap` to the target with a margin: 4 when the
/// error is far from it.
int refinement_factor(const TargetGap& gap);

}  // namespace dc::runs
