#pragma once
// What every solve reports: backend used, status, effort and our own certificate.
#include <string>
#include <vector>

#include "kept_storage.hpp"


#include "iteration_record.hpp"

namespace dc {

/// Residuals measured by us after a solve (never the backend's own claim).
struct Certificate {
  double complementarity = 0.0;  ///< max |min(p, g/C_ii)| / max p (normal problem)
  double gap_violation = 0.0;    ///< max(-g) / (max p * C_ii): interpenetration
  double pressure_violation = 0.0;  ///< max(-p) / max p
  double force_residual = 0.0;   ///< |sum p A - P| / P under force control
  double friction_law = 0.0;     ///< tangential: worst violation of (2.4)-(2.5) / traction level max |tau|
  double gap_function = 0.0;     ///< tangential: (4.24) g(tau) / (sum f(p) A * slip level max(|ds|, c_t max |tau|))
  double worst() const;          ///< the largest of the above; infinity if any is NaN
  /// The certificate of a point that is not finite (NaN or infinite entries): every measure infinite.
  static Certificate not_finite();
};

/// True when no entry is NaN or infinite (a point a certificate can measure at all).
bool all_finite(const std::vector<double>& values);

enum class SolveStatus { converged, not_converged, failed };

/// A backend that was tried and did not give the reported answer (`auto` moved on): what it
/// said, its effort, our certificate of its point and, for a native solver, its iterations.
struct FailedAttempt {
  std::string backend;
  SolveStatus status = SolveStatus::failed;
  std::string message;
  int iterations = 0;
  double time_s = 0.0;
  double certificate = 0.0;  ///< Certificate::worst() of its point (infinity: no point)
  std::vector<IterationRecord> history;
};

struct SolverReport {
  std::string backend;          ///< backend that produced the result
  std::string requested;        ///< backend the user asked for
  SolveStatus status = SolveStatus::failed;
  std::string message;          ///< backend message / reason for failure
  int iterations = 0;
  double time_s = 0.0;
  double objective = 0.0;
  bool fallback_used = false;
  bool polished = false;        ///< the backend's point was finished by the active-set polish
  std::string operator_kind;    ///< dense | fft
  Certificate certificate;
  std::vector<FailedAttempt> failed_attempts;  ///< the backends tried before (or instead of) this one
};

/// Back to a default report, the storage of its strings and lists kept: a report filled again
/// at every step of a run then allocates nothing once its texts have been as long before.
void reset_keeping_storage(SolverReport& report);

const char* to_string(SolveStatus status);
/// A number for messages: %.3g (never %f, which prints small residuals as 0.000001).
std::string format_number(double value);
/// One line for stderr per failed attempt of a report whose answer came from a fallback (or that
/// did not converge at all): "native: not_converged after 1000 iterations (iteration limit reached;
/// relative change 3e-4 at the end, contact set 5321 (+12 -9)); ipopt took over". Empty otherwise.
std::string fallback_warning(const SolverReport& report);

}  // namespace dc
