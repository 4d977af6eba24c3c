#include "summary_entries.hpp"

#include <cmath>
#include <string>

namespace dc::output {

nlohmann::json to_json(const Certificate& c) {
  return {{"complementarity", c.complementarity}, {"gap_violation", c.gap_violation},
          {"pressure_violation", c.pressure_violation}, {"force_residual", c.force_residual},
          {"friction_law", c.friction_law},     {"gap_function", c.gap_function}};
}

namespace {
nlohmann::json to_json(const FailedAttempt& a) {
  nlohmann::json history = nlohmann::json::array();
  for (const IterationRecord& h : a.history)
    history.push_back({{"iteration", h.iteration},
                       {"change", h.change},
                       {"active", h.active},
                       {"entered", h.entered},
                       {"left", h.left}});
  nlohmann::json j = {{"backend", a.backend},       {"status", to_string(a.status)}, {"message", a.message},
                      {"iterations", a.iterations}, {"time_s", a.time_s}};
  j["certificate"] = std::isfinite(a.certificate) ? nlohmann::json(a.certificate) : nlohmann::json(nullptr);
  if (!history.empty()) j["history"] = history;
  return j;
}
}  // namespace

nlohmann::json to_json(const SolverReport& r) {
  nlohmann::json j = {{"backend", r.backend},
          {"requested", r.requested},
          {"status", to_string(r.status)},
          {"message", r.message},
          {"iterations", r.iterations},
          {"time_s", r.time_s},
          {"objective", r.objective},
          {"fallback_used", r.fallback_used},
          {"polished", r.polished},
          {"operator", r.operator_kind},
          {"certificate", to_json(r.certificate)}};
  if (const std::string fell_back = fallback_warning(r); !fell_back.empty()) j["fallback_warning"] = fell_back;
  if (!r.failed_attempts.empty()) {
    nlohmann::json attempts = nlohmann::json::array();
    for (const FailedAttempt& a : r.failed_attempts) attempts.push_back(to_json(a));
    j["failed_attempts"] = attempts;
  }
  return j;
}

nlohmann::json limits_json(const std::vector<ResultLimit>& limits) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& l : limits) out.push_back({{"key", l.key},
                   {"message", l.message},
                   {"level", l.error ? "error" : "warning"},
                   {"accepted", l.accepted}});
  return out;
}

}  // namespace dc::output
