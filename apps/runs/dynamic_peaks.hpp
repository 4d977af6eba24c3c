#pragma once
// The peaks of a dynamic run (summary.json "peaks"): the largest contact force, approach and
// contact area (force and approach between the steps: the vertex of the parabola through the
// largest step and its neighbours, so that the time step's sampling does not cut the peak by
// O(dt^2)), and for an impact the first touch, the release, the contact time between them and
// the rebound speed at the release. The touch and the release are where the body's lowest point
// crosses the surface (linear in z - radius between the steps, an upright body): the continuum's
// contact, which Hertz's contact time measures. (The discrete contact force starts and ends a
// little later and earlier, where the grid's lowest element centre crosses; taken there, the
// contact time is off by 2 h_min / v, 5-50 x its error on the ball impact's grids.) Issue 28's
// dynamic error estimates are made for these.
#include <algorithm>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_quantities.hpp"
#include "dynamic_simulation.hpp"

namespace dc::runs {

/// The largest value of a sampled function of time, refined between the samples by a parabola
/// through the largest sample and its two neighbours.
class PeakBetweenSteps {
 public:
  void add(double t, double value);
  double value() const { return std::max(peak_, largest_sample_); }

 private:
  int count_ = 0;
  double t0_ = 0.0, f0_ = 0.0, t1_ = 0.0, f1_ = 0.0;  // the two samples before the newest
  double largest_sample_ = 0.0, peak_ = 0.0, peak_sample_ = 0.0;
};

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
  bool started_ = false;
  double previous_time_ = 0.0, previous_gap_ = 0.0, previous_vz_ = 0.0;
  PeakBetweenSteps max_force_, max_approach_;
  double max_area_ = 0.0;
  double last_descent_ = kNone;  ///< the latest fall of the lowest point through the surface
  double first_touch_ = kNone, release_ = kNone, rebound_velocity_ = kNone;
};

}  // namespace dc::runs
