#pragma once
// The field inside the bodies of a dynamic run (CASES.md "subsurface", "yield", "fatigue"): what
// the run keeps while it runs (the tractions of its snapshots, output.snapshot_every, and of the
// step with the largest normal force) and, after it, summary.json's entries from them: the field
// of each kept state and the worst over the run (subsurface_series.hpp), the worst utilisation
// (first_yield.hpp) and Dang Van's index of the base's material points over the snapshots
// (fatigue_over_run.hpp). One code path for the command line (dynamic_run.cpp, which also writes
// each state's field) and the Python module.
#include <optional>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "dynamic_simulation.hpp"
#include "static_fields.hpp"
#include "subsurface_series.hpp"

namespace dc::runs {

/// The contact fields of a step (fields.csv's columns); zero without contact.
output::StaticFields dynamic_step_fields(const Grid& grid, const dynamics::ContactState& cs);

class DynamicSubsurface {
 public:
  /// `c` must outlive this object.
  explicit DynamicSubsurface(const Case& c);
  /// A subsurface block, a yield strength or a fatigue criterion: the field is wanted.
  bool wanted() const { return wanted_; }
  /// After an accepted step on `grid`: keeps the tractions of a snapshot (`snapshot`: that step's
  /// fields, or nullptr when the step is none) and of the largest normal force so far.
  void observe(const Grid& grid, const dynamics::DynamicSample& s, const output::StaticFields* snapshot);
  /// summary["subsurface"], ["yield"], ["fatigue"] from the kept states, each state's field
  /// passed to `write` (may be empty); nothing when no state was kept. Returns the series.
  std::optional<SubsurfaceSeries> add_entries(const Grid& grid, const SubsurfaceSink& write,
                                              nlohmann::json& summary) const;

 private:
  const Case& case_;
  bool wanted_ = false;
  SubsurfaceStates states_;
};

}  // namespace dc::runs
