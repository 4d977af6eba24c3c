#include "certified_solve.hpp"

namespace dc {

bool better_result(const SolverReport& candidate, const SolverReport& kept) {
  if (candidate.status == SolveStatus::converged) return kept.status != SolveStatus::converged;
  if (candidate.status == SolveStatus::failed) return false;
  // candidate not converged, with a point
  if (kept.status == SolveStatus::failed) return true;
  if (kept.status == SolveStatus::converged) return false;
  return candidate.certificate.worst() < kept.certificate.worst();
}

}  // namespace dc
