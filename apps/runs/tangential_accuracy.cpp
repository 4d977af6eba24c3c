#include "tangential_accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <optional>
#include <utility>

#include "heights_accuracy.hpp"
#include "height_restriction.hpp"
#include "tangential_run.hpp"

namespace dc::runs {
namespace {

bool converged(const TangentialSolution& s) {
  return s.report.status == SolveStatus::converged && s.normal.report.status == SolveStatus::converged &&
         s.outer.converged;
}

/// The keys accuracy_quantities reads of a tangential solve, as a case's summary has them: the
/// normal ones and the tangential measures (the friction capacity sum f(p) A is what a force that
/// is zero in the continuum is judged against).
nlohmann::json level_summary(const Grid& grid, Control control, double certificate_tol, const TangentialSolution& s) {
  // The worst of the three: the tangential solve, the normal one, the outer loop (3.31)-(3.32).
  const SolveStatus status = s.report.status != SolveStatus::converged          ? s.report.status
                             : s.normal.report.status != SolveStatus::converged ? s.normal.report.status
                             : s.outer.converged                                ? SolveStatus::converged
                                                                                : SolveStatus::not_converged;
  nlohmann::json j = heights_estimate::normal_summary(grid, control, certificate_tol, s.normal, s.report, status);
  add_tangential_measures(j, grid, s, tangential_fields(s, std::max(certificate_tol, 1e-12)));
  return j;
}

Control control_of(const TangentialCall& c) {
  return c.kind == TangentialCall::Kind::step ? c.step_load.normal.control : c.rolling_load.normal.control;
}

}  // namespace

struct TangentialAccuracy::Level {
  Grid grid;
  std::unique_ptr<TangentialProblem> problem;
  std::size_t taken = 0;                // calls of the history taken (from the last reset)
  std::optional<TangentialSolution> last;
  std::string failed;                   // why its history broke off ("" while it goes on)
};

TangentialAccuracy::TangentialAccuracy(const Grid& grid, const MaterialPair& materials, std::vector<double> heights,
                                       FrictionLaw friction, OperatorKind kind, std::size_t max_recorded_calls)
    : grid_(grid),
      materials_(materials),
      heights_(std::move(heights)),
      friction_(std::move(friction)),
      kind_(kind),
      max_recorded_calls_(max_recorded_calls) {}

TangentialAccuracy::~TangentialAccuracy() = default;

void TangentialAccuracy::record(TangentialCall call, const std::string& fine_backend) {
  if (overflowed_) return;
  if (calls_.size() >= max_recorded_calls_) {
    overflowed_ = true;
    calls_.clear();
    calls_.shrink_to_fit();
    return;
  }
  call.solver = heights_estimate::coarse_solver(call.solver, fine_backend);
  calls_.push_back(std::move(call));
}

void TangentialAccuracy::reset() {
  overflowed_ = false;
  calls_.clear();
  calls_first_ = 0;
  for (auto& level : levels_) {
    level->problem->reset();
    level->taken = 0;
    level->last.reset();
    level->failed.clear();
  }
}

std::string TangentialAccuracy::catch_up(Level& level, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  for (; level.failed.empty() && level.taken < calls_first_ + calls_.size(); ++level.taken) {
    const TangentialCall& c = calls_[level.taken - calls_first_];
    TangentialProblem& p = *level.problem;
    const std::string where = "call " + std::to_string(level.taken + 1) + " of the history on the grid of " +
                              std::to_string(level.grid.nx) + " x " + std::to_string(level.grid.ny) + " elements";
    // A coarse solve that throws (an interrupt aside) breaks this level's history off, as one that
    // does not converge: the fine answer stands, its estimate says why it has none.
    try {
      switch (c.kind) {
        case TangentialCall::Kind::step: level.last = p.step(c.step_load, c.solver); break;
        case TangentialCall::Kind::steady_rolling: level.last = p.steady_rolling(c.rolling_load, c.solver); break;
        case TangentialCall::Kind::roll: level.last = p.roll(c.rolling_load, c.distance, c.solver); break;
      }
    } catch (const std::exception& e) {
      level.failed = where + " failed: " + e.what();
      break;
    }
    if (!converged(*level.last)) level.failed = where + " did not converge";
  }
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return level.failed;
}

nlohmann::json TangentialAccuracy::estimate(const TangentialSolution& fine, double fine_seconds) {
  namespace he = heights_estimate;
  const Control control = calls_.empty() ? Control::force : control_of(calls_.back());
  const double certificate_tol = calls_.empty() ? 1e-6 : calls_.back().solver.certificate_tol;
  std::vector<nlohmann::json> summaries{level_summary(grid_, control, certificate_tol, fine)};
  std::vector<Grid> grids{grid_};
  std::vector<double> seconds{fine_seconds};
  const int across = he::fewest_across(summaries[0]);
  std::string unavailable = he::why_none(grid_, converged(fine), across);
  if (overflowed_ && unavailable.empty())
    unavailable = "more than " + std::to_string(max_recorded_calls_) + " calls of the history since reset() waited for the "
                  "coarse grids and were not kept: ask estimate=True at least that often (or from the first call)";
  if (calls_.empty() && unavailable.empty()) unavailable = "no call of the problem to estimate";
  // The coarse problems, once: the heights are the problem's for its whole life.
  if (unavailable.empty() && levels_.empty() && levels_unavailable_.empty()) {
    Grid finer = grid_;
    std::vector<double> finer_heights = heights_;
    for (int k = 0; k < 2; ++k) {
      std::optional<RestrictedHeights> coarse = restrict_heights(finer, finer_heights);
      if (!coarse) break;
      auto level = std::make_unique<Level>();
      level->grid = coarse->grid;
      level->problem = std::make_unique<TangentialProblem>(
          coarse->grid, materials_, coarse->heights, friction_,
          kind_ == OperatorKind::automatic ? OperatorKind::fft : kind_);
      levels_.push_back(std::move(level));
      finer = coarse->grid;
      finer_heights = std::move(coarse->heights);
    }
    if (levels_.empty())
      levels_unavailable_ = "the grid has an odd number of elements (or fewer than 4) along an axis: no grid of twice "
                            "the element size over the same heights";
  }
  if (unavailable.empty()) unavailable = levels_unavailable_;
  double coarse_seconds = 0.0;
  for (std::size_t k = 0; k < levels_.size() && unavailable.empty() && he::enough_across(across, k); ++k) {
    Level& level = *levels_[k];
    double t = 0.0;
    const std::string failed = catch_up(level, t);
    coarse_seconds += t;
    if (!failed.empty()) {
      if (k == 0) unavailable = failed;
      break;
    }
    summaries.push_back(level_summary(level.grid, control, certificate_tol, *level.last));
    grids.push_back(level.grid);
    seconds.push_back(t);
  }
  // The calls every level has taken are not needed again.
  std::size_t taken_by_all = calls_first_ + calls_.size();
  for (const auto& level : levels_) taken_by_all = std::min(taken_by_all, level->taken);
  if (!levels_.empty() && taken_by_all > calls_first_) {
    calls_.erase(calls_.begin(), calls_.begin() + static_cast<std::ptrdiff_t>(taken_by_all - calls_first_));
    calls_first_ = taken_by_all;
  }
  return he::block(grids, seconds, summaries, unavailable, coarse_seconds,
                   he::unresolved_in_contact(grid_, heights_, fine.normal.pressure, certificate_tol), materials_.E_star());
}

}  // namespace dc::runs
