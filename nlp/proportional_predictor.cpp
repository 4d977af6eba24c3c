#include "proportional_predictor.hpp"

#include <algorithm>
#include <cmath>

namespace dc {

void ProportionalPredictor::record(const Load& load, const std::vector<double>& tau,
                                   const std::vector<double>& pressure) {
  if (states_.size() == 2) states_.erase(states_.begin());
  states_.push_back({load, tau, pressure});
}

void ProportionalPredictor::clear() { states_.clear(); }

double ProportionalPredictor::ratio(const Load& older, const Load& last, const Load& next) {
  const std::size_t n = next.values.size();
  if (older.values.size() != n || last.values.size() != n || older.kinds != next.kinds || last.kinds != next.kinds)
    return 0.0;
  // Each value against its own size (the values have different units).
  std::vector<double> scale(n);
  for (std::size_t j = 0; j < n; ++j)
    scale[j] = std::max({std::abs(older.values[j]), std::abs(last.values[j]), std::abs(next.values[j])});
  // r from the value that changed most (relative to its size), then every value must follow it.
  std::size_t lead = n;
  double lead_change = 1e-12;
  for (std::size_t j = 0; j < n; ++j) {
    const double d = scale[j] > 0.0 ? std::abs(last.values[j] - older.values[j]) / scale[j] : 0.0;
    if (d > lead_change) {
      lead = j;
      lead_change = d;
    }
  }
  if (lead == n) return 0.0;  // the last step held the load: no direction to continue
  const double r = (next.values[lead] - last.values[lead]) / (last.values[lead] - older.values[lead]);
  if (!(r > 0.0 && r <= 2.0)) return 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double expected = r * (last.values[j] - older.values[j]);
    if (std::abs(next.values[j] - last.values[j] - expected) > 1e-9 * scale[j]) return 0.0;
  }
  return r;
}

bool ProportionalPredictor::predict(const Load& load, std::vector<double>& tau, std::vector<double>& pressure) const {
  if (states_.size() != 2) return false;
  const State& a = states_[0];
  const State& b = states_[1];
  if (a.tau.size() != b.tau.size() || a.pressure.size() != b.pressure.size()) return false;
  const double r = ratio(a.load, b.load, load);
  if (r == 0.0) return false;
  tau.resize(b.tau.size());
  for (std::size_t i = 0; i < tau.size(); ++i) tau[i] = b.tau[i] + r * (b.tau[i] - a.tau[i]);
  pressure.resize(b.pressure.size());
  for (std::size_t i = 0; i < pressure.size(); ++i)
    pressure[i] = std::max(0.0, b.pressure[i] + r * (b.pressure[i] - a.pressure[i]));
  return true;
}

}  // namespace dc
