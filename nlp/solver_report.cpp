#include "solver_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>

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

nlohmann::json to_json(const SolverReport& r) {
  return {{"backend", r.backend},
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
}

}  // namespace dc
