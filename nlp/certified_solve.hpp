#pragma once
// The backend fallback loop shared by the normal (4.7), tangential (4.8) and finite-body (3.14)
// problems: each backend in turn, its point certified by us (never by the backend's own claim),
// an interior point Ipopt accepted but our certificate did not finished by the active-set polish,
// one rule for the result kept, and one report of what was tried.
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "active_set_polish.hpp"
#include "quadratic_program.hpp"
#include "solver_report.hpp"

namespace dc {

/// The one "best result" rule: a converged result beats any other; a result with a point beats
/// a failed one; of two unconverged results with points the smaller certificate
/// (Certificate::worst) wins. Ties keep the earlier result.
bool better_result(const SolverReport& candidate, const SolverReport& kept);

/// The attempts of one solve and the result kept. `Result` is any solution with a
/// `SolverReport report` (NormalSolution, the tangential step's inner result).
template <class Result>
class AttemptLedger {
 public:
  /// `first` holds what every attempt's report starts from (requested backend, operator), and
  /// is the answer when nothing is recorded.
  explicit AttemptLedger(Result first) : kept_(std::move(first)) {}
  AttemptLedger() = default;

  /// Starts another solve from `first`, keeping the storage of the last one's results, attempts
  /// and messages (a solve repeated every step allocates nothing once they are sized).
  void restart(const Result& first) {
    kept_ = first;
    have_ = false;
    kept_index_ = 0;
    n_tried_ = 0;
    attempts_.clear();
  }

  /// Records one certified attempt; `has_point` is false when the backend gave no point (its
  /// certificate then reads infinite in failed_attempts). True when it became the kept result.
  bool record(Result attempt, bool has_point, const std::vector<IterationRecord>& history = {}) {
    return record_swapping(attempt, has_point, history);
  }
  /// The same, taking the attempt by swapping: `attempt` is left with the storage of the result
  /// it replaced (or its own, when it was not kept), for the next attempt to fill.
  bool record_swapping(Result& attempt, bool has_point, const std::vector<IterationRecord>& history = {}) {
    const SolverReport& r = attempt.report;
    if (!attempts_.empty()) attempts_ += "; ";
    attempts_ += r.backend;
    attempts_ += ": ";
    attempts_ += to_string(r.status);
    if (n_tried_ == tried_.size()) tried_.emplace_back();
    FailedAttempt& tried = tried_[n_tried_++];
    tried.backend = r.backend;
    tried.status = r.status;
    tried.message = r.message;
    tried.iterations = r.iterations;
    tried.time_s = r.time_s;
    tried.certificate = has_point ? r.certificate.worst() : kInf;
    tried.history = history;
    if (have_ && !better_result(r, kept_.report)) return false;
    std::swap(kept_, attempt);
    kept_index_ = n_tried_ - 1;
    have_ = true;
    return true;
  }

  bool converged() const { return have_ && kept_.report.status == SolveStatus::converged; }
  const Result& kept() const { return kept_; }

  /// The kept result, its report listing the attempts not kept and, when a fallback answered or
  /// none converged, " [tried native: not_converged; ipopt: converged]" after its message.
  Result finish() && {
    Result out;
    finish_into(out);
    return out;
  }
  /// The same into `out` by swapping (the ledger keeps out's old storage for the next solve).
  void finish_into(Result& out) {
    for (std::size_t k = 0; k < n_tried_; ++k)
      if (!have_ || k != kept_index_) kept_.report.failed_attempts.push_back(tried_[k]);
    if (n_tried_ > 0 && (kept_.report.fallback_used || kept_.report.status != SolveStatus::converged)) {
      kept_.report.message += " [tried ";
      kept_.report.message += attempts_;
      kept_.report.message += "]";
    }
    std::swap(out, kept_);
  }

 private:
  Result kept_;
  bool have_ = false;
  std::size_t kept_index_ = 0;
  std::vector<FailedAttempt> tried_;  // the first n_tried_ are this solve's (the rest: storage)
  std::size_t n_tried_ = 0;
  std::string attempts_;
};

/// An interior point leaves the elements at the edge of their bounds (contact edge, slip
/// boundary) off them by about mu / (their multiplier): a point Ipopt's own test accepted that
/// misses our certificate is finished by the active-set polish on `program`, to a hundredth of
/// the tolerance, and kept when its certificate is the better one. `certify(x, multipliers,
/// result)` turns a point into a certified result. Returns the polished point when it was kept.
/// Then, for any backend that claimed success, a result the certificate rejects says so.
template <class Result, class Certify>
std::optional<std::vector<double>> finish_backend_point(const std::string& backend, const SolveOutcome& outcome,
                                                        const QuadraticProgram& program, double certificate_tol,
                                                        Result& result, Certify&& certify) {
  std::optional<std::vector<double>> kept_point;
  SolverReport& rep = result.report;
  if (backend == "ipopt" && outcome.success && rep.status != SolveStatus::converged) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<double> x = outcome.x, multipliers = outcome.equality_multipliers;
    const PolishResult polish = polish_on_active_set(program, x, multipliers, 1e-2 * certificate_tol);
    Result polished;
    polished.report = rep;
    if (polish.improved) certify(x, multipliers, polished);
    if (polish.improved && polished.report.certificate.worst() < rep.certificate.worst()) {
      result = std::move(polished);
      rep.polished = true;
      rep.message += "; " + polish_summary(polish);
      kept_point = std::move(x);
    }
    rep.time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (rep.status != SolveStatus::converged && outcome.success)
    rep.message += " (backend reported success but the certificate " + format_number(rep.certificate.worst()) +
                   " exceeds the tolerance)";
  return kept_point;
}

}  // namespace dc
