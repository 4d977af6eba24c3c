#pragma once
// The error estimate of a normal solve given by element heights alone (Python's NormalProblem,
// docs/accuracy.md "Problems given by their heights"): the same load solved again on grids of 2
// and 4 times the element size over the same bounds, their heights the given ones carried to the
// coarse centres (core/height_restriction.hpp: exact for a profile cubic along each axis), and
// the results estimated as a case's are (accuracy_estimate.hpp): summary.json's accuracy block.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "material.hpp"
#include "normal_problem.hpp"
#include "operator_kind.hpp"

namespace dc::runs {

/// What every estimate of a problem given by its heights does alike (HeightsAccuracy here,
/// TangentialAccuracy in tangential_accuracy.hpp).
namespace heights_estimate {

/// Why a fine solve on `grid` (`converged` or not, `across` elements across its contact at the
/// fewest) has no estimate: 2-D (its estimate needs shifted grids), not converged, or fewer than
/// kMinAcross3d elements across on the grid of twice the element size; "" when it may have one.
std::string why_none(const Grid& grid, bool converged, int across);
/// Whether the coarse grid `level` (0: 2h, 1: 4h) keeps kMinAcross3d elements across the contact.
bool enough_across(int across, std::size_t level);
/// The fewest elements across the contact of a summary's contact measures.
int fewest_across(const nlohmann::json& summary);
/// The solver of the coarse grids: the fine solve's backend where `solver` let auto choose
/// (auto would pick another by the coarse grid's size).
SolverOptions coarse_solver(const SolverOptions& solver, const std::string& fine_backend);
/// The normal keys accuracy_quantities and accuracy_block read of one grid's solve: control,
/// approach, normal_force, the contact measures, status and solver (`report`: its certificate).
nlohmann::json normal_summary(const Grid& grid, Control control, double certificate_tol, const NormalSolution& s,
                              const SolverReport& report, SolveStatus status);
/// summary.json's accuracy block of the grids (finest first) with their summaries and times.
/// `unresolved` (m): the height detail the coarse grid does not carry (floor_by_unresolved_height,
/// with the contact stiffness of E* (Pa) and the fine grid's contact area).
nlohmann::json block(const std::vector<Grid>& grids, const std::vector<double>& seconds,
                     const std::vector<nlohmann::json>& summaries, const std::string& unavailable,
                     double coarse_seconds, double unresolved, double e_star);
/// unresolved_height of `heights` where `pressure` is above the contact threshold.
double unresolved_in_contact(const Grid& grid, const std::vector<double>& heights, const std::vector<double>& pressure,
                             double certificate_tol);

}  // namespace heights_estimate

/// The coarse problems of one fine grid, set up on the first estimate and kept for the next
/// (a problem solved many times: each estimate's coarse solves start from the last ones).
class HeightsAccuracy {
 public:
  HeightsAccuracy(const Grid& grid, const MaterialPair& materials, OperatorKind kind);
  ~HeightsAccuracy();
  HeightsAccuracy(const HeightsAccuracy&) = delete;
  HeightsAccuracy& operator=(const HeightsAccuracy&) = delete;

  /// The accuracy block of `fine` (solved on the grid with `heights`, `load`, `solver` in
  /// `fine_seconds`). Unavailable (the block says why) in 2-D (its estimate needs shifted grids),
  /// when the solve did not converge, an axis has an odd number of elements, or the coarser grid
  /// would have fewer than 6 elements across the contact. Its cost_fraction counts the coarse
  /// problems' set-up when they are made.
  nlohmann::json estimate(const std::vector<double>& heights, const NormalSpec& load, const SolverOptions& solver,
                          const NormalSolution& fine, double fine_seconds);

 private:
  struct Level;
  Grid grid_;
  MaterialPair materials_;
  OperatorKind kind_;
  std::vector<std::unique_ptr<Level>> levels_;  // 2h, 4h as made
};

}  // namespace dc::runs
