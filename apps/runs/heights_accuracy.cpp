#include "heights_accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "accuracy_estimate.hpp"
#include "grid_interpolation.hpp"
#include "height_restriction.hpp"
#include "static_fields.hpp"

namespace dc::runs {
namespace {

/// The summary keys accuracy_quantities and accuracy_block read, of one grid's solve.
nlohmann::json level_summary(const Grid& grid, const NormalSpec& load, const SolverOptions& solver,
                             const NormalSolution& s) {
  nlohmann::json j = {{"control", load.control == Control::force ? "force" : "approach"},
                      {"approach", s.approach},
                      {"normal_force", s.force},
                      {"status", to_string(s.report.status)}};
  output::add_contact_measures(j, grid, output::normal_fields(s.pressure, std::max(solver.certificate_tol, 1e-12)));
  return j;
}

int fewest_across(const nlohmann::json& s) {
  const nlohmann::json& a = s.at("elements_across_contact");
  return a.is_array() ? std::min(a[0].get<int>(), a[1].get<int>()) : a.get<int>();
}

}  // namespace

struct HeightsAccuracy::Level {
  Grid grid;
  std::unique_ptr<NormalProblem> problem;
};

HeightsAccuracy::HeightsAccuracy(const Grid& grid, const MaterialPair& materials, OperatorKind kind)
    : grid_(grid), materials_(materials), kind_(kind) {}

HeightsAccuracy::~HeightsAccuracy() = default;

nlohmann::json HeightsAccuracy::estimate(const std::vector<double>& heights, const NormalSpec& load,
                                         const SolverOptions& solver, const NormalSolution& fine, double fine_seconds) {
  std::vector<nlohmann::json> summaries{level_summary(grid_, load, solver, fine)};
  std::vector<GridTime> grids{{grid_, fine_seconds, nullptr}};
  std::string unavailable;
  double coarse_seconds = 0.0;
  const int min_across = kMinAcross3d;
  const int across = fewest_across(summaries[0]);
  if (fine.report.status != SolveStatus::converged) unavailable = "the solve did not converge";
  // In 2-D the place of the contact edge within an element moves a result by up to 10 x its smooth
  // error: the estimate needs grids shifted by fractions of an element, which heights given at the
  // centres cannot give (docs/accuracy.md).
  if (grid_.dimension == 2)
    unavailable = "a 2-D estimate needs grids shifted by fractions of an element, which heights given at the "
                  "element centres do not give: solve the case (dyncontact.solve) for its estimate";
  Grid finer = grid_;
  std::vector<double> finer_heights = heights;
  std::vector<double> finer_pressure = fine.pressure;
  // The fine solve's backend on the coarse grids (auto would pick another by their size).
  SolverOptions coarse_solver = solver;
  if (solver.backend == Backend::automatic)
    if (const auto b = backend_from_string(fine.report.backend); b && *b != Backend::automatic) coarse_solver.backend = *b;
  for (std::size_t k = 0; k < 2 && unavailable.empty(); ++k) {
    const std::string size = k == 0 ? "twice" : "four times";
    if (across / (2 << k) < min_across) {
      if (k == 0)
        unavailable = "the contact is " + std::to_string(across) + " elements across: a grid of twice the element "
                      "size would have fewer than " + std::to_string(min_across);
      break;
    }
    std::optional<RestrictedHeights> coarse = restrict_heights(finer, finer_heights);
    if (!coarse) {
      if (k == 0)
        unavailable = "the grid has an odd number of elements (or fewer than 4) along an axis: no grid of twice the "
                      "element size over the same heights";
      break;
    }
    const auto start = std::chrono::steady_clock::now();
    if (levels_.size() <= k) {
      // The FFT operator on every grid (as the case path: a dense matrix costs more than its solve);
      // the first solve starts from the finer grid's pressure, the later ones from their last.
      auto level = std::make_unique<Level>();
      level->grid = coarse->grid;
      level->problem = std::make_unique<NormalProblem>(coarse->grid, materials_, coarse->heights,
                                                       kind_ == OperatorKind::automatic ? OperatorKind::fft : kind_);
      level->problem->set_warm_start(interpolate_to_grid(finer, finer_pressure, coarse->grid));
      levels_.push_back(std::move(level));
    } else {
      levels_[k]->problem->set_heights(coarse->heights);
    }
    const NormalSolution s = levels_[k]->problem->solve(load, coarse_solver);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    coarse_seconds += seconds;
    if (s.report.status != SolveStatus::converged) {
      if (k == 0) unavailable = "the solve on the grid of " + size + " the element size did not converge";
      break;
    }
    summaries.push_back(level_summary(coarse->grid, load, solver, s));
    grids.push_back({coarse->grid, seconds, nullptr});
    finer = coarse->grid;
    finer_heights = std::move(coarse->heights);
    finer_pressure = s.pressure;
  }
  for (std::size_t k = 0; k < grids.size(); ++k) grids[k].summary = &summaries[k];
  std::vector<EstimatedQuantity> quantities;
  if (unavailable.empty()) {
    std::vector<std::vector<QuantityValue>> per_level;
    std::vector<double> sizes;
    for (std::size_t k = 0; k < grids.size(); ++k) {
      per_level.push_back(accuracy_quantities(summaries[k]));
      sizes.push_back(element_size(grids[k].grid));
    }
    quantities = estimate_quantities(sizes, per_level, grid_.dimension);
  }
  return accuracy_block(grids, unavailable, quantities, coarse_seconds, AccuracySpec{});
}

}  // namespace dc::runs
