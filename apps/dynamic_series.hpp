#pragma once
// The run of a "dynamic" case without its files: summary.json's content (without "files") and
// timeseries.csv's text. The command line writes them (dynamic_run.cpp); the Python module
// returns them (the time series as NumPy columns).
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "dynamic_simulation.hpp"
#include "result_limits.hpp"

namespace dc::cli {

struct DynamicOutcome {
  dynamics::DynamicResult result;
  nlohmann::json summary;  ///< summary.json without "files" (CASES.md "dynamic")
  std::string timeseries;  ///< timeseries.csv: a header line, one row per accepted step
  double elapsed = 0.0;    ///< wall time of the run (s)
  std::vector<ResultLimit> limits;  ///< before and after the run (dynamic_limits.hpp); also summary["limits"]
};

/// A plotted quantity of timeseries.csv: its figure's file stem, axis label and columns
/// (1-based column number, legend).
struct DynamicPlotSeries {
  const char* stem;
  const char* ylabel;
  std::vector<std::pair<int, const char*>> columns;
};
/// The figures a dynamic run draws, one per quantity (the contact area's label by dimension).
std::vector<DynamicPlotSeries> dynamic_plot_series(int dimension);

/// Runs the case; `on_step` (optional) after every accepted step, e.g. to write snapshots; a
/// progress line on stderr when `progress`. Never throws for non-convergence (the summary's
/// status says where and why the run stopped); throws InputError for what dynamic_limits_before
/// refuses before the run. The result limits are in `limits` and summary["limits"].
DynamicOutcome simulate_dynamic(const Case& c, bool progress,
                                const std::function<void(const dynamics::DynamicSample&)>& on_step = {});

}  // namespace dc::cli
