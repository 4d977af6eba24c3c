#include "heights_accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "accuracy_estimate.hpp"
#include "grid_interpolation.hpp"
#include "height_restriction.hpp"
#include "static_fields.hpp"
#include "summary_entries.hpp"

namespace dc::runs {

namespace heights_estimate {

std::string why_none(const Grid& grid, bool converged, int across) {
  // In 2-D the place of the contact edge within an element moves a result by up to 10 x its smooth
  // error: the estimate needs grids shifted by fractions of an element, which heights given at the
  // centres cannot give (docs/accuracy.md).
  if (grid.dimension == 2)
    return "a 2-D estimate needs grids shifted by fractions of an element, which heights given at the element "
           "centres do not give: solve the case (dyncontact.solve) for its estimate";
  if (!converged) return "the solve did not converge";
  if (!enough_across(across, 0))
    return "the contact is " + std::to_string(across) + " elements across: a grid of twice the element size would "
           "have fewer than " + std::to_string(kMinAcross3d);
  return "";
}

bool enough_across(int across, std::size_t level) { return across / (2 << level) >= kMinAcross3d; }

int fewest_across(const nlohmann::json& s) {
  const nlohmann::json& a = s.at("elements_across_contact");
  return a.is_array() ? std::min(a[0].get<int>(), a[1].get<int>()) : a.get<int>();
}

SolverOptions coarse_solver(const SolverOptions& solver, const std::string& fine_backend) {
  SolverOptions coarse = solver;
  if (solver.backend == Backend::automatic)
    if (const auto b = backend_from_string(fine_backend); b && *b != Backend::automatic) coarse.backend = *b;
  return coarse;
}

nlohmann::json normal_summary(const Grid& grid, Control control, double certificate_tol, const NormalSolution& s,
                              const SolverReport& report, SolveStatus status) {
  nlohmann::json j = {{"control", control == Control::force ? "force" : "approach"},
                      {"approach", s.approach},
                      {"normal_force", s.force},
                      {"status", to_string(status)},
                      {"solver", output::to_json(report)}};
  output::add_contact_measures(j, grid, output::normal_fields(s.pressure, std::max(certificate_tol, 1e-12)));
  return j;
}

nlohmann::json block(const std::vector<Grid>& grids, const std::vector<double>& seconds,
                     const std::vector<nlohmann::json>& summaries, const std::string& unavailable,
                     double coarse_seconds, double unresolved, double e_star) {
  std::vector<GridTime> timed;
  for (std::size_t k = 0; k < grids.size(); ++k) timed.push_back({grids[k], seconds[k], &summaries[k]});
  std::vector<EstimatedQuantity> quantities;
  if (unavailable.empty()) {
    std::vector<std::vector<QuantityValue>> per_level;
    std::vector<double> sizes;
    for (std::size_t k = 0; k < grids.size(); ++k) {
      per_level.push_back(accuracy_quantities(summaries[k]));
      sizes.push_back(element_size(grids[k]));
    }
    quantities = estimate_quantities(sizes, per_level, grids.front().dimension);
    floor_by_unresolved_height(quantities, unresolved, contact_stiffness(e_star, summaries.front().value("contact_area", 0.0)));
  }
  return accuracy_block(timed, unavailable, quantities, coarse_seconds, AccuracySpec{});
}

double unresolved_in_contact(const Grid& grid, const std::vector<double>& heights, const std::vector<double>& pressure,
                             double certificate_tol) {
  double peak = 0.0;
  for (double p : pressure) peak = std::max(peak, p);
  const double threshold = std::max(certificate_tol, 1e-12) * peak;
  std::vector<char> in_contact(pressure.size());
  for (std::size_t e = 0; e < pressure.size(); ++e) in_contact[e] = pressure[e] > threshold;
  return unresolved_height(grid, heights, in_contact);
}

}  // namespace heights_estimate

struct HeightsAccuracy::Level {
  Grid grid;
  std::unique_ptr<NormalProblem> problem;
};

HeightsAccuracy::HeightsAccuracy(const Grid& grid, const MaterialPair& materials, OperatorKind kind)
    : grid_(grid), materials_(materials), kind_(kind) {}

HeightsAccuracy::~HeightsAccuracy() = default;

nlohmann::json HeightsAccuracy::estimate(const std::vector<double>& heights, const NormalSpec& load,
                                         const SolverOptions& solver, const NormalSolution& fine, double fine_seconds) {
  namespace he = heights_estimate;
  std::vector<nlohmann::json> summaries{
      he::normal_summary(grid_, load.control, solver.certificate_tol, fine, fine.report, fine.report.status)};
  std::vector<Grid> grids{grid_};
  std::vector<double> seconds{fine_seconds};
  double coarse_seconds = 0.0;
  const int across = he::fewest_across(summaries[0]);
  std::string unavailable = he::why_none(grid_, fine.report.status == SolveStatus::converged, across);
  Grid finer = grid_;
  std::vector<double> finer_heights = heights;
  std::vector<double> finer_pressure = fine.pressure;
  const SolverOptions coarse_solver = he::coarse_solver(solver, fine.report.backend);
  for (std::size_t k = 0; k < 2 && unavailable.empty() && he::enough_across(across, k); ++k) {
    const std::string size = k == 0 ? "twice" : "four times";
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
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    coarse_seconds += t;
    if (s.report.status != SolveStatus::converged) {
      if (k == 0) unavailable = "the solve on the grid of " + size + " the element size did not converge";
      break;
    }
    summaries.push_back(he::normal_summary(coarse->grid, load.control, solver.certificate_tol, s, s.report, s.report.status));
    grids.push_back(coarse->grid);
    seconds.push_back(t);
    finer = coarse->grid;
    finer_heights = std::move(coarse->heights);
    finer_pressure = s.pressure;
  }
  return he::block(grids, seconds, summaries, unavailable, coarse_seconds,
                   he::unresolved_in_contact(grid_, heights, fine.pressure, solver.certificate_tol), materials_.E_star());
}

}  // namespace dc::runs
