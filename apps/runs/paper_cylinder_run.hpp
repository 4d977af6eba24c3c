#pragma once
// `dyncontact solve` for problem "paper_cylinder" (CASES.md): the paper's Section 5 cylinder in
// its dimensionless form, one run per sweep value; summary.json, timeseries.csv (one per run)
// and the plots of F^, l^, v^ against t^ (Figs 4-6).
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"

namespace dc::runs {

/// Checks the paper_cylinder blocks (dimensionless, time, traction_model, sweep); throws
/// InputError naming the key.
void validate_paper_cylinder(const Case& c);

/// The runs of a case without its files. Its sweep's runs are spread over the cores, or over the
/// ranks under mpirun (table/table_ranks.hpp: dynamic assignment, gathered in sweep order, the same
/// content either way); progress with the time left on stderr unless `quiet`.
struct PaperCylinderOutcome {
  bool root = true;                 ///< false on MPI ranks other than 0 (nothing else is set)
  nlohmann::json summary;           ///< summary.json without "files"
  std::vector<std::string> files;   ///< timeseries file name of every run with a time series (a failed run has none)
  std::vector<std::string> texts;   ///< their CSV texts
  std::vector<std::string> labels;  ///< their labels (plots)
  bool all_ok = true, interrupted = false;
  std::size_t planned = 0;          ///< runs of the sweep
};
PaperCylinderOutcome simulate_paper_cylinder(const Case& c, bool quiet);

/// Runs the case into `dir` (rank 0 writes; under mpirun `dir` is used on rank 0 only); returns the exit code (0, or kExitUnconverged when a run stopped
/// early).
int run_paper_cylinder(const Case& c, const std::string& dir, bool quiet);

}  // namespace dc::runs
