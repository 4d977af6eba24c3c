#include "temperature_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "flash_temperature.hpp"

namespace dc::runs {
namespace {

const char* partition_name(HeatPartition::Rule r) {
  switch (r) {
    case HeatPartition::Rule::equal_mean: return "equal_mean";
    case HeatPartition::Rule::equal_max: return "equal_max";
    case HeatPartition::Rule::pointwise: return "pointwise";
    case HeatPartition::Rule::fixed: return "fixed";
  }
  return "?";
}

nlohmann::json place(const Grid& g, std::size_t e) {
  const int i = static_cast<int>(e % static_cast<std::size_t>(g.nx)), j = static_cast<int>(e / static_cast<std::size_t>(g.nx));
  return g.dimension == 3 ? nlohmann::json::array({g.xc(i), g.yc(j)}) : nlohmann::json::array({g.xc(i)});
}

/// The contact's half-width along x (m): the Peclet numbers' length, reported.
double heated_half_length(const Grid& g, const std::vector<double>& q) {
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (std::size_t e = 0; e < q.size(); ++e)
    if (q[e] > 0.0) {
      const double x = g.xc(static_cast<int>(e % static_cast<std::size_t>(g.nx)));
      lo = any ? std::min(lo, x - 0.5 * g.dx) : x - 0.5 * g.dx;
      hi = any ? std::max(hi, x + 0.5 * g.dx) : x + 0.5 * g.dx;
      any = true;
    }
  return any ? 0.5 * (hi - lo) : 0.0;
}

}  // namespace

std::vector<double> power_density(const output::StaticFields& fields) {
  // Coulomb makes every share >= 0, a solver's round-off may leave a negative one of its
  // tolerance's size: no heat there.
  std::vector<double> q(fields.dissipation.size());
  for (std::size_t e = 0; e < q.size(); ++e) q[e] = std::max(0.0, fields.dissipation[e] * fields.dissipation_rate);
  return q;
}

nlohmann::json flash_entry(const ThermalSpec& t, const Grid& grid, const std::vector<double>& q,
                           const FlashTemperatureResult& r, double base_speed, double body_speed,
                           const std::string& model) {
  nlohmann::json j;
  j["partition"] = partition_name(t.partition.rule);
  const bool base_hotter = r.base_max >= r.body_max;
  // A surface without heat (full stick, no friction, or a partition of 0 or 1) has no hottest place.
  const auto where = [&](std::size_t e, double rise) { return rise > 0.0 ? place(grid, e) : nlohmann::json(); };
  j["max_rise"] = base_hotter ? r.base_max : r.body_max;
  j["at"] = base_hotter ? where(r.base_max_element, r.base_max) : where(r.body_max_element, r.body_max);
  j["base"] = {{"max_rise", r.base_max}, {"at", where(r.base_max_element, r.base_max)}, {"mean_rise", r.base_mean}};
  j["body"] = {{"max_rise", r.body_max}, {"at", where(r.body_max_element, r.body_max)}, {"mean_rise", r.body_mean}};
  j["fraction_into_base"] = r.base_fraction;
  j["heat"] = r.total_heat;
  const double L = heated_half_length(grid, q);
  const ThermalSurface base{*t.base, base_speed}, body{*t.body, body_speed};
  j["peclet"] = {{"base", base.peclet(L)}, {"body", body.peclet(L)}, {"length", L}};
  j["heated_elements"] = r.heated_elements;
  j["operator"] = model;
  return j;
}

nlohmann::json flash_temperature(const ThermalSpec& t, const Grid& grid, output::StaticFields& fields,
                                 double base_speed, double body_speed) {
  if (fields.dissipation.empty() || !(fields.dissipation_rate > 0.0))
    return {{"partition", partition_name(t.partition.rule)},
            {"max_rise", nullptr},
            {"note", "the state rolled no distance: no frictional power"}};
  const std::vector<double> q = power_density(fields);
  const ThermalSurface base{*t.base, base_speed}, body{*t.body, body_speed};
  const FlashTemperature flash(grid, base, body, OperatorKind::automatic, "materials.base.thermal",
                               "materials.body.thermal");
  const FlashTemperatureResult r = flash.compute(q, t.partition);
  fields.temperature_base = r.base;
  fields.temperature_body = r.body;
  return flash_entry(t, grid, q, r, base_speed, body_speed, flash.kind());
}

nlohmann::json add_flash_temperature(const Case& c, const Grid& grid, output::StaticFields& fields) {
  const double V = c.tangential->rolling.velocity;
  return flash_temperature(c.thermal, grid, fields, V, V);
}

}  // namespace dc::runs
