#include "transient_flash_temperature.hpp"

#include <algorithm>
#include <stdexcept>

#include "errors.hpp"

namespace dc {
namespace {

/// max over the grid of a + c b.
double transient_max(const std::vector<double>& a, double c, const std::vector<double>& b) {
  double m = a.empty() ? 0.0 : a[0] + c * b[0];
  for (std::size_t e = 0; e < a.size(); ++e) m = std::max(m, a[e] + c * b[e]);
  return m;
}

}  // namespace

TransientFlashTemperature::TransientFlashTemperature(const Grid& grid, const ThermalProperties& base,
                                                     const ThermalProperties& body, const HeatPartition& partition,
                                                     double step, double duration,
                                                     const TransientHeatOptions& options,
                                                     const std::string& base_key, const std::string& body_key,
                                                     const std::string& partition_key)
    : grid_(grid),
      partition_(partition),
      base_(grid, base, step, duration, options, base_key),
      body_(grid, body, step, duration, options, body_key),
      free_base_(grid.size()),
      free_body_(grid.size()),
      response_base_(grid.size()),
      response_body_(grid.size()) {
  if (partition.rule == HeatPartition::Rule::pointwise)
    throw InputError(partition_key, "the pointwise partition is not offered by the transient temperature: use "
                                    "auto, equal_mean, equal_max or a fraction");
  if (partition.rule == HeatPartition::Rule::fixed && !(partition.base_fraction >= 0.0 && partition.base_fraction <= 1.0))
    throw InputError(partition_key, "a fixed fraction of the heat into the base must lie in [0, 1]");
}

double TransientFlashTemperature::fraction(const std::vector<double>& q) const {
  switch (partition_.rule) {
    case HeatPartition::Rule::fixed:
      return partition_.base_fraction;
    case HeatPartition::Rule::equal_mean: {
      const double rb = heated_mean(response_base_, q), rd = heated_mean(response_body_, q);
      if (!(rb + rd > 0.0)) return 0.5;  // no heat this step: any fraction
      const double f = (heated_mean(free_body_, q) + rd - heated_mean(free_base_, q)) / (rb + rd);
      return std::clamp(f, 0.0, 1.0);
    }
    case HeatPartition::Rule::equal_max: {
      const auto gap = [&](double f) {
        return transient_max(free_base_, f, response_base_) - transient_max(free_body_, 1.0 - f, response_body_);
      };
      if (gap(0.0) >= 0.0) return 0.0;
      if (gap(1.0) <= 0.0) return 1.0;
      double lo = 0.0, hi = 1.0;
      while (hi - lo > 1e-12) {
        const double mid = 0.5 * (lo + hi);
        (gap(mid) < 0.0 ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    case HeatPartition::Rule::pointwise:
      break;
  }
  return 0.5;
}

FlashTemperatureResult TransientFlashTemperature::step(double h, double base_speed, double body_speed,
                                                       const std::vector<double>& heat_flux) {
  const std::size_t N = grid_.size();
  if (heat_flux.size() != N)
    throw std::invalid_argument("transient flash temperature: the heat flux needs one value per element (" +
                                std::to_string(N) + "), got " + std::to_string(heat_flux.size()));
  FlashTemperatureResult r;
  flash_flux_totals(grid_, heat_flux, r);
  base_.prepare(h, base_speed, heat_flux.data(), free_base_.data(), response_base_.data());
  body_.prepare(h, body_speed, heat_flux.data(), free_body_.data(), response_body_.data());
  const double f = r.heated_elements > 0 ? fraction(heat_flux) : 0.5;
  base_.commit(f);
  body_.commit(1.0 - f);
  r.base.resize(N);
  r.body.resize(N);
  for (std::size_t e = 0; e < N; ++e) {
    r.base[e] = free_base_[e] + f * response_base_[e];
    r.body[e] = free_body_[e] + (1.0 - f) * response_body_[e];
  }
  r.base_flux_fraction.assign(N, f);
  r.base_fraction = f;
  flash_result_statistics(heat_flux, r);
  return r;
}

}  // namespace dc
