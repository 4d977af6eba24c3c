#pragma once
// Problem "finite" on the command line: the FE body on the half-space, normal contact through
// the condensed program; summary.json (normal keys plus body_dofs, max_body_displacement,
// mesh and factorisation times), fields.csv and body.vtu.
#include <string>

#include "case_model.hpp"
#include "tangential_run.hpp"

namespace dc::runs {

/// Whether this build has finite-element support (DYNCONTACT_WITH_FE).
bool finite_supported();

/// Solves and writes into `dir`; returns the exit code. Without finite-element support in
/// this build, an input error saying so.
int run_finite(const Case& c, const std::string& dir, bool quiet);

/// Solves without writing (what `compare` compares): the summary as summary.json has it,
/// without "files".
StaticRun run_finite_static(const Case& c, bool progress);

}  // namespace dc::runs
