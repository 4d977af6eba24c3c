#pragma once
// `dyncontact solve` for problem "dynamic" (CASES.md): the moving massive body with the contact
// solved in every step; summary.json, timeseries.csv, plots of every series, progress on stderr.
#include <string>

#include "case_model.hpp"

namespace dc::cli {

/// Runs the case into `dir`; returns the exit code (0, or kExitUnconverged when the run stopped
/// early: the time series so far is written and summary.json says when and why).
int run_dynamic(const Case& c, const std::string& dir, bool quiet);

}  // namespace dc::cli
