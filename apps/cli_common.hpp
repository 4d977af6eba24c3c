#pragma once
// Shared by the subcommands: exit codes, loading a case with command-line overrides,
// the output folder.
#include <memory>
#include <string>
#include <vector>

#include "case_model.hpp"
#include "output_lock.hpp"

namespace dc::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 2;     ///< InputError, usage errors
inline constexpr int kExitUnconverged = 3;  ///< the solver did not converge
inline constexpr int kExitInternal = 4;     ///< anything unexpected
inline constexpr int kExitOutput = 5;       ///< OutputError: a result file could not be written

/// Reads `path`, names the case after the file when it has no "name", applies the
/// `--set path=value` overrides in order, then `backend` (if not empty), and validates.
Case load_case(const std::string& path, const std::vector<std::string>& overrides,
               const std::string& backend = "");

/// Whether `name` is one of the result files a run writes (summary.json, fields[_k].csv,
/// timeseries[_k].csv, compare.json, the plots and their data, body.vtu, body_<k>.vtu and
/// body.pvd): a new run removes these from its folder first. A run kind that writes new file
/// names lists them here.
bool is_result_file(const std::string& name);

/// An output folder ready for a run, locked while `lock` lives.
struct OutputFolder {
  std::string dir;
  std::unique_ptr<OutputFolderLock> lock;
};

/// `--out` when given, else output.dir, else out/<name>; created if missing and locked
/// (output_lock.hpp: a folder another run holds is refused at once). Throws InputError naming
/// the key (--out, output.dir, name) when it cannot be created, locked or written into, before
/// anything is solved; removes the temporaries of a killed run (output_files.hpp) and the
/// result files of an earlier run (only those). `out_key` names the folder given (Python: out).
OutputFolder open_output_folder(const Case& c, const std::string& cli_out, const std::string& out_key = "--out");

/// open_output_folder for the command line: the folder stays locked until the process ends.
std::string prepare_output_dir(const Case& c, const std::string& cli_out);

/// Message for the problem kinds that have no solver in this build.
[[noreturn]] void not_implemented(ProblemKind kind);

}  // namespace dc::cli
