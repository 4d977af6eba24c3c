#pragma once
// `dyncontact solve` for problem "paper_cylinder" (CASES.md): the paper's Section 5 cylinder in
// its dimensionless form, one run per sweep value; summary.json, timeseries.csv (one per run)
// and the plots of F^, l^, v^ against t^ (Figs 4-6).
#include <string>

#include "case_model.hpp"

namespace dc::cli {

/// Checks the paper_cylinder blocks (dimensionless, time, traction_model, sweep); throws
/// InputError naming the key.
void validate_paper_cylinder(const Case& c);

/// Runs the case into `dir`; returns the exit code (0, or kExitUnconverged when a run stopped
/// early).
int run_paper_cylinder(const Case& c, const std::string& dir, bool quiet);

}  // namespace dc::cli
