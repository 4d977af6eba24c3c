// The depth-only front end of the shakedown program: the samples and the residual columns of
// shakedown_samples.hpp as one station per depth (shakedown_stations.hpp), solved there.
#include "shakedown_problem.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include "shakedown_samples.hpp"
#include "shakedown_stations.hpp"

namespace dc {

ShakedownResult solve_shakedown(const StressHistory& history, const YieldCriterion& criterion,
                                const ResidualModel& model, const ShakedownOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (const std::string why = options.validate(); !why.empty()) throw std::invalid_argument("shakedown: " + why);
  const ShakedownSamples s = shakedown_samples(history, criterion, model);
  std::vector<double> theta;
  ShakedownResult out = solve_shakedown_stations(depth_stations(s), options, theta);
  out.residual.assign(static_cast<std::size_t>(s.depths), Voigt{});
  if (!theta.empty() && out.status != ShakedownStatus::unbounded && out.status != ShakedownStatus::failed)
    for (int j = 0; j < s.depths; ++j)
      out.residual[static_cast<std::size_t>(j)] = s.residual(theta.data() + static_cast<std::size_t>(j * s.p()));
  if (criterion.outer_factor() != 1.0) {  // first yield of the criterion itself, not of its cone
    std::size_t worst = 0;
    out.elastic_limit = exact_elastic_limit(history.stress, criterion, worst);
    out.elastic_limit_depth = static_cast<int>(worst / static_cast<std::size_t>(s.positions));
    out.elastic_limit_position = static_cast<int>(worst % static_cast<std::size_t>(s.positions));
  }
  out.limit_upper_bound = out.certificate.upper_bound * criterion.outer_factor();
  set_shakedown_verdict(out);
  out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace dc
