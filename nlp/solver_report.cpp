#include "solver_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <string>

namespace dc {

double Certificate::worst() const {
  double worst = 0.0;
  for (double m : {complementarity, gap_violation, pressure_violation, force_residual, friction_law, gap_function}) {
    if (std::isnan(m)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, m);
  }
  return worst;
}

Certificate Certificate::not_finite() {
  const double inf = std::numeric_limits<double>::infinity();
  return {inf, inf, inf, inf, inf, inf};
}

bool all_finite(const std::vector<double>& values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

const char* to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::converged: return "converged";
    case SolveStatus::not_converged: return "not_converged";
    case SolveStatus::failed: return "failed";
  }
  return "failed";
}

std::string format_number(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", value);
  return buf;
}

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

std::string fallback_warning(const SolverReport& r) {
  if (r.failed_attempts.empty() || (!r.fallback_used && r.status == SolveStatus::converged)) return "";
  std::string text;
  for (const FailedAttempt& a : r.failed_attempts) {
    text += (text.empty() ? "" : "; ") + a.backend + ": " + to_string(a.status) + " after " +
            std::to_string(a.iterations) + " iterations (" + a.message;
    if (!a.history.empty()) {
      const IterationRecord& h = a.history.back();
      text += "; relative change " + format_number(h.change) + " at the end, contact set " + std::to_string(h.active) +
              " (+" + std::to_string(h.entered) + " -" + std::to_string(h.left) + ")";
    }
    text += ")";
  }
  if (r.status == SolveStatus::converged) text += "; " + r.backend + " took over";
  return text;
}

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

}  // namespace dc
