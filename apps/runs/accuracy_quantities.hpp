#pragma once
// The results an error estimate is made for (issue 28, docs/accuracy.md), read from a static
// run's summary.json: which converge smoothly with the element size (Richardson) and which do
// not (a band).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "discretisation_error.hpp"

namespace dc::runs {

/// One result of one grid.
struct QuantityValue {
  std::string name;  ///< accuracy_quantity_names() (accuracy_spec.hpp)
  double value = 0.0;
  Convergence convergence = Convergence::smooth;
  /// What counts as zero for its relative error (a share of the load, of the friction capacity):
  /// a force that vanishes in the continuum is not judged against its own round-off.
  double scale = 0.0;
  /// An area or a width counted in whole elements (never a value the case prescribes): equal on
  /// every grid it still has the uncertainty of its edge's element.
  bool whole_elements = false;
};

/// The results of a normal or tangential summary (a history: its last step's keys) that the
/// case did not prescribe: approach or normal force (whichever the control leaves free) and peak
/// pressure (smooth), contact area (and the 2-D half-width) as bands; a tangential step adds, as
/// bands, its force (magnitude and components), twisting moment, the rigid shift or creepage it
/// found, and its stick and slip areas.
std::vector<QuantityValue> accuracy_quantities(const nlohmann::json& summary);

}  // namespace dc::runs
