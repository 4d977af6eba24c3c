#pragma once
// The sweep of a "dynamic" case without its files: one dynamic run per value of the swept key,
// spread over the cores, or over the ranks under mpirun (table/table_ranks.hpp: dynamic assignment,
// gathered in sweep order, the same content either way). The command line writes the files
// (dynamic_run.cpp); the Python module returns them.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"

namespace dc::runs {

struct DynamicSweepOutcome {
  bool root = true;                 ///< false on MPI ranks other than 0 (nothing else is set)
  nlohmann::json summary;           ///< summary.json without "files": the sweep and its "runs"
  std::vector<std::string> files;   ///< timeseries file name of every run that ran
  std::vector<std::string> texts;   ///< their CSV texts
  std::vector<std::string> energy_files, energy_texts;  ///< each run's energy audit: energy_<k>.csv and its text
  std::vector<std::string> labels;  ///< their labels ("key = value")
  bool all_completed = true;        ///< every run reached t_end
  bool interrupted = false;         ///< a signal stopped the sweep (the runs before it are kept)
  std::string input_error;          ///< the first run's "key: reason" that stopped on its input
  bool limit_error = false;         ///< a run's result limits hold an error (summary "limits", with "run")
  std::vector<std::string> targets_missed;  ///< labels of the runs whose accuracy target was not met
  std::size_t planned = 0;          ///< runs of the sweep
};

/// Runs every point of the case's sweep (progress with the time left on stderr unless `quiet`).
/// Every point is checked first (dynamic_limits_before: InputError naming the run's key).
DynamicSweepOutcome simulate_dynamic_sweep(const Case& c, bool quiet);

}  // namespace dc::runs
