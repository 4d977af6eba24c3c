#include "dynamic_peaks.hpp"

#include <algorithm>
#include <cmath>

namespace dc::runs {
namespace {

/// Where a linear function from a (at t0) to b (at t1) is zero.
double crossing(double t0, double a, double t1, double b) {
  return a == b ? t1 : t0 + (t1 - t0) * a / (a - b);
}

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

}  // namespace

void PeakBetweenSteps::add(double t, double f) {
  largest_sample_ = std::max(largest_sample_, f);
  if (count_ >= 2 && f1_ >= f0_ && f1_ >= f && f1_ > peak_sample_) {
    // The vertex of the quadratic through (t0, f0), (t1, f1), (t, f): divided differences.
    const double a = ((f - f1_) / (t - t1_) - (f1_ - f0_) / (t1_ - t0_)) / (t - t0_);
    const double b = (f1_ - f0_) / (t1_ - t0_) - a * (t0_ + t1_);
    if (a < 0.0) {
      const double tv = std::clamp(-b / (2.0 * a), t0_, t);
      peak_ = std::max(peak_, f0_ + (tv - t0_) * ((f1_ - f0_) / (t1_ - t0_) + a * (tv - t1_)));
    }
    peak_sample_ = f1_;
  }
  t0_ = t1_;
  f0_ = f1_;
  t1_ = t;
  f1_ = f;
  ++count_;
}

void ContactPeaks::add(const dynamics::DynamicSample& s) {
  const dynamics::ContactState& cs = s.contact_state;
  const double t = s.state.time, gap = s.state.position.z() - radius_, vz = s.state.velocity.z();
  max_force_.add(t, cs.in_contact ? std::abs(s.contact.force.z()) : 0.0);
  max_approach_.add(t, cs.in_contact ? cs.approach : 0.0);
  if (cs.in_contact) max_area_ = std::max(max_area_, cs.contact_area);
  if (!started_) {  // the first step: a body that starts touching touched at t = 0
    if (gap <= 0.0) last_descent_ = 0.0;
  } else if (previous_gap_ > 0.0 && gap <= 0.0) {
    last_descent_ = crossing(previous_time_, previous_gap_, t, gap);
  }
  if (cs.in_contact && std::isnan(first_touch_)) first_touch_ = std::isfinite(last_descent_) ? last_descent_ : t;
  // The release: the first rise of the lowest point through the surface once the contact force
  // has gone (the discrete contact opens a little earlier, at the lowest element centre).
  if (started_ && std::isfinite(first_touch_) && std::isnan(release_) && !cs.in_contact && previous_gap_ <= 0.0 &&
      gap > 0.0) {
    release_ = crossing(previous_time_, previous_gap_, t, gap);
    const double w = (release_ - previous_time_) / (t - previous_time_);
    rebound_velocity_ = (1.0 - w) * previous_vz_ + w * vz;
  }
  started_ = true;
  previous_time_ = t;
  previous_gap_ = gap;
  previous_vz_ = vz;
}

nlohmann::json ContactPeaks::to_json() const {
  const double duration = std::isfinite(release_) && std::isfinite(first_touch_) ? release_ - first_touch_ : kNone;
  return {{"max_normal_force", max_force_.value()},
          {"max_approach", max_approach_.value()},
          {"max_contact_area", max_area_},
          {"first_touch", number_or_null(first_touch_)},
          {"release", number_or_null(release_)},
          {"contact_time", number_or_null(duration)},
          {"rebound_velocity", number_or_null(rebound_velocity_)}};
}

std::vector<QuantityValue> ContactPeaks::quantities() const {
  using C = Convergence;
  std::vector<QuantityValue> q = {{"max_normal_force", max_force_.value(), C::smooth, 0.0},
                                  {"max_approach", max_approach_.value(), C::smooth, 0.0},
                                  {"max_contact_area", max_area_, C::band, 0.0}};
  if (std::isfinite(release_)) {
    q.push_back({"contact_time", release_ - first_touch_, C::smooth, 0.0});
    q.push_back({"rebound_velocity", rebound_velocity_, C::smooth, 0.0});
  }
  return q;
}

}  // namespace dc::runs
