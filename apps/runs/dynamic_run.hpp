#pragma once
// `dyncontact solve` for problem "dynamic" (CASES.md): the moving massive body with the contact
// solved in every step; summary.json, timeseries.csv (output/dynamic_series.hpp), plots of every
// series, progress on stderr. The run without its files is simulate_dynamic (also the Python
// module's).
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_quantities.hpp"
#include "case_model.hpp"
#include "dynamic_simulation.hpp"
#include "result_limits.hpp"

namespace dc::runs {

/// The run of a "dynamic" case without its files: summary.json's content (without "files") and
/// timeseries.csv's text. run_dynamic writes them; the Python module returns them (the time
/// series as NumPy columns).
struct DynamicOutcome {
  dynamics::DynamicResult result;
  nlohmann::json summary;  ///< summary.json without "files" (CASES.md "dynamic")
  std::string timeseries;  ///< timeseries.csv: a header line, one row per accepted step
  std::string energy;      ///< energy.csv: a header line, the row of t = 0, one row per accepted step
  double elapsed = 0.0;    ///< wall time of the run (s)
  std::vector<ResultLimit> limits;  ///< before and after the run (dynamic_limits.hpp); also summary["limits"]
  std::vector<QuantityValue> peaks;  ///< summary["peaks"] as results for an error estimate (dynamic_peaks.hpp)
};

/// Runs the case; `on_step` (optional) after every accepted step, e.g. to write snapshots; a
/// progress line on stderr when `progress`. Never throws for non-convergence (the summary's
/// status says where and why the run stopped); throws InputError for what dynamic_limits_before
/// refuses before the run. The result limits are in `limits` and summary["limits"].
/// `worn_gap` (optional): the worn depth added to the body's gap at every evaluation
/// (dynamics::ContactWrench::set_worn_gap; dynamic_wear.hpp).
DynamicOutcome simulate_dynamic(const Case& c, bool progress,
                                const std::function<void(const dynamics::DynamicSample&)>& on_step = {},
                                const dynamics::ContactWrench::WornGap& worn_gap = {});

/// Runs the case into `dir`; returns the exit code (0, or kExitUnconverged when the run stopped
/// early: the time series so far is written and summary.json says when and why).
int run_dynamic(const Case& c, const std::string& dir, bool quiet);

/// Runs the case's sweep into `dir` (rank 0 writes; under mpirun `dir` is used on rank 0 only):
/// timeseries_<k>.csv per run, summary.json with the sweep and its "runs" (each run's summary,
/// label, value, time series file), one figure per quantity with every run's curves. Exit code
/// as run_dynamic's, over all runs.
int run_dynamic_sweep(const Case& c, const std::string& dir, bool quiet);

}  // namespace dc::runs
