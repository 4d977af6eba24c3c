#include "flash_temperature.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "errors.hpp"
#include "gmres.hpp"
#include "number_text.hpp"

namespace dc {
namespace {

/// The maximum and its element, and the mean over the heated elements.
void flash_statistics(const std::vector<double>& T, const std::vector<double>& q, double& max, std::size_t& where,
                      double& mean) {
  max = T.empty() ? 0.0 : T[0];
  where = 0;
  for (std::size_t e = 0; e < T.size(); ++e)
    if (T[e] > max) {
      max = T[e];
      where = e;
    }
  mean = heated_mean(T, q);
}

double flash_max(const std::vector<double>& T) {
  double m = T.empty() ? 0.0 : T[0];
  for (double v : T) m = std::max(m, v);
  return m;
}
}  // namespace

double heated_mean(const std::vector<double>& T, const std::vector<double>& q) {
  double sum = 0.0;
  std::size_t heated = 0;
  for (std::size_t e = 0; e < T.size(); ++e)
    if (q[e] > 0.0) {
      sum += T[e];
      ++heated;
    }
  return heated > 0 ? sum / static_cast<double>(heated) : 0.0;
}

FlashTemperature::FlashTemperature(const Grid& grid, const ThermalSurface& base, const ThermalSurface& body,
                                   OperatorKind kind, const std::string& base_key, const std::string& body_key)
    : grid_(grid),
      base_(base),
      body_(body),
      base_table_(heat_influence_table(grid, base, base_key)),
      body_table_(heat_influence_table(grid, body, body_key)),
      base_op_(make_convolution_operator(grid, {base_table_}, 1, 1, kind)),
      body_op_(make_convolution_operator(grid, {body_table_}, 1, 1, kind)) {}

void FlashTemperature::surface_temperature(BodySide side, const double* flux, double* temperature) const {
  (side == BodySide::base ? base_op_ : body_op_)->apply(flux, temperature);
}

std::vector<double> FlashTemperature::surface_temperature(BodySide side, const std::vector<double>& flux) const {
  if (flux.size() != grid_.size())
    throw std::invalid_argument("surface temperature: the flux needs one value per element (" +
                                std::to_string(grid_.size()) + "), got " + std::to_string(flux.size()));
  std::vector<double> T(grid_.size());
  surface_temperature(side, flux.data(), T.data());
  return T;
}

std::vector<double> FlashTemperature::pointwise_base_flux(const std::vector<double>& q,
                                                          const std::vector<double>& body_full, double start_fraction,
                                                          std::size_t dense_limit) const {
  std::vector<std::size_t> heated;
  for (std::size_t e = 0; e < q.size(); ++e)
    if (q[e] > 0.0) heated.push_back(e);
  const std::size_t n = heated.size();
  std::vector<double> rhs(n), g(n);
  for (std::size_t r = 0; r < n; ++r) {
    rhs[r] = body_full[heated[r]];  // (A_body q) on S: all the flux into the body
    g[r] = start_fraction * q[heated[r]];
  }
  if (n <= dense_limit) {
    Eigen::MatrixXd m(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (std::size_t r = 0; r < n; ++r) {
      const int io = static_cast<int>(heated[r] % grid_.nx), jo = static_cast<int>(heated[r] / grid_.nx);
      for (std::size_t c = 0; c < n; ++c) {
        const int ii = static_cast<int>(heated[c] % grid_.nx), ji = static_cast<int>(heated[c] / grid_.nx);
        m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
            base_table_.at(io - ii, jo - ji) + body_table_.at(io - ii, jo - ji);
      }
    }
    Eigen::Map<Eigen::VectorXd>(g.data(), static_cast<Eigen::Index>(n)) =
        m.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(rhs.data(), static_cast<Eigen::Index>(n)));
  } else {
    std::vector<double> full(grid_.size(), 0.0), t_base(grid_.size()), t_body(grid_.size());
    const VectorMap apply = [&](const std::vector<double>& in, std::vector<double>& out) {
      for (std::size_t r = 0; r < n; ++r) full[heated[r]] = in[r];
      base_op_->apply(full.data(), t_base.data());
      body_op_->apply(full.data(), t_body.data());
      out.resize(n);
      for (std::size_t r = 0; r < n; ++r) out[r] = t_base[heated[r]] + t_body[heated[r]];
    };
    const GmresResult result = gmres(apply, VectorMap{}, rhs, g, 1e-12, 60, 3000);
    if (!result.converged)
      throw SolverFailure("pointwise heat partition: GMRES stopped at relative residual " +
                          six_digits(result.relative_residual) + " after " + std::to_string(result.iterations) +
                          " iterations");
  }
  std::vector<double> base_flux(q.size(), 0.0);
  for (std::size_t r = 0; r < n; ++r) base_flux[heated[r]] = g[r];
  return base_flux;
}

FlashTemperatureResult FlashTemperature::compute(const std::vector<double>& heat_flux,
                                                 const HeatPartition& partition) const {
  const std::size_t N = grid_.size();
  if (heat_flux.size() != N)
    throw std::invalid_argument("flash temperature: the heat flux needs one value per element (" +
                                std::to_string(N) + "), got " + std::to_string(heat_flux.size()));
  FlashTemperatureResult r;
  flash_flux_totals(grid_, heat_flux, r);
  if (partition.rule == HeatPartition::Rule::fixed &&
      !(partition.base_fraction >= 0.0 && partition.base_fraction <= 1.0))
    throw InputError("partition", "a fixed fraction of the heat into the base must lie in [0, 1], got " +
                                      six_digits(partition.base_fraction));

  // Each surface's temperature under the whole flux; the equal-mean, equal-max and fixed rules
  // scale them (T_s is linear in its share).
  const std::vector<double> base_full = surface_temperature(BodySide::base, heat_flux);
  const std::vector<double> body_full = surface_temperature(BodySide::body, heat_flux);
  double f = partition.base_fraction;
  switch (partition.rule) {
    case HeatPartition::Rule::fixed:
      break;
    case HeatPartition::Rule::equal_mean:
    case HeatPartition::Rule::equal_max: {
      const bool mean = partition.rule == HeatPartition::Rule::equal_mean;
      const double mb = mean ? heated_mean(base_full, heat_flux) : flash_max(base_full);
      const double md = mean ? heated_mean(body_full, heat_flux) : flash_max(body_full);
      f = mb + md > 0.0 ? md / (mb + md) : 0.5;  // no heat: every fraction gives equal (zero) temperatures
      break;
    }
    case HeatPartition::Rule::pointwise:
      break;
  }

  r.base.resize(N);
  r.body.resize(N);
  r.base_flux_fraction.assign(N, f);
  if (partition.rule == HeatPartition::Rule::pointwise && r.heated_elements > 0) {
    // The equal-mean share starts GMRES.
    const double mb = heated_mean(base_full, heat_flux), md = heated_mean(body_full, heat_flux);
    const std::vector<double> g = pointwise_base_flux(heat_flux, body_full, md / (mb + md), partition.dense_limit);
    std::vector<double> rest(N);
    double into_base = 0.0;
    for (std::size_t e = 0; e < N; ++e) {
      rest[e] = heat_flux[e] - g[e];
      into_base += g[e] * grid_.area();
    }
    f = into_base / r.total_heat;
    surface_temperature(BodySide::base, g.data(), r.base.data());
    surface_temperature(BodySide::body, rest.data(), r.body.data());
    for (std::size_t e = 0; e < N; ++e) r.base_flux_fraction[e] = heat_flux[e] > 0.0 ? g[e] / heat_flux[e] : f;
  } else {
    if (partition.rule == HeatPartition::Rule::pointwise) f = 0.5;
    for (std::size_t e = 0; e < N; ++e) {
      r.base[e] = f * base_full[e];
      r.body[e] = (1.0 - f) * body_full[e];
      r.base_flux_fraction[e] = f;
    }
  }
  r.base_fraction = f;
  flash_result_statistics(heat_flux, r);
  return r;
}

void flash_flux_totals(const Grid& grid, const std::vector<double>& q, FlashTemperatureResult& r) {
  r.total_heat = 0.0;
  r.heated_elements = 0;
  for (std::size_t e = 0; e < q.size(); ++e) {
    if (!std::isfinite(q[e]) || q[e] < 0.0)
      throw std::invalid_argument("flash temperature: the heat flux must be finite and >= 0, element " +
                                  std::to_string(e) + " has " + six_digits(q[e]));
    r.total_heat += q[e] * grid.area();
    if (q[e] > 0.0) ++r.heated_elements;
  }
}

void flash_result_statistics(const std::vector<double>& q, FlashTemperatureResult& r) {
  flash_statistics(r.base, q, r.base_max, r.base_max_element, r.base_mean);
  flash_statistics(r.body, q, r.body_max, r.body_max_element, r.body_mean);
}

}  // namespace dc
