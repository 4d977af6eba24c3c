#pragma once
// The peaks of a dynamic run (summary.json "peaks"): the largest contact force, approach and
// contact area, and for an impact the first touch, the release, the contact time between them and
// the rebound speed at the release. The touch and the release are placed between the steps where
// the contact began and ended, where the body's lowest point crosses the surface (linear in the
// gap z - radius of an upright body). Issue 28's dynamic error estimates are made for these.
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_quantities.hpp"
#include "dynamic_simulation.hpp"

namespace dc::runs {

class ContactPeaks {
 public:
  /// `radius`: the height of the body's centre of mass over its lowest point (DynamicSpec::radius).
  explicit ContactPeaks(double radius) : radius_(radius) {}
  void add(const dynamics::DynamicSample& s);

  /// {max_normal_force, max_approach, max_contact_area, first_touch, release, contact_time,
  ///  rebound_velocity}; the impact's keys null when the run has no touch or no release.
  nlohmann::json to_json() const;
  /// The same as results for an error estimate (accuracy_quantities.hpp): the largest force and
  /// approach, the contact time and rebound speed (smooth), the largest area (a band).
  std::vector<QuantityValue> quantities() const;

 private:
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  double radius_;
  bool started_ = false, previous_contact_ = false;
  double previous_time_ = 0.0, previous_gap_ = 0.0, previous_vz_ = 0.0;
  double max_force_ = 0.0, max_approach_ = 0.0, max_area_ = 0.0;
  double first_touch_ = kNone, release_ = kNone, rebound_velocity_ = kNone;
};

}  // namespace dc::runs
