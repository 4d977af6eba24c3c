#pragma once
// First yield (CASES.md "yield"): for each body with materials.<body>.yield, the utilisation
// max(sigma_eq) / strength of the solved load (von Mises sqrt(3 J2) against Y, or Tresca's tau_1
// against k) and its place, and the load factor at which the body first yields. The factor is
// solved for, not scaled: the contact grows with the load (Hertz: p0 ~ P^(1/3)), so the case is
// solved again at factor x its normal load on the same grid, the field recomputed, and the factor
// iterated (secant in log-log) until the utilisation is 1 within 1e-3. A tangential problem's
// tangential forces and moment are scaled with the normal load (its shifts, creepages, spin and
// angle are kept: a full-sliding contact stays in full sliding).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "subsurface_series.hpp"

namespace dc::runs {

struct StaticRun;

struct FirstYield {
  std::string body;
  YieldSpec criterion;
  double utilisation = 0.0;
  FieldExtreme at;                     ///< where the equivalent stress peaks
  std::optional<double> load_factor;   ///< none: see `note`
  std::string note;                    ///< why there is no factor (or "")
  int solves = 0;                      ///< the solves the factor took
};

/// The utilisation of `measures` under `criterion`, and the extreme it comes from.
double utilisation(const YieldSpec& criterion, const SubsurfaceMeasures& measures, FieldExtreme* at = nullptr);

/// Every body of `c` with a yield strength, from `run` (solved, with its subsurface field).
std::vector<FirstYield> first_yield(const Case& c, const StaticRun& run);

/// summary.json's "yield": per body utilisation, at, criterion, strength, first_yield_load_factor
/// (null with a "note" when it could not be found), solves.
nlohmann::json first_yield_json(const std::vector<FirstYield>& yields, int dimension);

/// summary.json's "yield" of a run in time (a history, a dynamic run): per body with a strength
/// the utilisation of the worst state (subsurface_series.hpp), at, step (`timed`: time),
/// criterion, strength, first_yield_load_factor null with a note (not solved for runs in time).
nlohmann::json worst_yield_json(const Case& c, const SubsurfaceSeries& series, int dimension, bool timed);

}  // namespace dc::runs
