#pragma once
// `dyncontact solve` for problem "dynamic" (CASES.md): the moving massive body with the contact
// solved in every step; summary.json, timeseries.csv, plots of every series, progress on stderr.
#include <string>

#include "case_model.hpp"

namespace dc::cli {

/// Runs the case into `dir`; returns the exit code (0, or kExitUnconverged when the run stopped
/// early: the time series so far is written and summary.json says when and why).
int run_dynamic(const Case& c, const std::string& dir, bool quiet);

/// Runs the case's sweep into `dir` (rank 0 writes; under mpirun `dir` is used on rank 0 only):
/// timeseries_<k>.csv per run, summary.json with the sweep and its "runs" (each run's summary,
/// label, value, time series file), one figure per quantity with every run's curves. Exit code
/// as run_dynamic's, over all runs.
int run_dynamic_sweep(const Case& c, const std::string& dir, bool quiet);

}  // namespace dc::cli
