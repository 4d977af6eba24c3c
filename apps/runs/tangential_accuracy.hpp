#pragma once
// The error estimate of a tangential problem given by element heights (Python's
// TangentialProblem, docs/accuracy.md "Problems given by their heights"): a history with memory
// (Cattaneo-Mindlin steps, transient rolling) is estimated by taking the same history on grids
// of 2 and 4 times the element size, their heights the given ones carried to the coarse centres
// (core/height_restriction.hpp). The fine problem's calls are recorded; the first estimate sets
// the coarse problems up and takes them through every call since the last reset, the later ones
// through the calls since the previous estimate. The last call's results are then estimated as a
// case's are (accuracy_quantities.hpp: the tangential ones as bands).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "friction_law.hpp"
#include "material.hpp"
#include "operator_kind.hpp"
#include "tangential_problem.hpp"

namespace dc::runs {

/// One call of a tangential problem's history, as the fine problem took it.
struct TangentialCall {
  enum class Kind { step, steady_rolling, roll } kind = Kind::step;
  TangentialLoad step_load;    ///< Kind::step
  RollingLoad rolling_load;    ///< Kind::steady_rolling, Kind::roll
  double distance = 0.0;       ///< Kind::roll (m)
  SolverOptions solver;        ///< with the backend the fine solve used (auto would choose by size)
};

class TangentialAccuracy {
 public:
  /// The most calls kept for the coarse grids to take (224 bytes each): a longer stretch of the
  /// history without an estimate is not kept, and the estimates until reset() say why.
  static constexpr std::size_t kMaxRecordedCalls = std::size_t{1} << 16;

  TangentialAccuracy(const Grid& grid, const MaterialPair& materials, std::vector<double> heights,
                     FrictionLaw friction, OperatorKind kind, std::size_t max_recorded_calls = kMaxRecordedCalls);
  ~TangentialAccuracy();
  TangentialAccuracy(const TangentialAccuracy&) = delete;
  TangentialAccuracy& operator=(const TangentialAccuracy&) = delete;

  /// The fine problem took `call` (its solver's backend replaced by `fine_backend` where auto).
  void record(TangentialCall call, const std::string& fine_backend);
  /// The fine problem forgot its history: so do the coarse ones.
  void reset();
  /// The accuracy block of `fine`, the solution of the last recorded call (in `fine_seconds`).
  /// Unavailable (the block says why) in 2-D, when the solve did not converge, an axis has an odd
  /// number of elements, the coarser grid would have fewer than 6 elements across the contact, or
  /// a coarse grid's history did not converge or more than kMaxRecordedCalls calls waited for
  /// the coarse grids (until the next reset).
  nlohmann::json estimate(const TangentialSolution& fine, double fine_seconds);

 private:
  struct Level;
  /// Takes `level` through the recorded calls it has not taken; its last solution.
  std::string catch_up(Level& level, double& seconds);
  Grid grid_;
  MaterialPair materials_;
  std::vector<double> heights_;
  FrictionLaw friction_;
  OperatorKind kind_;
  std::vector<TangentialCall> calls_;  // since the last reset, from calls_first_
  std::size_t calls_first_ = 0;        // the history's index of calls_[0] (the ones before: taken by every level)
  std::vector<std::unique_ptr<Level>> levels_;  // 2h, 4h once made
  std::string levels_unavailable_;              // why no coarse grid exists (odd sizes), once tried
  std::size_t max_recorded_calls_;
  bool overflowed_ = false;                     // more than max_recorded_calls_ waited: not kept
};

}  // namespace dc::runs
