#pragma once
// Shared by the subcommands: loading a case with command-line overrides, the output folder,
// input errors under mpirun. The exit codes: runs/exit_codes.hpp.
#include <functional>
#include <string>
#include <vector>

#include "case_model.hpp"
#include "exit_codes.hpp"

namespace dc::cli {

/// Reads `path`, names the case after the file when it has no "name", applies the
/// `--set path=value` overrides in order, then `backend` (if not empty), and validates.
Case load_case(const std::string& path, const std::vector<std::string>& overrides,
               const std::string& backend = "");

/// open_output_folder (output/output_folder.hpp) for the command line: the folder stays locked
/// until the process ends.
std::string prepare_output_dir(const Case& c, const std::string& cli_out);

/// Message for the problem kinds that have no solver in this build.
[[noreturn]] void not_implemented(ProblemKind kind);

/// Runs a command on this rank; under mpirun every rank reads the same input, so an InputError
/// propagates from rank 0 only (the other ranks return the bad-input exit code quietly).
int report_input_errors_on_root(const std::function<int()>& command);

}  // namespace dc::cli
