#pragma once
// Shared by the subcommands: exit codes, loading a case with command-line overrides,
// the output folder.
#include <string>
#include <vector>

#include "case_model.hpp"

namespace CLI {
class Validator;
}

namespace dc::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 2;     ///< InputError, usage errors
inline constexpr int kExitUnconverged = 3;  ///< the solver did not converge
inline constexpr int kExitInternal = 4;     ///< anything unexpected

/// Reads `path`, names the case after the file when it has no "name", applies the
/// `--set path=value` overrides in order, then `backend` (if not empty), and validates.
Case load_case(const std::string& path, const std::vector<std::string>& overrides,
               const std::string& backend = "");

/// Whether `name` is one of the result files a run writes (summary.json, fields[_k].csv,
/// timeseries[_k].csv, compare.json, the plots and their data): a new run removes these from
/// its folder first. A run kind that writes new file names lists them here.
bool is_result_file(const std::string& name);

/// `--out` when given, else output.dir, else out/<name>; created if missing. Throws
/// InputError naming the key (--out, output.dir, name) when it cannot be created or written
/// into, before anything is solved; removes the result files of an earlier run (only those).
std::string prepare_output_dir(const Case& c, const std::string& cli_out);

/// Writes `text` to `path` (throws InputError naming the file when that fails).
void write_text_file(const std::string& path, const std::string& text);

/// --out: a folder name, not empty.
const CLI::Validator& non_empty_folder();

/// Message for the problem kinds that have no solver in this build.
[[noreturn]] void not_implemented(ProblemKind kind);

}  // namespace dc::cli
