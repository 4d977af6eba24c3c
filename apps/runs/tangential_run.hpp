#pragma once
#include <optional>
// Solving a tangential case for the command line (progress, fields, summary), and the
// static run that `solve` and `compare` use for either static problem (normal, tangential).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subsurface_series.hpp"

#include "case_model.hpp"
#include "solver_report.hpp"
#include "static_fields.hpp"
#include "wear_series_writer.hpp"
#include "tangential_problem.hpp"

namespace dc::runs {

struct TangentialRun {
  std::vector<TangentialSolution> steps;     ///< one, or one per history step
  std::vector<output::StaticFields> fields;  ///< per step
  std::vector<NormalSpec> normal;            ///< the normal load of each step
  bool interrupted = false;                  ///< an interrupt came: `steps` are those finished
  nlohmann::json summary;                    ///< summary.json content (without "files"): the last
                                             ///< step's keys, plus "steps" with a history
  bool converged() const;                    ///< every step converged
  double total_time_s() const;               ///< solver time of all steps (s)
  /// The report to show: the first step that did not converge, else the last.
  const SolverReport& report() const;
};

/// Solves with dc::solve_tangential_case, a progress line on stderr when `progress` and the
/// solve takes over a second.
TangentialRun run_tangential(const Case& c, bool progress);
/// The run (fields, summary) of solutions already solved for case `c`, `normals` the normal
/// load of each (the wear run's last cycle, wear_run.hpp).
TangentialRun tangential_run_of(const Case& c, std::vector<TangentialSolution> solutions,
                                std::vector<NormalSpec> normals);

/// The contact fields of one tangential step: pressure, traction, slip, friction bound, and
/// the states 0 free / 1 stick / 2 slip. An element is in contact when p exceeds
/// `relative_threshold` times the peak (as for the normal problem); its stick/slip state is the
/// solver's (an element in contact without friction capacity slips).
output::StaticFields tangential_fields(const TangentialSolution& solution, double relative_threshold);

/// The tangential keys of one step's summary (CASES.md): tangential_force, twisting_moment,
/// creepage and spin (rolling) or rigid_shift and rotation, n_stick, n_slip, stick_area,
/// slip_area and friction_capacity (sum f(p) A).
void add_tangential_measures(nlohmann::json& summary, const Grid& grid, const TangentialSolution& solution,
                             const output::StaticFields& fields);

/// The keys of one tangential step (CASES.md): the normal keys of `c` (whose `normal` is the
/// step's load) plus tangential_force, twisting_moment, creepage, spin, rigid_shift, rotation,
/// n_stick, n_slip, stick_area, the outer-loop and marching counts (a step of a rolling history
/// adds its rolled `distance`; one of distance 0 is quasi-static: rigid_shift, no creepage);
/// `solver` is the tangential report (its certificate holds the normal residuals too).
nlohmann::json tangential_summary(const Case& c, const TangentialSolution& solution,
                                  const output::StaticFields& fields);

/// A solved static case, whichever problem it was: what `solve` writes and `compare` compares.
struct StaticRun {
  nlohmann::json summary;                    ///< summary.json content (without "files")
  std::vector<output::StaticFields> fields;  ///< one per step; the last is fields.csv
  NormalSpec normal;                         ///< the normal load of the last step (closed-form curves)
  SolverReport report;                       ///< see TangentialRun::report()
  bool converged = false;
  bool history = false;                      ///< a loading history: summary "steps", fields_<k>.csv
  bool interrupted = false;                  ///< an interrupt came during a history: the steps finished
  Grid grid;                                 ///< the grid solved (an accuracy target chooses it)
  std::optional<SubsurfaceRun> subsurface;   ///< the "subsurface" block's field (final state)
  std::optional<SubsurfaceSeries> subsurface_series;  ///< a history's: the worst over its states
  /// "wear" (wear_run.hpp): each body's worn depth (m per element of `grid`; empty: not worn).
  std::vector<double> worn_base, worn_body;
  /// The worn depth after the profile updates (at most 64, evenly thinned, the last kept; see
  /// wear_run.hpp); a body's depth: each worn body takes it.
  std::vector<output::WornState> wear_series;
};

/// Runs a static case (normal, tangential, finite) with its accuracy block
/// (run_static_with_accuracy, accuracy_run.hpp): what `solve`, `compare` and Python call.
/// A history's subsurface field is computed for each state (subsurface_series.hpp), handed to
/// `history_sink` when given (the command line writes subsurface_<step>.vti).
StaticRun run_static(const Case& c, bool progress, const SubsurfaceSink& history_sink = nullptr);
/// One solve of a static case on its grid (run_normal / run_tangential / run_finite_static);
/// a normal case from `warm_pressure` (one per element) when given.
StaticRun run_static_once(const Case& c, bool progress, const std::vector<double>* warm_pressure = nullptr);

}  // namespace dc::runs
