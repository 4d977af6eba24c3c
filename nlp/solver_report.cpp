#include "solver_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <string>
#include <utility>

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

void reset_keeping_storage(SolverReport& report) {
  reset_keeping_members(report, &SolverReport::backend, &SolverReport::requested, &SolverReport::message,
                        &SolverReport::operator_kind, &SolverReport::failed_attempts);
}

}  // namespace dc
